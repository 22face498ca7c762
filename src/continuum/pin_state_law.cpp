#include "continuum/pin_state_law.h"

#include "tribo/number_format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace runin::continuum {
using tribo::format_g;

PinStateLaw::PinStateLaw(const PinStateLawSettings &settings, StateLawFriction &held)
    : s_(settings), held_(held), nodes_(held.law, held.policy, 0), disk_(tribo::ArchardWear(0.0, 1.0), settings.track_radius) {
  if (s_.flat_radius) {
    flat_grid_.emplace(*s_.flat_radius, s_.tip.rings, s_.tip.effective_modulus);
    grid_radius_ = *s_.flat_radius;
  } else {
    PinWearParameters wp = s_.tip;
    // Grid size: Hertz, and the cap an Archard wear at the law's largest w/p would flatten over the run.
    double factor = 0.0;
    const auto &w = held.law->table(coupling::StateField::WearRate).mean;
    for (std::size_t i = 0; i < w.size(); ++i)
      for (double x : w[i]) factor = std::max(factor, x / held.law->pressure()[i]);
    const tribo::ArchardWear equivalent(factor, 1.0);
    wp.grid_radius = s_.grid_radius ? *s_.grid_radius
                                    : suggested_grid_radius(wp.tip_radius, wp.effective_modulus, s_.load, &equivalent,
                                                            s_.slid_estimate);
    grid_radius_ = wp.grid_radius;
    pin_.emplace(wp, tribo::ArchardWear(0.0, 1.0), s_.load);
  }
  const int n = grid().rings();
  area_.resize(n);
  for (int i = 0; i < n; ++i) area_[i] = grid().ring_area(i);
  for (double a : area_) flat_area_ += a;
  uniform_.assign(n, s_.load / flat_area_);
  for (int i = 0; i < n; ++i)
    if (pressure()[i] > 0.0 && (smallest_node_area_ == 0.0 || area_[i] < smallest_node_area_))
      smallest_node_area_ = area_[i];
  nodes_ = NodeStateLaw(held.law, held.policy, n);
  if (held.film) nodes_.set_film(*held.film, counterface_duty());
}

void PinStateLaw::start() {
  held_.held_static = held_.mu_static ? *held_.mu_static : nodes_.peak_mu(pressure(), area_);
  held_.held_kinetic = nodes_.mu_effective(pressure(), area_);
}

bool PinStateLaw::step(const PinOnDiskSample &s) {
  const double dt = std::max(s.t - t_now_, 0.0);
  t_now_ = s.t;
  const double ds = s.distance - slid_;
  if (!(ds > 0.0)) {
    // at rest a film still regrows
    const NodeFilm *film = nodes_.film();
    if (!film || !(dt > 0.0) || !(film->settings().growth_rate > 0.0)) return false;
    nodes_.advance(pressure(), 0.0, dt);
    held_.held_kinetic = nodes_.mu_effective(pressure(), area_);
    return true;
  }
  wear(ds, dt);
  slid_ = s.distance;
  held_.held_kinetic = nodes_.mu_effective(pressure(), area_);
  return true;
}

// Slides ds in dt: outer steps bounded by the pressure-wear stability of the tip (flat: one step, p stays uniform),
// each taking its share of dt.
void PinStateLaw::wear(double ds, double dt) {
  const int n = grid().rings();
  double remaining = ds;
  while (remaining > 0.0) {
    double step = remaining;
    if (pin_) {
      if (wear_steps_ >= s_.tip.max_steps)
        throw SlowStepError(SplitStatus::TooManySlowSteps, "pin wear at t = " + format_g(t_now_) + " s: more than " +
                                                               std::to_string(s_.tip.max_steps) + " wear updates");
      step = std::min(remaining, nodes_.stable_contact_step(pressure(), pin_->contact_stiffness(), s_.tip.step_safety));
      if (remaining - step < 1e-9 * ds) step = remaining;
    }
    const double width = 2.0 * contact_radius();
    const auto inc = nodes_.advance(pressure(), step, dt * step / ds);
    double volume = 0.0;
    for (int i = 0; i < n; ++i) volume += inc.counterface[i] * area_[i];
    disk_.slide_volume(volume, step, width);
    if (pin_ && !pin_->apply(inc.body, step))
      throw SlowStepError(SplitStatus::SlowFailure, "pin wear at t = " + format_g(t_now_) + " s: " + pin_->message());
    ++wear_steps_;
    remaining -= step;
  }
}

