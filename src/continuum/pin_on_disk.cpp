#include "continuum/pin_on_disk.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
int sign_of(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }
}  // namespace

void PinOnDiskParameters::validate() const {
  require(std::isfinite(mass) && mass > 0.0, "mass must be positive");
  require(std::isfinite(track_radius) && track_radius > 0.0, "track_radius must be positive");
  require(std::isfinite(normal_load) && normal_load > 0.0, "normal_load must be positive");
  require(std::isfinite(applied_torque), "applied_torque must be finite");
  require(std::isfinite(ramp_time) && ramp_time >= 0.0, "ramp_time must be >= 0");
  if (drive == PinDrive::Speed)
    require(std::isfinite(sliding_speed) && sliding_speed > 0.0, "sliding_speed must be positive");
}

double PinOnDiskParameters::prescribed_speed(double t) const {
  if (ramp_time <= 0.0 || t >= ramp_time) return sliding_speed;
  return sliding_speed * std::max(t, 0.0) / ramp_time;
}

double PinOnDiskParameters::prescribed_acceleration(double t) const {
  return ramp_time > 0.0 && t <= ramp_time ? sliding_speed / ramp_time : 0.0;
}

void PinOnDiskRun::validate() const {
  require(std::isfinite(t_end) && t_end > 0.0, "t_end must be positive");
  require(std::isfinite(output_interval) && output_interval > 0.0, "output_interval must be positive");
  require(t_end / output_interval <= 1e7, "output_interval gives more than 1e7 samples");
  require(std::isfinite(initial_speed), "initial_speed must be finite");
  require(max_events > 0, "max_events must be positive");
}

PinOnDiskSystem::PinOnDiskSystem(PinOnDiskParameters parameters, SlidingFriction friction)
    : p_(parameters), friction_(std::move(friction)) {
  p_.validate();
}

double PinOnDiskSystem::applied_torque(double t) const {
  if (p_.ramp_time <= 0.0 || t >= p_.ramp_time) return p_.applied_torque;
  return p_.applied_torque * std::max(t, 0.0) / p_.ramp_time;
}

double PinOnDiskSystem::static_torque_limit() const {
  return friction_.static_coefficient() * p_.normal_load * p_.track_radius;
}

double PinOnDiskSystem::static_torque_limit(const double *y) const {
  return friction_.static_coefficient(y[2]) * p_.normal_load * p_.track_radius;
}

double PinOnDiskSystem::friction_torque(double t, const double *y, ContactState state, int direction) const {
  if (state == ContactState::Stick) return applied_torque(t);  // whatever keeps w = 0
  const double speed = p_.drive == PinDrive::Speed ? p_.prescribed_speed(t) : p_.track_radius * y[0];
  return direction * friction_.kinetic(y[1], speed, y[2]) * p_.normal_load * p_.track_radius;
}

void PinOnDiskSystem::rhs(double t, const double *y, double *dydt, ContactState state, int direction) const {
  if (state == ContactState::Stick) {
    dydt[0] = 0.0;
    dydt[1] = 0.0;
    dydt[2] = friction_.state_rate(y[2], 0.0, false);
    return;
  }
  if (p_.drive == PinDrive::Speed) {  // w = V(t) / r prescribed: y[0] is not used (its jump in dw/dt at
    const double speed = p_.prescribed_speed(t);  // the ramp end would stall CVODE)
    dydt[0] = 0.0;
    dydt[1] = speed;
    dydt[2] = friction_.state_rate(y[2], speed, true);
    return;
  }
  dydt[0] = (applied_torque(t) - friction_torque(t, y, state, direction)) / p_.inertia();
  // direction * V rather than |V|: smooth through the re-stick root, equal to |V| before it.
  dydt[1] = direction * p_.track_radius * y[0];
  dydt[2] = friction_.state_rate(y[2], p_.track_radius * y[0], true);
}

PinOnDiskSample PinOnDiskSystem::sample(double t, const double *y, ContactState state, int direction) const {
  PinOnDiskSample s;
  s.t = t;
  s.applied_torque = applied_torque(t);
  s.friction_torque = friction_torque(t, y, state, direction);
  if (p_.drive == PinDrive::Speed)
    s.applied_torque = s.friction_torque + p_.inertia() * p_.prescribed_acceleration(t) / p_.track_radius;
  s.friction_force = s.friction_torque / p_.track_radius;
  s.mu = s.friction_force / p_.normal_load;
  s.mu_law = friction_.kinetic(y[1], 0.0, y[2]);
  s.roughness = y[2];
  s.speed = state == ContactState::Stick ? 0.0
            : (p_.drive == PinDrive::Speed ? p_.prescribed_speed(t) : p_.track_radius * y[0]);
  s.distance = y[1];
  s.state = state;
  return s;
}

