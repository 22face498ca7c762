#include "continuum/piston_ring.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace runin::continuum {
namespace {
constexpr double kPi = 3.14159265358979323846;
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
int sign_of(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }
bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }
std::string fmt_cycle(double cycle) { return std::to_string(static_cast<int>(std::lround(cycle * 180.0 / kPi))) + " deg"; }
}  // namespace

void SliderCrank::validate() const {
  require(finite_positive(crank_radius), "crank_radius must be positive");
  require(finite_positive(link_length), "link_length must be positive");
  require(link_length > crank_radius, "link_length must exceed crank_radius");
}

double SliderCrank::position(double theta) const {
  const double s = crank_radius / link_length * std::sin(theta);
  return crank_radius * std::cos(theta) + link_length * std::sqrt(1.0 - s * s);
}

double SliderCrank::velocity(double theta, double omega) const {
  const double s = std::sin(theta), c = std::cos(theta);
  const double ratio = crank_radius / link_length;
  const double root = std::sqrt(1.0 - ratio * ratio * s * s);
  return -crank_radius * omega * s * (1.0 + ratio * c / root);
}

double SliderCrank::angle_at(double x) const {
  const double r = crank_radius, l = link_length;
  const double c = (x * x + r * r - l * l) / (2.0 * x * r);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

void GasPressureTable::validate() const {
  require(crank_angle.size() == pressure.size(), "gas table: crank_angle and pressure differ in length");
  require(finite_positive(cycle), "gas cycle must be positive");
  require(std::isfinite(factor) && factor >= 0.0, "gas factor must be >= 0");
  for (std::size_t i = 0; i < crank_angle.size(); ++i) {
    require(std::isfinite(crank_angle[i]) && crank_angle[i] >= 0.0 && crank_angle[i] < cycle,
            "gas crank angles must lie in [0, cycle)");
    require(i == 0 || crank_angle[i] > crank_angle[i - 1], "gas crank angles must increase");
    require(std::isfinite(pressure[i]) && pressure[i] >= 0.0, "gas pressures must be >= 0");
  }
}

double GasPressureTable::at(double theta) const {
  if (crank_angle.empty()) return 0.0;
  if (crank_angle.size() == 1) return factor * pressure[0];
  double a = std::fmod(theta, cycle);
  if (a < 0.0) a += cycle;
  // Periodic linear interpolation: the last point connects to the first one cycle later.
  const auto upper = std::upper_bound(crank_angle.begin(), crank_angle.end(), a);
  const std::size_t n = crank_angle.size();
  std::size_t hi = static_cast<std::size_t>(upper - crank_angle.begin());
  double a_lo, a_hi, p_lo, p_hi;
  if (hi == 0) {
    a_lo = crank_angle[n - 1] - cycle, p_lo = pressure[n - 1], a_hi = crank_angle[0], p_hi = pressure[0];
  } else if (hi == n) {
    a_lo = crank_angle[n - 1], p_lo = pressure[n - 1], a_hi = crank_angle[0] + cycle, p_hi = pressure[0];
  } else {
    a_lo = crank_angle[hi - 1], p_lo = pressure[hi - 1], a_hi = crank_angle[hi], p_hi = pressure[hi];
  }
  return factor * (p_lo + (p_hi - p_lo) * (a - a_lo) / (a_hi - a_lo));
}

void PistonRingParameters::validate() const {
  crank.validate();
  require(std::isfinite(start_angle) && start_angle >= 0.0 && start_angle <= kPi,
          "start_angle must lie in [0, 180] deg before TDC");
  if (motion == PistonMotion::Ramp) {
    require(finite_positive(ramp_time), "ramp_time must be positive");
    require(gas.empty(), "a gas pressure table needs the crank motion");
  } else {
    require(finite_positive(crank_speed), "crank_speed must be positive");
  }
  require(finite_positive(bore), "bore must be positive");
  require(finite_positive(ring_width), "ring_width must be positive");
  require(finite_positive(ring_mass), "ring_mass must be positive");
  require(finite_positive(land_stiffness), "land_stiffness must be positive");
  require(std::isfinite(land_damping) && land_damping >= 0.0, "land_damping must be >= 0");
  require(finite_positive(elastic_pressure), "elastic_pressure must be positive");
  gas.validate();
}

double PistonRingParameters::contact_area() const { return kPi * bore * ring_width; }

void PistonRingRun::validate() const {
  require(finite_positive(t_end), "t_end must be positive");
  require(finite_positive(output_interval), "output_interval must be positive");
  require(t_end / output_interval <= 1e7, "output_interval gives more than 1e7 samples");
  require(max_events > 0, "max_events must be positive");
}

PistonRingSystem::PistonRingSystem(PistonRingParameters parameters, SlidingFriction friction)
    : p_(std::move(parameters)), friction_(std::move(friction)) {
  p_.validate();
}

double PistonRingSystem::crank_angle(double t) const {
  if (p_.motion == PistonMotion::Crank) return -p_.start_angle + p_.crank_speed * t;
  return -p_.crank.angle_at(piston_position(t));
}

double PistonRingSystem::piston_position(double t) const {
  if (p_.motion == PistonMotion::Crank) return p_.crank.position(crank_angle(t));
  const double x0 = p_.crank.position(p_.start_angle);
  const double fraction = std::clamp(t / p_.ramp_time, 0.0, 1.0);
  return x0 + (p_.crank.top_dead_centre() - x0) * fraction;
}

double PistonRingSystem::piston_velocity(double t) const {
  if (p_.motion == PistonMotion::Crank) return p_.crank.velocity(crank_angle(t), p_.crank_speed);
  if (t < 0.0 || t > p_.ramp_time) return 0.0;  // left-continuous: the ramp's last sample keeps its speed
  return (p_.crank.top_dead_centre() - p_.crank.position(p_.start_angle)) / p_.ramp_time;
}

double PistonRingSystem::motion_kink() const { return p_.motion == PistonMotion::Ramp ? p_.ramp_time : -1.0; }

double PistonRingSystem::normal_load(double t) const {
  const double gas = p_.gas.empty() ? 0.0 : p_.gas.at(crank_angle(t));
  return (p_.elastic_pressure + gas) * p_.contact_area();
}

double PistonRingSystem::land_force(double t, const double *y) const {
  return -p_.land_stiffness * y[0] - p_.land_damping * (y[1] - piston_velocity(t));
}

double PistonRingSystem::static_limit(double t, const double *y) const {
  return friction_.static_coefficient(y[3]) * normal_load(t);
}

void PistonRingSystem::rhs(double t, const double *y, double *dydt, ContactState state, int direction) const {
  const double vp = piston_velocity(t);
  if (state == ContactState::Stick) {
    dydt[0] = -vp;
    dydt[1] = 0.0;
    dydt[2] = 0.0;
    dydt[3] = friction_.state_rate(y[3], 0.0, false);
    return;
  }
  const double friction = direction * friction_.kinetic(y[2], y[1], y[3]) * normal_load(t);
  dydt[0] = y[1] - vp;
  dydt[1] = (land_force(t, y) - friction) / p_.ring_mass;
  // direction * u rather than |u|: smooth through the re-stick root, equal to |u| before it.
  dydt[2] = direction * y[1];
  dydt[3] = friction_.state_rate(y[3], y[1], true);
}

PistonRingSample PistonRingSystem::sample(double t, const double *y, ContactState state, int direction) const {
  PistonRingSample s;
  s.t = t;
  s.crank_angle = crank_angle(t);
  s.piston_position = piston_position(t);
  s.piston_velocity = piston_velocity(t);
  s.ring_position = s.piston_position + y[0];
  s.normal_load = normal_load(t);
  s.distance = y[2];
  s.roughness = y[3];
  s.state = state;
  s.mu_law = friction_.kinetic(y[2], 0.0, y[3]);
  if (state == ContactState::Stick) {
    s.speed = 0.0;
    // The ring is at rest: it passes the whole land force on to the liner.
    s.land_force = -p_.land_stiffness * y[0] + p_.land_damping * s.piston_velocity;
    s.friction_force = s.land_force;
  } else {
    s.speed = y[1];
    s.land_force = land_force(t, y);
    s.friction_force = direction * friction_.kinetic(y[2], y[1], y[3]) * s.normal_load;
  }
  s.mu = std::abs(s.friction_force) / s.normal_load;
  return s;
}

namespace {
struct PistonRingHooks : SystemHooks<PistonRingSystem, PistonRingObserver> {
  PistonRingHooks(const PistonRingSystem &sys, const PistonRingObserver &obs, const PistonRingRefresh &ref)
      : SystemHooks(sys, obs), refresh_fn(ref) {}
  const PistonRingRefresh &refresh_fn;
  bool refresh(StickSlipState &) { return refresh_fn ? refresh_fn() : false; }
  static constexpr std::size_t speed_index = 1;
  // The land force with the ring at rest (u = 0).
  double stick_force(double t, const double *y) const {
    double stuck[PistonRingSystem::state_size] = {y[0], 0.0, y[2], y[3]};
    return system.land_force(t, stuck);
  }
  double breakaway_function(double t, const double *y) const {
    return std::abs(stick_force(t, y)) - system.static_limit(t, y);
  }
  int breakaway_direction(double t, const double *y) const { return sign_of(stick_force(t, y)); }
};
}  // namespace

void RingLandGeometry::validate() const {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(bore)) throw std::invalid_argument("bore must be positive");
  if (!positive(groove_diameter) || groove_diameter >= bore)
    throw std::invalid_argument("groove_diameter must lie in (0, bore)");
  if (!positive(land_width)) throw std::invalid_argument("land_width must be positive");
  if (!positive(ring_width)) throw std::invalid_argument("ring_width must be positive");
  if (!positive(ring_thickness) || 2.0 * ring_thickness >= bore)
    throw std::invalid_argument("ring_thickness must lie in (0, bore / 2)");
  if (!positive(youngs_modulus)) throw std::invalid_argument("youngs_modulus must be positive");
  if (!std::isfinite(poisson_ratio) || poisson_ratio <= -1.0 || poisson_ratio >= 0.5)
    throw std::invalid_argument("poisson_ratio must lie in (-1, 0.5)");
}

