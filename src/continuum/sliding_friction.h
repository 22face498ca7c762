// Friction coefficient of a sliding contact for the continuum systems:
//   stick:  |tangential load| <= mu_static * normal load
//   slip:   mu(s, V) = mu_kinetic(s) + alpha * |V|
// with s the accumulated sliding distance (m) and V the sliding speed (m/s).
#pragma once

#include <cmath>
#include <functional>
#include <string>

#include "coupling/friction_law.h"

namespace runin::continuum {

class SlidingFriction {
 public:
  // mu0 (+ alpha V): thesis eq. 4.5 with the + sign (see doc/pin_on_disk.md).
  static SlidingFriction constant(double mu0, double alpha = 0.0);
  static SlidingFriction static_kinetic(double mu_static, double mu_kinetic, double alpha = 0.0);
  // Micro law: mu_static is the law's peak value, and sliding starts at the peak:
  //   mu_kinetic(s) = law(s_peak + s / (distance_scale * metres per law unit)).
  // distance_scale = macro asperity size / micro asperity size (similarity).
  static SlidingFriction from_law(const coupling::FrictionLaw &law, coupling::FrictionLaw::Branch branch,
                                  double distance_scale, double alpha = 0.0);

  double static_coefficient() const { return mu_static_; }
  double speed_coefficient() const { return alpha_; }
  double kinetic(double s, double speed) const { return mu_kinetic_(s) + alpha_ * std::abs(speed); }
  const std::string &description() const { return description_; }

 private:
  SlidingFriction(double mu_static, std::function<double(double)> mu_kinetic, double alpha,
                  std::string description);

  double mu_static_;
  std::function<double(double)> mu_kinetic_;
  double alpha_;
  std::string description_;
};

}  // namespace runin::continuum