namespace {
struct PinOnDiskHooks : SystemHooks<PinOnDiskSystem, PinOnDiskObserver> {
  PinOnDiskHooks(const PinOnDiskSystem &sys, const PinOnDiskObserver &obs, const PinOnDiskRefresh &ref)
      : SystemHooks(sys, obs), refresh_fn(ref) {}
  const PinOnDiskRefresh &refresh_fn;
  bool refresh(StickSlipState &) { return refresh_fn ? refresh_fn() : false; }
  static constexpr std::size_t speed_index = 0;
  double breakaway_function(double t, const double *y) const { return system.breakaway_function(t, y); }
  int breakaway_direction(double t, const double *) const {
    const int direction = sign_of(system.applied_torque(t));
    return direction != 0 ? direction : sign_of(system.parameters().applied_torque);  // frictionless, ramp at 0
  }
};
}  // namespace

SolveReport simulate(const PinOnDiskSystem &system, const PinOnDiskRun &run, const PinOnDiskObserver &observer,
                     const PinOnDiskRefresh &refresh) {
  run.validate();
  const double radius = system.parameters().track_radius;
  const bool speed_drive = system.parameters().drive == PinDrive::Speed;

  SolveReport report;
  CvodeIntegrator integrator(PinOnDiskSystem::state_size, run.integrator);
  StickSlipState start;
  start.y = {run.initial_speed / radius, 0.0, system.friction().initial_state()};
  start.state = run.initial_speed != 0.0 ? ContactState::Slip : ContactState::Stick;
  start.direction = sign_of(run.initial_speed);
  // The speed drive slides throughout: no events.
  const StickSlipGrid grid{run.t_end, run.output_interval, system.parameters().ramp_time, run.max_events, !speed_drive};
  PinOnDiskHooks hooks(system, observer, refresh);
  StickSlipLoop<PinOnDiskHooks> loop(hooks, grid, integrator, std::move(start), report);

  // Already past the static limit at the start (step loading), or no static friction at all
  // (CVODE does not report a root function that starts at zero)?
  auto &s = loop.state();
  const bool frictionless = system.static_torque_limit(s.y.data()) == 0.0 && system.parameters().applied_torque != 0.0;
  if (speed_drive) {  // the drive moves the pin from t = 0: break-away at the static limit at once
    s.y[0] = system.parameters().prescribed_speed(0.0) / radius;
    report.breakaway_times.push_back(0.0);
    s.state = ContactState::Slip;
    s.direction = 1;
  } else if (s.state == ContactState::Stick && (system.breakaway_function(s.t, s.y.data()) > 0.0 || frictionless)) {
    loop.emit();
    loop.break_away();
  }
  loop.run();
  return report;
}

double thesis_speed(const PinOnDiskParameters &p, double mu0, double alpha, double v0, double t) {
  const double drive = p.applied_torque / p.track_radius - mu0 * p.normal_load;  // N
  if (alpha == 0.0) return v0 + drive * t / p.mass;
  const double v_ss = drive / (alpha * p.normal_load);
  return v_ss + (v0 - v_ss) * std::exp(-alpha * p.normal_load * t / p.mass);
}

double thesis_torque_for_speed(const PinOnDiskParameters &p, double mu0, double alpha, double v0, double v1,
                               double t1) {
  require(t1 > 0.0, "target time must be positive");
  if (alpha == 0.0) return p.track_radius * (mu0 * p.normal_load + p.mass * (v1 - v0) / t1);
  const double decay = std::exp(-alpha * p.normal_load * t1 / p.mass);
  const double v_ss = (v1 - v0 * decay) / (1.0 - decay);
  return p.track_radius * p.normal_load * (mu0 + alpha * v_ss);
}

