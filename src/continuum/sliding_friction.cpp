#include "continuum/sliding_friction.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument("friction: " + what);
}
std::string format(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}
}  // namespace

SlidingFriction::SlidingFriction(double mu_static, std::function<double(double)> mu_kinetic, double alpha,
                                 std::string description)
    : mu_static_(mu_static), mu_kinetic_(std::move(mu_kinetic)), alpha_(alpha),
      description_(std::move(description)) {
  require(std::isfinite(mu_static_) && mu_static_ >= 0.0, "static coefficient must be >= 0");
  require(std::isfinite(alpha_), "alpha must be finite");
}

SlidingFriction SlidingFriction::constant(double mu0, double alpha) {
  require(std::isfinite(mu0) && mu0 >= 0.0, "mu0 must be >= 0");
  return SlidingFriction(mu0, [mu0](double) { return mu0; }, alpha,
                         "mu = " + format(mu0) + " + " + format(alpha) + " V");
}

SlidingFriction SlidingFriction::static_kinetic(double mu_static, double mu_kinetic, double alpha) {
  require(std::isfinite(mu_kinetic) && mu_kinetic >= 0.0, "mu_kinetic must be >= 0");
  return SlidingFriction(mu_static, [mu_kinetic](double) { return mu_kinetic; }, alpha,
                         "mu_static = " + format(mu_static) + ", mu = " + format(mu_kinetic) + " + " +
                             format(alpha) + " V");
}

SlidingFriction SlidingFriction::from_law(const coupling::FrictionLaw &law, coupling::FrictionLaw::Branch branch,
                                          double distance_scale, double alpha) {
  require(std::isfinite(distance_scale) && distance_scale > 0.0, "distance_scale must be > 0");
  const double s_peak = law.peak_distance();
  const double metres_per_micro_unit = distance_scale * law.distance_unit_in_m;
  auto mu_of_distance = [law, branch, s_peak, metres_per_micro_unit](double s) {
    return law.evaluate(s_peak + s / metres_per_micro_unit, branch);
  };
  const bool fitted = branch == coupling::FrictionLaw::Branch::Fit && law.fit;
  return SlidingFriction(law.evaluate(s_peak, branch), mu_of_distance, alpha,
                         std::string("law file ") + law.source_file + " (" + (fitted ? "fit" : "table") +
                             "), distance_scale = " + format(distance_scale) + ", + " + format(alpha) + " V");
}

SlidingFriction SlidingFriction::state_law(std::shared_ptr<StateLawFriction> state, double alpha) {
  require(state && state->law, "state law missing");
  SlidingFriction f(0.0, [held = state](double) { return held->held_kinetic; }, alpha,
                    "state law " + state->path + " per contact node (mu_eff pressure-weighted, out_of_range = " +
                        coupling::to_string(state->policy) + "), + " +
                        format(alpha) + " V");
  f.state_law_ = std::move(state);
  return f;
}

SlidingFriction SlidingFriction::feedback(const tribo::FeedbackModel &model, double initial_roughness,
                                          bool per_distance, double alpha) {
  require(std::isfinite(initial_roughness) && initial_roughness > 0.0, "R0 must be > 0");
  auto shared = std::make_shared<const tribo::FeedbackModel>(model);
  SlidingFriction f(model.mu(initial_roughness), [shared, initial_roughness](double) { return shared->mu(initial_roughness); },
                    alpha,
                    std::string(tribo::to_string(model.kind())) + " feedback mu = C1 R + C2/R, dR/d" +
                        (per_distance ? "s" : "t") + " = -A K1 R + B K2/R, R0 = " + format(initial_roughness) +
                        " (mu0 = " + format(model.mu(initial_roughness)) + ", R* = " +
                        format(model.stationary_roughness()) + "), + " + format(alpha) + " V");
  f.feedback_ = std::move(shared);
  f.r0_ = initial_roughness;
  f.per_distance_ = per_distance;
  return f;
}

double SlidingFriction::feedback_roughness_for(const tribo::FeedbackModel &model, double mu0) {
  const auto &c = model.coefficients();
  const double r_star = model.stationary_roughness(), mu_star = model.mu(r_star);
  require(std::isfinite(mu0) && mu0 > mu_star,
          "mu0 = " + format(mu0) + " is not above the steady value mu(R*) = " + format(mu_star) + " (no run-in)");
  const double root = std::sqrt(mu0 * mu0 - 4.0 * c.C1 * c.C2);  // real: mu0 > mu(R*) >= 2 sqrt(C1 C2)
  const double r0 = (mu0 + root) / (2.0 * c.C1);
  require(r0 > r_star, "mu0 = " + format(mu0) + " gives R0 = " + format(r0) + " below R* = " + format(r_star));
  return r0;
}

double equilibrium_time(const std::vector<double> &t, const std::vector<double> &x, double tolerance, double tail) {
  if (t.empty() || t.size() != x.size()) return -1.0;
  const double final_value = x.back(), band = tolerance * std::abs(final_value);
  double from = t.front();
  for (std::size_t i = x.size(); i-- > 0;)
    if (std::abs(x[i] - final_value) > band) {
      from = t[std::min(i + 1, t.size() - 1)];
      break;
    }
  return from <= t.front() + (1.0 - tail) * (t.back() - t.front()) ? from : -1.0;
}

}  // namespace runin::continuum