LandStiffness land_stiffness(const RingLandGeometry &g) {
  g.validate();
  constexpr double kPi = 3.14159265358979323846, kShear = 5.0 / 6.0;
  const double shear_modulus = g.youngs_modulus / (2.0 * (1.0 + g.poisson_ratio));
  const double length = 0.5 * (g.bore - g.groove_diameter), h = g.land_width;
  const double rigidity = g.youngs_modulus * h * h * h / (12.0 * (1.0 - g.poisson_ratio * g.poisson_ratio));
  const double per_circumference =
      length * length * length / (20.0 * rigidity) + length / (3.0 * kShear * shear_modulus * h);
  LandStiffness k;
  k.land = kPi * 0.5 * (g.bore + g.groove_diameter) / per_circumference;
  k.ring = 2.0 * kPi * shear_modulus * g.ring_width / std::log(g.bore / (g.bore - 2.0 * g.ring_thickness));
  k.total = 1.0 / (1.0 / k.land + 1.0 / k.ring);
  return k;
}

SolveReport simulate(const PistonRingSystem &system, const PistonRingRun &run, const PistonRingObserver &observer,
                     const PistonRingRefresh &refresh) {
  run.validate();
  SolveReport report;
  CvodeIntegrator integrator(PistonRingSystem::state_size, run.integrator);
  StickSlipState start;
  start.y = {0.0, 0.0, 0.0, system.friction().initial_state()};
  StickSlipGrid grid{run.t_end, run.output_interval, system.motion_kink(), run.max_events};
  PistonRingHooks hooks(system, observer, refresh);
  StickSlipLoop<PistonRingHooks> loop(hooks, grid, integrator, std::move(start), report);

  // Already past the static limit at the start (the land damper sees the piston's start speed)?
  // No stick sample then: its land force would be the damper's response to the speed step.
  const auto &s = loop.state();
  if (hooks.breakaway_function(s.t, s.y.data()) > 0.0) loop.break_away();
  loop.run();
  return report;
}