PinOnDiskSummary summarise(const std::vector<PinOnDiskSample> &samples) {
  PinOnDiskSummary summary;
  if (samples.empty()) return summary;
  for (const auto &s : samples)
    if (std::abs(s.friction_force) > std::abs(summary.peak_friction_force)) summary.peak_friction_force = s.friction_force;
  // Peak time: first sample within 1e-6 of the maximum (a held plateau has round-off wiggles).
  for (const auto &s : samples)
    if (std::abs(s.friction_force) >= (1.0 - 1e-6) * std::abs(summary.peak_friction_force)) {
      summary.peak_time = s.t;
      break;
    }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto &s = samples[i];
    if (summary.breakaway_time < 0.0 && i > 0 && samples[i - 1].state == ContactState::Stick &&
        s.state == ContactState::Slip)
      summary.breakaway_time = s.t;
  }
  const auto &last = samples.back();
  summary.steady_mu = last.mu;
  summary.steady_mu_law = last.mu_law;
  summary.steady_friction_force = last.friction_force;
  summary.final_speed = last.speed;
  if (samples.front().state == ContactState::Slip) summary.breakaway_time = samples.front().t;
  for (const auto &s : samples) {  // up to the first slip sample: the stick sample at the event is mu_s W
    summary.start_friction_force = std::max(summary.start_friction_force, std::abs(s.friction_force));
    if (s.state == ContactState::Slip) break;
  }
  std::vector<double> t, force, speed;
  for (const auto &s : samples) {
    t.push_back(s.t);
    force.push_back(s.friction_force);
    speed.push_back(s.speed);
  }
  const double tol = PinOnDiskSummary::steady_tolerance;
  const double t_force = equilibrium_time(t, force, tol), t_speed = equilibrium_time(t, speed, tol);
  if (t_force >= 0.0 && t_speed >= 0.0) summary.steady_time = std::max(t_force, t_speed);
  return summary;
}

RunInDistance run_in_distance(const std::vector<PinOnDiskSample> &samples, double tolerance, double tail) {
  RunInDistance r;
  r.tolerance = tolerance, r.tail = tail;
  if (samples.size() < 2) return r;
  const double s_end = samples.back().distance;
  const double cut = s_end - tail * (s_end - samples.front().distance);
  double weighted = 0.0, length = 0.0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double from = std::max(samples[i - 1].distance, cut), to = samples[i].distance;
    if (to > from) {
      weighted += samples[i].mu * (to - from);
      length += to - from;
    }
  }
  if (!(length > 0.0)) return r;
  r.steady_mu = weighted / length;
  for (std::size_t i = samples.size(); i-- > 0;) {
    if (std::abs(samples[i].mu - r.steady_mu) > tolerance * std::abs(r.steady_mu)) break;
    r.distance = samples[i].distance;
  }
  return r;
}

ContactStress hertz_contact_stress(double p0, double a, double mu, const tribo::Material &pin,
                                   const tribo::Material &disk, int points) {
  ContactStress c;
  c.method = "Hertz closed form (Hamilton 1983)";
  c.friction_coefficient = mu;
  c.contact_radius = a;
  c.peak_pressure = p0;
  const std::vector<double> x = tribo::cell_centres(-1.5 * a, 1.5 * a, points);
  const std::vector<double> z = tribo::uniform_points(0.0, 1.5 * a, points);
  const tribo::SlidingHertzSphere on_disk{p0, a, disk.poisson_ratio, mu}, on_pin{p0, a, pin.poisson_ratio, -mu};
  c.disk = body_stress(disk, tribo::hamilton_field(on_disk, x, z));
  c.pin = body_stress(pin, tribo::hamilton_field(on_pin, x, z));
  // the closed form's maximum, not the grid's: with friction it can sit on the contact edge between grid points
  c.disk.peak = tribo::hamilton_peak_von_mises(on_disk, c.disk.field);
  c.pin.peak = tribo::hamilton_peak_von_mises(on_pin, c.pin.field);
  return c;
}

ContactStress ring_contact_stress(const std::vector<double> &ring_pressure, double ring_width, double mu,
                                  const tribo::Material &pin, const tribo::Material &disk, int points) {
  ContactStress c;
  c.method = "influence functions (Boussinesq/Cerruti patches) on the solved pressure";
  c.friction_coefficient = mu;
  std::size_t last = 0;
  for (std::size_t i = 0; i < ring_pressure.size(); ++i)
    if (ring_pressure[i] > 0.0) last = i + 1;
  c.contact_radius = last * ring_width;
  c.peak_pressure = ring_pressure.empty() ? 0.0 : *std::max_element(ring_pressure.begin(), ring_pressure.end());
  const double half = 1.5 * std::max(c.contact_radius, ring_width);
  const std::vector<double> z = tribo::uniform_points(0.0, half, points);
  c.disk = body_stress(disk, tribo::axisymmetric_section(ring_pressure, ring_width, mu, disk.poisson_ratio, half,
                                                         points, z));
  c.pin = body_stress(pin, tribo::axisymmetric_section(ring_pressure, ring_width, -mu, pin.poisson_ratio, half,
                                                       points, z));
  return c;
}

}  // namespace runin::continuum