PinStateLaw::State PinStateLaw::state() const {
  State row;
  const auto &p = pressure();
  const auto &h = nodes_.state();
  double loaded = 0.0, volume = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    volume += h[i] * area_[i];
    if (p[i] > 0.0) {
      row.h_mean += h[i] * area_[i];
      loaded += area_[i];
    }
    row.h_max = std::max(row.h_max, h[i]);
  }
  row.h_mean = loaded > 0.0 ? row.h_mean / loaded : 0.0;
  row.mu_eff = held_.held_kinetic;
  row.wear_volume = volume;
  row.contact_radius = contact_radius();
  row.peak_pressure = *std::max_element(p.begin(), p.end());
  row.mean_pressure = pin_ ? pin_->contact().mean_pressure : s_.load / flat_area_;
  row.disk_wear_volume = disk_.volume();
  row.disk_track_depth = disk_.depth();
  if (const NodeFilm *film = nodes_.film()) {
    std::vector<double> load(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) load[i] = std::max(p[i], 0.0) * area_[i];
    row.film_coverage = film->mean_coverage(load);
  }
  return row;
}

void PinStateLaw::restore(const Snapshot &s) {
  pin_ = s.pin;
  nodes_ = s.nodes;
  disk_ = s.disk;
  slid_ = s.slid;
  t_now_ = s.t_now;
  held_.held_kinetic = s.held_kinetic;
  wear_steps_ = s.wear_steps;
}

double PinStateLaw::profile_height(int ring) const {
  return pin_ ? pin_->profile_height(ring) : nodes_.state()[static_cast<std::size_t>(ring)];
}

void WearSteps::validate() const {
  if (!(std::isfinite(tolerance) && tolerance > 0.0 && tolerance <= 0.1))
    throw std::invalid_argument("wear steps: tolerance must be in (0, 0.1], got " + format_g(tolerance));
  if (!(std::isfinite(max_fraction) && max_fraction > 0.0 && max_fraction <= 1.0))
    throw std::invalid_argument("wear steps: max_fraction must be in (0, 1], got " + format_g(max_fraction));
  if (max_steps <= 0) throw std::invalid_argument("wear steps: max_steps must be positive");
  if (dynamics_chunk <= 0) throw std::invalid_argument("wear steps: dynamics_chunk must be positive");
}

namespace {
// A slow step's failure as a status (split_run's rule).
template <class F>
bool guarded(SplitReport &report, double t, const F &step) {
  try {
    step();
    return true;
  } catch (const SlowStepError &e) {
    report.status = e.status, report.message = e.what();
  } catch (const std::out_of_range &e) {
    report.status = SplitStatus::LawOutOfRange, report.message = e.what();
  } catch (const std::invalid_argument &e) {
    report.status = SplitStatus::InvalidState, report.message = e.what();
  }
  report.time = t;
  return false;
}

// The step's error estimate over the tolerance: the relative change of mu_eff (the lag of F/W behind the state,
// first order in the step) and each node's move inside the law's depth range over that range's length.
double step_error(double mu0, double mu1, const std::vector<double> &h0, const std::vector<double> &h1,
                  double depth_range, double tolerance) {
  double e = std::abs(mu1 - mu0) / std::max(std::abs(mu0), 1e-12);
  if (depth_range > 0.0)
    for (std::size_t i = 0; i < h0.size(); ++i)
      e = std::max(e, std::abs(std::min(h1[i], depth_range) - std::min(h0[i], depth_range)) / depth_range);
  return e / tolerance;
}
}  // namespace

