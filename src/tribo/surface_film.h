// Surface film (oxide or adsorbed contaminant) on an asperity summit: its coverage theta in [0, 1] is removed
// by sliding and grows back from the environment (doc/surface_films.md).
//
//   removal:  d theta = -theta ds / s_r           each slip increment ds of a contact strips the fraction ds / s_r
//                                                  (s_r: removal distance; a film worn off in proportion to the
//                                                  distance slid, as Archard wear of a thin layer)
//   growth:   d theta / dt = k_g (1 - theta)       first-order re-covering of the bare fraction: Langmuir's
//                                                  adsorption kinetics (Langmuir 1918, J. Am. Chem. Soc. 40:1361);
//                                                  for an oxide, 1/k_g is the time to re-cover bare metal (the
//                                                  thickening of a grown oxide, parabolic in Quinn's oxidational
//                                                  wear theory, Quinn 1983, Tribol. Int. 16:257, is not modelled)
//
// Over a step with slip ds and time dt (both taken as uniform in the step) the linear equation
// d theta = -(ds / s_r) theta + (k_g dt) (1 - theta) has the exact solution
//   theta' = theta* + (theta - theta*) exp(-(r + g)),   r = ds / s_r, g = k_g dt, theta* = g / (r + g),
// so growth off gives theta exp(-s / s_r) and removal off 1 - (1 - theta) exp(-k_g t) to round-off, whatever the
// step; at a steady slip rate v the coverage tends to theta* = k_g / (k_g + v / s_r) = s_r / (s_r + v / k_g).
#pragma once

#include "tribo/contact.h"    // InvalidCoefficient

#include <cmath>
#include <cstdio>
#include <string>

namespace runin::tribo {

class FilmKinetics {
 public:
  // s_r: removal distance [m], 0: no removal by sliding; k_g: growth rate [1/s], 0: no regrowth.
  FilmKinetics(double removal_distance, double growth_rate)
      : removal_distance_(checked(removal_distance, "s_r: film removal distance must be >= 0 m (0: no removal)")),
        growth_rate_(checked(growth_rate, "k_g: film growth rate must be >= 0 1/s (0: no growth)")),
        inv_removal_distance_(removal_distance > 0.0 ? 1.0 / removal_distance : 0.0)
  {
  }
  double removal_distance() const { return removal_distance_; }
  double growth_rate() const { return growth_rate_; }
  bool removes() const { return removal_distance_ > 0.0; }

  // The removal exposure r = ds / s_r of a slip increment (0 with removal off), and the growth exposure g = k_g dt.
  double removal(double slip) const { return slip * inv_removal_distance_; }
  double growth(double dt) const { return growth_rate_ * dt; }

  // theta after a step with removal exposure r and growth exposure g (the exact solution above).
  static double advance(double theta, double removal, double growth)
  {
    const double k = removal + growth;
    if (!(k > 0.0)) return theta;
    const double steady = growth / k;
    return theta + (steady - theta) * -std::expm1(-k);
  }
  // theta* at a steady slip rate v [m/s] (1 when nothing removes the film, 0 when nothing regrows it).
  double steady_state(double slip_rate) const
  {
    const double r = slip_rate * inv_removal_distance_;
    return r + growth_rate_ > 0.0 ? growth_rate_ / (r + growth_rate_) : 1.0;
  }

  // A property of the covered interface: theta f_film + (1 - theta) f_clean (exact at theta = 0 and 1).
  static double interpolate(double theta, double clean, double film) { return theta * film + (1.0 - theta) * clean; }

  // A coverage given as input (initial values): in [0, 1].
  static double checked_coverage(double theta, const char *what = "coverage")
  {
    if (!(theta >= 0.0 && theta <= 1.0)) {
      char got[32];
      std::snprintf(got, sizeof got, "%.6g", theta);
      throw InvalidCoefficient(std::string(what) + ": film coverage must be in [0, 1], got " + got);
    }
    return theta;
  }

 private:
  static double checked(double value, const char *message)
  {
    if (!(value >= 0.0) || !std::isfinite(value)) {
      char got[32];
      std::snprintf(got, sizeof got, "%.6g", value);
      throw InvalidCoefficient(std::string(message) + ", got " + got);
    }
    return value;
  }
  double removal_distance_, growth_rate_, inv_removal_distance_;
};

}    // namespace runin::tribo
