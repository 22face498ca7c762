#include "tribo/contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <mutex>
#include <stdexcept>

#include <boost/math/tools/toms748_solve.hpp>
#include <boost/numeric/odeint.hpp>

namespace runin::tribo {

namespace {
void require(bool ok, const std::string &what)
{
  if (!ok) throw InvalidCoefficient(what);
}
}    // namespace

void Material::validate(const std::string &name) const
{
  require(youngs_modulus > 0.0, name + ": Young's modulus must be > 0");
  require(poisson_ratio > -1.0 && poisson_ratio < 0.5, name + ": Poisson ratio must be in (-1, 0.5)");
  require(hardness > 0.0, name + ": hardness must be > 0");
}

double effective_modulus(const Material &a, const Material &b)
{
  return 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
}

double effective_shear_modulus(const Material &a, const Material &b)
{
  return 1.0 / ((2.0 - a.poisson_ratio) / a.shear_modulus() + (2.0 - b.poisson_ratio) / b.shear_modulus());
}

double effective_radius(double radius_a, double radius_b)
{
  return radius_a * radius_b / (radius_a + radius_b);
}

HertzNormal::HertzNormal(double effective_modulus, double effective_radius)
    : e_eff_(effective_modulus), r_eff_(effective_radius)
{
  require(e_eff_ > 0.0, "E*: effective modulus must be > 0");
  require(r_eff_ > 0.0, "R*: effective radius must be > 0");
}

double HertzNormal::contact_radius(double overlap) const
{
  return overlap > 0.0 ? std::sqrt(r_eff_ * overlap) : 0.0;
}

double HertzNormal::force(double overlap) const
{
  return overlap > 0.0 ? 4.0 / 3.0 * e_eff_ * contact_radius(overlap) * overlap : 0.0;
}

double HertzNormal::stiffness(double overlap) const
{
  return 2.0 * e_eff_ * contact_radius(overlap);
}

double HertzNormal::elastic_energy(double overlap) const
{
  return overlap > 0.0 ? 8.0 / 15.0 * e_eff_ * contact_radius(overlap) * overlap * overlap : 0.0;
}

namespace {

// Nondimensional Hertz impact (see contact.h): delta = x (m* v0^2 / K)^(2/5), t = tau delta_scale / v0 with
// F_Hertz = K delta^(3/2), k_n = 3/2 K delta^(1/2). Approach speed 1; gamma = c sqrt(3/2).
using ImpactState = std::array<double, 2>;    // x, dx/dtau

// Total normal force divided by x^(1/4): its sign is that of the (unclamped) contact force.
double impact_force_sign(const ImpactState &s, double gamma)
{
  return std::pow(std::max(s[0], 0.0), 1.25) + gamma * s[1];
}

double separation_speed(double factor)
{
  namespace odeint = boost::numeric::odeint;
  const double gamma = factor * std::sqrt(1.5);
  const auto rhs = [gamma](const ImpactState &s, ImpactState &ds, double) {
    const double x = std::max(s[0], 0.0);
    ds[0] = s[1];
    ds[1] = -std::max(0.0, x * std::sqrt(x) + gamma * std::sqrt(std::sqrt(x)) * s[1]);    // clamp fn >= 0
  };
  auto stepper = odeint::make_dense_output(1e-13, 1e-13, odeint::runge_kutta_dopri5<ImpactState>());
  stepper.initialize(ImpactState{0.0, 1.0}, 0.0, 1e-3);
  // the undamped contact lasts 3.2 time units; damping only shortens it
  for (int step = 0; step < 1000000 && stepper.current_time() < 100.0; ++step) {
    stepper.do_step(rhs);
    const ImpactState &now = stepper.current_state();
    if (now[1] >= 0.0 || impact_force_sign(now, gamma) > 0.0) continue;
    // the force reached zero in the last step: locate it on the dense output
    ImpactState at;
    const auto force_at = [&](double t) {
      stepper.calc_state(t, at);
      return impact_force_sign(at, gamma);
    };
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve(force_at, stepper.previous_time(), stepper.current_time(),
                                                        boost::math::tools::eps_tolerance<double>(52), iterations);
    stepper.calc_state(0.5 * (root.first + root.second), at);
    return -at[1];
  }
  throw std::runtime_error("RestitutionDamping: the calibration impact did not separate");
}

// c for a requested e (toms748 on the monotone e(c)); memoised, as fix runin/wall builds one per step.
double calibrated_factor(double e)
{
  static std::mutex mutex;
  static std::map<double, double> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  const auto found = cache.find(e);
  if (found != cache.end()) return found->second;
  const auto miss = [e](double factor) { return separation_speed(factor) - e; };
  double lo = 0.0, hi = 1.0;
  while (miss(hi) > 0.0) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e12) throw std::runtime_error("RestitutionDamping: no damping factor found for e");
  }
  std::uintmax_t iterations = 200;
  const auto root = boost::math::tools::toms748_solve(miss, lo, hi, boost::math::tools::eps_tolerance<double>(50),
                                                      iterations);
  return cache[e] = 0.5 * (root.first + root.second);
}

}    // namespace

double RestitutionDamping::hertz_restitution(double damping_factor)
{
  return damping_factor > 0.0 ? separation_speed(damping_factor) : 1.0;
}

RestitutionDamping::RestitutionDamping(double e) : restitution_(e), factor_(0.0)
{
  require(e >= kMinimumRestitution && e <= 1.0, "e: coefficient of restitution must be in [1e-6, 1]");
  if (e < 1.0) factor_ = calibrated_factor(e);
}

StaticKineticFriction::StaticKineticFriction(double mu_static, double mu_kinetic, double d_c)
    : mu_s_(mu_static), mu_k_(mu_kinetic), d_c_(d_c), inv_d_c_(d_c > 0.0 ? 1.0 / d_c : 0.0)
{
  require(mu_s_ >= 0.0, "mu_s: static friction coefficient must be >= 0");
  require(mu_k_ >= 0.0, "mu_k: kinetic friction coefficient must be >= 0");
  require(mu_k_ <= mu_s_, "mu_k: kinetic friction coefficient must not exceed mu_s");
  require(d_c_ >= 0.0, "d_c: slip-weakening distance must be >= 0");
}

}    // namespace runin::tribo