namespace {
using Observer = std::function<void(const PinOnDiskSample &)>;

// The step-size controller of both adaptive loops: first order (the change goes as the step), safety 0.9, a
// rejected step shrinks at most 5x, an accepted one grows at most 2x.
double shrink_factor(double err) { return std::max(0.2, 0.9 / err); }
double grow_factor(double err) { return err > 0.0 ? std::clamp(0.9 / err, 0.2, 2.0) : 2.0; }

// Counts one more try of a step ending at t; false (TooManySlowSteps in the report) past max_steps.
bool within_step_budget(SplitReport &report, long &tries, long max_steps, double t) {
  if (++tries <= max_steps) return true;
  report.status = SplitStatus::TooManySlowSteps;
  report.message = "adaptive wear steps at t = " + format_g(t) + " s: more than " + std::to_string(max_steps) + " steps";
  report.time = t;
  return false;
}

SplitReport run_speed_adaptive(const PinOnDiskSystem &system, const PinOnDiskRun &run, PinStateLaw &pin,
                               const WearSteps &steps, const Observer &observer) {
  const auto &p = system.parameters();
  // The drive prescribes s(t) (a linear ramp of V, then V held): the pin's dynamics are kinematic, F = mu_eff W
  // (+ alpha V), and the drive's torque adds J dw/dt on the ramp (PinOnDiskSystem::sample). Only the slow system
  // is stepped, in distance.
  const double V = p.sliding_speed, ramp = p.ramp_time, s_ramp = 0.5 * V * ramp;
  const auto distance_at = [&](double t) {
    return ramp > 0.0 && t <= ramp ? 0.5 * V * t * t / ramp : s_ramp + V * (t - ramp);
  };
  const auto time_at = [&](double s) {
    return s <= s_ramp ? std::sqrt(2.0 * ramp * s / V) : ramp + (s - s_ramp) / V;
  };
  const double R0 = system.friction().initial_state();
  const auto sample_at = [&](double t, double s) {
    const double y[PinOnDiskSystem::state_size] = {p.prescribed_speed(t) / p.track_radius, s, R0};
    return system.sample(t, y, ContactState::Slip, 1);  // F/W: the coefficient held over the step that ends here
  };

  SplitReport report;
  report.fast.breakaway_times.push_back(0.0);  // the drive moves the pin from t = 0 (as simulate)
  if (!guarded(report, 0.0, [&] { pin.start(); })) return report;
  const PinOnDiskSample first = sample_at(0.0, 0.0);
  if (!guarded(report, 0.0, [&] { pin.step(first); })) return report;
  if (observer) observer(first);

  const double s_end = distance_at(run.t_end);
  const double max_step = steps.max_fraction * s_end;
  const double smallest = 1e-12 * s_end;
  std::vector<double> stops;
  for (double t : steps.stop_times)
    if (t > 0.0 && t < run.t_end) stops.push_back(distance_at(t));
  std::sort(stops.begin(), stops.end());
  stops.push_back(s_end);
  std::size_t next_stop = 0;
  const double depth_range = pin.nodes().law().worn_depth().back();
  // First try: the distance of the first output interval (of a fixed-interval run).
  double s = 0.0, ds = std::min(distance_at(std::min(run.output_interval, run.t_end)), max_step);
  long tries = 0;
  while (s < s_end) {
    while (stops[next_stop] <= s) ++next_stop;
    const bool at_stop = s + ds >= stops[next_stop] * (1.0 - 1e-14);
    const double s1 = at_stop ? stops[next_stop] : s + ds;
    const double t1 = s1 >= s_end ? run.t_end : time_at(s1);
    if (!within_step_budget(report, tries, steps.max_steps, t1)) return report;
    const PinOnDiskSample sample = sample_at(t1, s1);
    const auto before = pin.save();
    const double mu0 = pin.held().held_kinetic;
    if (!guarded(report, t1, [&] { pin.step(sample); })) return report;
    const double err = step_error(mu0, pin.held().held_kinetic, before.nodes.state(), pin.nodes().state(),
                                  depth_range, steps.tolerance);
    if (err > 1.0) {  // rejected: back, and a shorter step (first order: the change goes as the step)
      pin.restore(before);
      if (s1 - s <= smallest) {
        report.status = SplitStatus::SlowFailure;
        report.message = "adaptive wear steps at t = " + format_g(t1) + " s: the change of mu_eff or of the node states "
                         "exceeds the tolerance over a step of " + format_g(s1 - s) + " m (a jump in the law?)";
        report.time = t1;
        report.failed_step_distance = s1 - s;
        report.failed_step_duration = t1 - time_at(s);
        return report;
      }
      ++report.rejected_steps;
      ds = std::max((s1 - s) * shrink_factor(err), smallest);
      continue;
    }
    ++report.slow_steps;
    report.time = t1;
    if (observer) observer(sample);
    const double grow = grow_factor(err);
    // a step cut short by a stop does not set the next one
    ds = std::min(max_step, at_stop && s1 - s < ds ? ds : (s1 - s) * grow);
    s = s1;
  }
  report.fast.end_time = run.t_end;
  return report;
}

// The pin's slow system, continued by a later split_run: its start() does not reset the held coefficients.
class Continued final : public SlowSystem<PinOnDiskSample> {
 public:
  explicit Continued(PinStateLaw &pin) : pin_(pin) {}
  void start() override {}
  bool step(const PinOnDiskSample &s) override { return pin_.step(s); }

