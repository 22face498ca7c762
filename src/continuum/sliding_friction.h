// Friction coefficient of a sliding contact for the continuum systems:
//   stick:  |tangential load| <= mu_static * normal load
//   slip:   mu(s, V) = mu_kinetic(s) + alpha * |V|
// with s the accumulated sliding distance (m) and V the sliding speed (m/s).
// alpha > 0 is velocity strengthening (thesis eq. 4.5 with +), alpha < 0 weakening (with -).
// The feedback variant carries one state, the roughness R (thesis eq. 3.6):
//   mu = C1 R + C2 / R,  dR/dx = -A K1 R + B K2 / R,  x = s (per metre slid) or t (per second),
// and its static coefficient is mu(R) at the current R.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <memory>
#include <optional>

#include "continuum/node_film.h"
#include "coupling/friction_law.h"
#include "coupling/state_law.h"
#include "tribo/feedback.h"

namespace runin::continuum {

// The homogenised state law on the contact nodes (doc/state_law_continuum.md). The machine element
// owns the per-node states (NodeStateLaw) and, by operator splitting at the output interval, sets the held
// coefficients the ODE sees: kinetic mu_eff (+ alpha V) and the static limit. Shared by all copies of the
// SlidingFriction made from it.
struct StateLawFriction {
  std::shared_ptr<const coupling::StateLaw> law;
  coupling::OutOfRange policy = coupling::OutOfRange::Error;
  std::string path;                 // friction.law, resolved
  std::optional<double> mu_static;  // friction.mu_static; absent: the law's peak at the initial pressures
  double held_static = 0.0;         // set by the element before the run
  double held_kinetic = 0.0;        // mu_eff, set by the element after each output interval
  std::optional<FilmSettings> film; // [film]: a surface film on the nodes (node_film.h)
};

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

  // State law on the nodes: static = state->held_static, kinetic = state->held_kinetic + alpha V, both set by
  // the element's splitting loop. No distance_scale: the law's state is the worn depth, not the distance.
  static SlidingFriction state_law(std::shared_ptr<StateLawFriction> state, double alpha = 0.0);
  StateLawFriction *state_law() const { return state_law_.get(); }

  // Roughness-feedback friction; `per_distance` integrates R along the sliding distance
  // (frozen in stick), otherwise along time.
  static SlidingFriction feedback(const tribo::FeedbackModel &model, double initial_roughness, bool per_distance,
                                  double alpha = 0.0);
  // The rough root R0 of mu(R0) = C1 R0 + C2 / R0 = mu0 (the larger one): the initial roughness whose
  // friction is the static coefficient mu0. The run-in then takes mu from mu0 to mu(R*), R* independent
  // of R0, so a higher mu0 means a rougher start and a longer run-in. Throws std::invalid_argument
  // unless mu0 > mu(R*) and R0 > R* (mu0 at or below the steady value has no run-in).
  static double feedback_roughness_for(const tribo::FeedbackModel &model, double mu0);

  // Static coefficient at the initial state (feedback: mu(R0)).
  double static_coefficient() const { return state_law_ ? state_law_->held_static : mu_static_; }
  double speed_coefficient() const { return alpha_; }
  double kinetic(double s, double speed) const { return mu_kinetic_(s) + alpha_ * std::abs(speed); }
  const std::string &description() const { return description_; }

  // State-carrying variant (feedback). Without a state these fall back to the stateless forms.
  // A system that does not integrate R and calls kinetic(s, V) sees the constant mu(R0) + alpha V.
  bool has_state() const { return static_cast<bool>(feedback_); }
  double initial_state() const { return feedback_ ? r0_ : 0.0; }
  bool state_per_distance() const { return per_distance_; }
  const tribo::FeedbackModel *feedback_model() const { return feedback_.get(); }
  double static_coefficient(double state) const {
    return feedback_ ? feedback_->mu(state) : static_coefficient();
  }
  double kinetic(double s, double speed, double state) const {
    return feedback_ ? feedback_->mu(state) + alpha_ * std::abs(speed) : kinetic(s, speed);
  }
  // dR/dt: `slipping` and `speed` matter only for the per-distance form.
  double state_rate(double state, double speed, bool slipping) const {
    if (!feedback_) return 0.0;
    if (!per_distance_) return feedback_->dRdt(state);
    return slipping ? feedback_->dRdt(state) * std::abs(speed) : 0.0;
  }

 private:
  SlidingFriction(double mu_static, std::function<double(double)> mu_kinetic, double alpha,
                  std::string description);

  double mu_static_;
  std::function<double(double)> mu_kinetic_;
  double alpha_;
  std::string description_;
  std::shared_ptr<const tribo::FeedbackModel> feedback_;
  std::shared_ptr<StateLawFriction> state_law_;
  double r0_ = 0.0;
  bool per_distance_ = true;
};

// Time to equilibrium of a sampled series: the first time after which |x - x_final| <= tolerance |x_final|
// at every later sample; -1 if that time lies in the last `tail` fraction of the span (not shown to be
// steady within the run).
double equilibrium_time(const std::vector<double> &t, const std::vector<double> &x, double tolerance,
                     double tail = 0.1);

}  // namespace runin::continuum