PistonRingSummary summarise(const PistonRingSystem &system, const std::vector<PistonRingSample> &samples) {
  PistonRingSummary summary;
  if (samples.empty()) return summary;
  for (const auto &s : samples) {
    summary.peak_friction_force = std::max(summary.peak_friction_force, std::abs(s.friction_force));
    summary.peak_land_force = std::max(summary.peak_land_force, std::abs(s.land_force));
  }
  for (const auto &s : samples)
    if (std::abs(s.friction_force) >= (1.0 - 1e-6) * summary.peak_friction_force) {
      summary.peak_time = s.t;
      break;
    }
  if (samples.front().state == ContactState::Slip) summary.breakaway_time = samples.front().t;
  for (std::size_t i = 1; i < samples.size() && summary.breakaway_time < 0.0; ++i)
    if (samples[i - 1].state == ContactState::Stick && samples[i].state == ContactState::Slip) {
      summary.breakaway_time = samples[i].t;
      break;
    }
  for (const auto &s : samples) {  // up to the first slip sample: the stick sample at the event is mu_s W
    summary.start_friction_force = std::max(summary.start_friction_force, std::abs(s.friction_force));
    if (s.state == ContactState::Slip) break;
  }
  double tol = PistonRingSummary::steady_tolerance;
  const auto &last = samples.back();
  const double t0 = samples.front().t;
  const auto &p = system.parameters();
  if (p.motion == PistonMotion::Ramp) {
    summary.steady_criterion = "|friction force| and sliding speed within 2 % of their final values";
    summary.steady_mu = last.mu;
    summary.steady_friction_force = std::abs(last.friction_force);
    const double force_band = tol * std::abs(last.friction_force), speed_band = tol * std::abs(last.speed);
    double steady_from = t0;
    for (std::size_t i = samples.size(); i-- > 0;) {
      const auto &s = samples[i];
      if (std::abs(std::abs(s.friction_force) - std::abs(last.friction_force)) > force_band ||
          std::abs(s.speed - last.speed) > speed_band) {
        steady_from = i + 1 < samples.size() ? samples[i + 1].t : last.t;
        break;
      }
    }
    if (steady_from <= t0 + 0.9 * (last.t - t0)) summary.steady_time = steady_from;
    return summary;
  }
  // Crank: means over a revolution, or over the gas cycle (720 deg four-stroke) when there is one.
  tol = PistonRingSummary::cycle_tolerance;
  const double cycle = p.gas.empty() ? 2.0 * kPi : p.gas.cycle;
  summary.steady_criterion = fmt_cycle(cycle) + "-mean |friction force| within 1 % of the last full cycle's";
  const double period = cycle / p.crank_speed;
  const long cycles = static_cast<long>(std::floor((last.t - t0) / period + 1e-9));
  if (cycles < 1) return summary;
  std::vector<double> mean_force(cycles, 0.0), mean_load(cycles, 0.0);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double dt = samples[i].t - samples[i - 1].t;
    const long rev = static_cast<long>(std::floor((0.5 * (samples[i].t + samples[i - 1].t) - t0) / period));
    if (dt <= 0.0 || rev >= cycles) continue;
    mean_force[rev] += 0.5 * dt * (std::abs(samples[i].friction_force) + std::abs(samples[i - 1].friction_force));
    mean_load[rev] += 0.5 * dt * (samples[i].normal_load + samples[i - 1].normal_load);
  }
  const double final_force = mean_force.back() / period;
  summary.steady_friction_force = final_force;
  summary.steady_mu = mean_force.back() / mean_load.back();
  long first_steady = cycles - 1;
  while (first_steady > 0 && std::abs(mean_force[first_steady - 1] / period - final_force) <= tol * final_force)
    --first_steady;
  if (cycles >= 2 && first_steady < cycles - 1) summary.steady_time = t0 + first_steady * period;
  return summary;
}

}  // namespace runin::continuum