 private:
  PinStateLaw &pin_;
};

// Torque drive: the full dynamics (split_run at the output interval) over the ramp and wherever the pin may stick
// or its speed lags its quasi-static value; quasi-static distance steps where it slides steadily. Steady sliding
// under the held torque T needs alpha > 0: V_ss = (T / r - mu_eff W) / (alpha W), reached with the time constant
// tau = m / (alpha W); the quasi-static speed lags the true one by tau dV_ss/dt, which the control keeps below
// tolerance x V_ss.
SplitReport run_torque_adaptive(const PinOnDiskSystem &system, const PinOnDiskRun &run, PinStateLaw &pin,
                                const WearSteps &steps, const Observer &observer) {
  const auto &p = system.parameters();
  const double alpha = system.friction().speed_coefficient(), W = p.normal_load, r = p.track_radius;
  const double T = p.applied_torque, tau = p.mass / (alpha * W), tol = steps.tolerance;
  const auto v_ss = [&](double mu) { return (T / r - mu * W) / (alpha * W); };
  const double R0 = system.friction().initial_state();
  const double depth_range = pin.nodes().law().worn_depth().back();
  const long chunk = steps.dynamics_chunk;

  SplitReport report;
  PinOnDiskSample last, before_last;
  bool have_two = false;
  // A stretch of full dynamics from the last sample (the first: from t = 0 with the ramp), samples shifted.
  const auto full_dynamics = [&](double t_stop, bool first) {
    PinOnDiskParameters q = p;
    PinOnDiskRun r1 = run;
    double t0 = 0.0, s0 = 0.0;
    if (!first) {
      q.ramp_time = 0.0;  // past the ramp: the torque is held
      t0 = last.t, s0 = last.distance;
      r1.initial_speed = last.state == ContactState::Slip ? last.speed : 0.0;
    }
    r1.t_end = t_stop - t0;
    const PinOnDiskSystem shifted(q, system.friction());
    Continued continued(pin);
    SlowSystem<PinOnDiskSample> &slow = first ? static_cast<SlowSystem<PinOnDiskSample> &>(pin) : continued;
    bool skip = !first;  // the restart's first sample is the last one again
    const auto part = split_run<PinOnDiskSample>(
        slow,
        [&](const auto &on_sample, const auto &refresh) {
          return simulate(shifted, r1, [&](const PinOnDiskSample &s) {
            if (std::exchange(skip, false)) return;
            PinOnDiskSample a = s;
            a.t += t0, a.distance += s0;
            on_sample(a);
          }, refresh);
        },
        [&](const PinOnDiskSample &s) {
          before_last = last, last = s;
          have_two = true;
          if (observer) observer(s);
        });
    report.slow_steps += part.slow_steps;
    report.fast.steps += part.fast.steps;
    for (double e : part.fast.breakaway_times) report.fast.breakaway_times.push_back(e + t0);
    for (double e : part.fast.restick_times) report.fast.restick_times.push_back(e + t0);
    report.fast.end_time = part.fast.end_time + t0;
    report.time = part.time + t0;
    if (!part.ok()) {
      report.status = part.status, report.message = part.message;
      report.fast.status = part.fast.status, report.fast.message = part.fast.message;
    }
    return part.ok();
  };
  // Steady sliding: slipping past the ramp, at a positive V_ss that the speed follows within the tolerance.
  const auto steady = [&] {
    if (!have_two || last.state != ContactState::Slip || last.t < p.ramp_time || !(last.t > before_last.t)) return false;
    const double v = v_ss(pin.held().held_kinetic);
    if (!(v > 0.0) || std::abs(last.speed - v) > tol * v) return false;
    const double dv_dt = std::abs(last.speed - before_last.speed) / (last.t - before_last.t);
    return tau * dv_dt <= tol * v;
  };

  if (!full_dynamics(std::min(run.t_end, std::max(p.ramp_time, run.output_interval)), true)) return report;
  double ds = 0.0;
  long tries = 0;
  while (last.t < run.t_end * (1.0 - 1e-14)) {
    if (!steady()) {
      ++report.fallbacks;
      if (!full_dynamics(std::min(run.t_end, last.t + chunk * run.output_interval), false)) return report;
      ds = 0.0;
      continue;
    }
    if (ds == 0.0) ds = last.speed * run.output_interval;
    // Quasi-static: V = V_ss(mu_eff held) over the step, then the slow step; back to the dynamics when V_ss
    // changes faster than the pin can follow.
    bool fall_back = false;
    while (last.t < run.t_end * (1.0 - 1e-14)) {
      const double v = v_ss(pin.held().held_kinetic);
      if (!(v > 0.0)) {
        fall_back = true;
        break;
      }
      double stop = run.t_end;  // the next VTK time, or the end
      for (double ts : steps.stop_times)
        if (ts > last.t * (1.0 + 1e-14) && ts < stop) stop = ts;
      const double t1 = last.t + ds / v >= stop * (1.0 - 1e-14) ? stop : last.t + ds / v;
      const double s1 = last.distance + v * (t1 - last.t);
      if (!within_step_budget(report, tries, steps.max_steps, t1)) return report;
      const double y[PinOnDiskSystem::state_size] = {v / r, s1, R0};
      const PinOnDiskSample sample = system.sample(t1, y, ContactState::Slip, 1);
      const auto before = pin.save();
      const double mu0 = pin.held().held_kinetic;
      if (!guarded(report, t1, [&] { pin.step(sample); })) return report;
      const double v1 = v_ss(pin.held().held_kinetic);
      const double lag = tau * std::abs(v1 - v) / ((t1 - last.t) * v);  // tau dV_ss/dt / V_ss
      if (lag > tol || !(v1 > 0.0)) {  // the pin would lag its quasi-static speed: full dynamics
        pin.restore(before);
        fall_back = true;
        break;
      }
      const double err = std::max(step_error(mu0, pin.held().held_kinetic, before.nodes.state(),
                                             pin.nodes().state(), depth_range, tol),
                                  std::abs(v1 - v) / (v * tol));
      if (err > 1.0) {
        pin.restore(before);
        ++report.rejected_steps;
        ds = (s1 - last.distance) * shrink_factor(err);
        if (ds <= 1e-12 * std::max(s1, 1e-12)) {
          fall_back = true;
          break;
        }
        continue;
      }
      ++report.slow_steps;
      report.time = t1;
      before_last = last, last = sample;
      if (observer) observer(sample);
      const double grow = grow_factor(err);
      ds = std::min((s1 - before_last.distance) * grow,
                    steps.max_fraction * std::max(last.distance, v * run.t_end));
    }
    if (!fall_back) continue;
    ++report.fallbacks;
    if (!full_dynamics(std::min(run.t_end, last.t + chunk * run.output_interval), false)) return report;
    ds = 0.0;
  }
  report.fast.end_time = run.t_end;
  return report;
}
}  // namespace

SplitReport run_pin_split(const PinOnDiskSystem &system, const PinOnDiskRun &run, PinStateLaw &pin,
                          const WearSteps &steps, const std::function<void(const PinOnDiskSample &)> &observer) {
  if (!steps.adaptive)
    return split_run<PinOnDiskSample>(
        pin, [&](const auto &on_sample, const auto &refresh) { return simulate(system, run, on_sample, refresh); },
        observer);
  steps.validate();
  run.validate();
  const auto &p = system.parameters();
  if (p.drive == PinDrive::Speed) return run_speed_adaptive(system, run, pin, steps, observer);
  if (!(system.friction().speed_coefficient() > 0.0) || !(p.applied_torque > 0.0))
    throw std::invalid_argument("adaptive wear steps under the torque drive need alpha > 0 and a positive torque "
                                "(steady sliding at V_ss = (T / r - mu W) / (alpha W))");
  return run_torque_adaptive(system, run, pin, steps, observer);
}

ArchardRatios archard_ratios(const coupling::StateLaw &law, double pin_volume, double disk_volume,
                             double load_distance) {
  ArchardRatios r;
  const double p0 = law.pressure().front();
  const auto slice = law.slice(p0, coupling::OutOfRange::Clamp);
  r.k_pin = law.value(coupling::StateField::WearRate, slice, 0.0) / p0;
  r.k_disk = law.value(coupling::StateField::CounterfaceWearRate, slice, 0.0) / p0;
  if (load_distance > 0.0) {
    if (r.k_pin > 0.0) r.pin = pin_volume / (r.k_pin * load_distance);
    if (r.k_disk > 0.0) r.disk = disk_volume / (r.k_disk * load_distance);
  }
  return r;
}

}  // namespace runin::continuum
