#include "continuum/journal_bearing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "continuum/state_law_splitting.h"

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
int sign_of(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }
bool finite_non_negative(double x) { return std::isfinite(x) && x >= 0.0; }
}  // namespace

double shaft_torsional_stiffness(double diameter, double length, double youngs_modulus, double poisson_ratio) {
  require(std::isfinite(diameter) && diameter > 0.0, "shaft diameter must be positive");
  require(std::isfinite(length) && length > 0.0, "shaft length must be positive");
  require(std::isfinite(youngs_modulus) && youngs_modulus > 0.0, "shaft youngs_modulus must be positive");
  require(poisson_ratio > -1.0 && poisson_ratio < 0.5, "shaft poisson_ratio must be in (-1, 0.5)");
  const double shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
  const double polar_moment = M_PI * std::pow(diameter, 4) / 32.0;
  return shear_modulus * polar_moment / length;
}

void JournalBearingParameters::validate() const {
  bore.validate();
  require(std::isfinite(load) && load > 0.0, "load must be positive");
  require(halves == 1 || halves == 2, "halves must be 1 or 2");
  require(finite_non_negative(second_half_load), "second_half_load must be >= 0 (0: equal to load)");
  require(std::isfinite(ramp_angle), "ramp_angle must be finite");
  require(std::isfinite(ramp_time) && ramp_time > 0.0, "ramp_time must be positive");
  require(std::isfinite(run_speed), "run_speed must be finite");
  require(std::isfinite(inertia) && inertia > 0.0, "inertia must be positive");
  require(std::isfinite(coupling_stiffness) && coupling_stiffness > 0.0, "coupling_stiffness must be positive");
  require(finite_non_negative(coupling_damping), "coupling_damping must be >= 0");
  require(finite_non_negative(wear_coefficient), "wear_coefficient must be >= 0");
  require(std::isfinite(hardness) && hardness > 0.0, "hardness must be positive");
}

double JournalBearingParameters::drive_speed(double t) const {
  return t < ramp_time ? ramp_angle / ramp_time : run_speed;
}

double JournalBearingParameters::drive_angle(double t) const {
  if (t <= ramp_time) return ramp_angle * std::max(t, 0.0) / ramp_time;
  return ramp_angle + run_speed * (t - ramp_time);
}

void JournalBearingRun::validate() const {
  require(std::isfinite(t_end) && t_end > 0.0, "t_end must be positive");
  require(std::isfinite(output_interval) && output_interval > 0.0, "output_interval must be positive");
  require(t_end / output_interval <= 1e7, "output_interval gives more than 1e7 samples");
  require(std::isfinite(wear_step_fraction) && wear_step_fraction > 0.0, "wear_step_fraction must be positive");
  require(finite_non_negative(fixed_wear_step), "fixed_wear_step must be >= 0");
  for (double f : frame_times) require(finite_non_negative(f), "frame_times must be >= 0");
  require(max_events > 0, "max_events must be positive");
}

JournalBearingSystem::JournalBearingSystem(JournalBearingParameters parameters, SlidingFriction friction)
    : p_((parameters.validate(), parameters)),
      friction_(std::move(friction)),
      contact_(p_.bore),
      wear_(p_.wear_coefficient, p_.hardness, p_.archard_form) {}

namespace {

// The wear and contact state between wear updates.
struct Surface {
  std::vector<double> wear;      // m per node
  ConformalSolution contact;
  double normal_force = 0.0;     // N
  double distance_at_update = 0.0;
  double committed_volume = 0.0;
};

bool solve_contact(const JournalBearingSystem &sys, Surface &surface, std::string &message, int half = 0) {
  const std::vector<double> previous = surface.contact.pressure;
  surface.contact = sys.contact().solve(sys.load_per_length(half), surface.wear, previous.empty() ? nullptr : &previous);
  if (!surface.contact.ok()) {
    message = std::string("contact solver") + (sys.parameters().halves == 2 ? (half ? " (upper half)" : " (lower half)") : "") +
              ": " + to_string(surface.contact.status) +
              (surface.contact.status == ConformalStatus::ArcTooShort ? " (increase contact.arc_half_angle)" : "");
    return false;
  }
  surface.normal_force = surface.contact.normal_force_per_length * sys.parameters().bore.axial_width;
  return true;
}

void apply_wear(const JournalBearingSystem &sys, Surface &surface, double distance) {
  const double ds = distance - surface.distance_at_update;
  const double panel_area = sys.contact().panel_length() * sys.parameters().bore.axial_width;
  for (std::size_t i = 0; i < surface.wear.size(); ++i) {
    const double depth = sys.wear_law().depth_rate(surface.contact.pressure[i]) * ds;
    surface.wear[i] += depth;
    surface.committed_volume += depth * panel_area;
  }
  surface.distance_at_update = distance;
}

}  // namespace

namespace {
// friction.model = "state_law": the slow system of the splitting driver (state_law_splitting.h). Per half the node
// states, the held kinetic and static coefficients and the shaft's worn volume. A slow step advances every half to
// the sliding distance of a sample (node states and bore by the law, contact re-solve, mu_eff); the wear-step roots
// of the fast stepper advance it the same way (advance_to), so a slow step never outgrows the stable wear step.
class BearingStateLaw final : public SlowSystem<JournalBearingSample> {
 public:
  BearingStateLaw(const JournalBearingSystem &sys, std::vector<Surface> &surf, JournalBearingReport &rep,
                  const JournalBearingRun &run)
      : system_(sys), surfaces_(surf), report_(rep), wear_fraction_(run.wear_step_fraction),
        fixed_wear_step_(run.fixed_wear_step) {}

  std::vector<double> mu_kin, mu_stat;  // per half
  double next_wear = 0.0;               // m, the sliding distance of the next wear-step root
  bool root_changed = false;            // advanced at a root since the last restart

  void start() override {
    const auto *held = system_.friction().state_law();
    const auto area = node_areas();
    for (std::size_t h = 0; h < surfaces_.size(); ++h) {
      laws_.emplace_back(held->law, held->policy, area.size());
      if (held->film) laws_.back().set_film(*held->film);  // the bore's film (the case refuses a shaft film)
      time_at_update_.push_back(0.0);
      mu_stat.push_back(held->mu_static ? *held->mu_static : laws_[h].peak_mu(surfaces_[h].contact.pressure, area));
      mu_kin.push_back(laws_[h].mu_effective(surfaces_[h].contact.pressure, area));
      counterface_volume_.push_back(0.0);
    }
    set_held();
    report_.stable_wear_step = stable_step();
    next_wear = wear_step();
  }
  // Operator splitting: the sample's friction is the one held over the interval that ends here; then the node
  // states and the bore advance by the distance slid in it and the next interval gets the new mu_eff.
  bool step(const JournalBearingSample &s) override {
    if (!(s.distance > surfaces_[0].distance_at_update)) return false;
    std::string message;
    ++report_.wear_updates;
    if (!advance_to(s.distance, s.t, message)) throw SlowStepError(SplitStatus::SlowFailure, "journal bearing: " + message);
    return true;
  }
  // Advances every half to the sliding distance `distance` at time t: node states (and film) and bore by the law,
  // re-solve, mu_eff.
  bool advance_to(double distance, double t, std::string &message) {
    const auto area = node_areas();
    for (std::size_t h = 0; h < surfaces_.size(); ++h) {
      Surface &surface = surfaces_[h];
      const double ds = distance - surface.distance_at_update;
      if (!(ds > 0.0)) continue;
      const double dt = std::max(t - time_at_update_[h], 0.0);
      time_at_update_[h] = t;
      const auto inc = laws_[h].advance(surface.contact.pressure, ds, dt);
      for (std::size_t i = 0; i < surface.wear.size(); ++i) {
        surface.wear[i] += inc.body[i];
        surface.committed_volume += inc.body[i] * area[i];
        counterface_volume_[h] += inc.counterface[i] * area[i];
      }
      surface.distance_at_update = distance;
      if (!solve_contact(system_, surface, message, static_cast<int>(h))) return false;
      mu_kin[h] = laws_[h].mu_effective(surface.contact.pressure, area);
    }
    set_held();
    next_wear = distance + wear_step();
    return true;
  }
  // The sample's state-law columns (after its step).
  void fill(JournalBearingSample &s) const {
    s.wear_volume = 0.0;
    double n = 0.0;
    for (std::size_t h = 0; h < surfaces_.size(); ++h) {
      JournalBearingHalfSample &half = s.half[h];
      const auto &state = laws_[h].state();
      const auto &pressure = surfaces_[h].contact.pressure;
      half.wear_volume = surfaces_[h].committed_volume;
      half.mu_eff = mu_kin[h];
      half.counterface_volume = counterface_volume_[h];
      int loaded_nodes = 0;
      for (std::size_t i = 0; i < state.size(); ++i) {
        half.h_max = std::max(half.h_max, state[i]);
        if (pressure[i] > 0.0) {
          half.h_mean += state[i];
          ++loaded_nodes;
        }
      }
      half.h_mean = loaded_nodes ? half.h_mean / loaded_nodes : 0.0;
      if (const NodeFilm *film = laws_[h].film()) half.film_coverage = film->mean_coverage(pressure);
      s.wear_volume += half.wear_volume;
      s.mu_eff += mu_kin[h] * surfaces_[h].normal_force;
      n += surfaces_[h].normal_force;
    }
    s.mu_eff = n > 0.0 ? s.mu_eff / n : 0.0;
  }
  std::vector<double> node_mu(std::size_t h) const { return laws_[h].node_mu(surfaces_[h].contact.pressure); }
  coupling::RangeUse use() const {
    coupling::RangeUse use;
    for (const auto &law : laws_) {
      use.lookups += law.use().lookups;
      use.below_pressure += law.use().below_pressure;
      use.above_pressure += law.use().above_pressure;
      use.beyond_depth += law.use().beyond_depth;
    }
    return use;
  }

 private:
  std::vector<double> node_areas() const {
    return std::vector<double>(static_cast<std::size_t>(system_.contact().nodes()),
                               system_.contact().panel_length() * system_.parameters().bore.axial_width);
  }
  double stable_step() {  // 2 / (k_c max_i w_i/p_i) over the halves
    double step = HUGE_VAL;
    for (std::size_t h = 0; h < surfaces_.size(); ++h)
      step = std::min(step, laws_[h].stable_contact_step(surfaces_[h].contact.pressure,
                                                         system_.contact().contact_stiffness_per_area(), 1.0));
    return step;
  }
  double wear_step() { return fixed_wear_step_ > 0.0 ? fixed_wear_step_ : wear_fraction_ * stable_step(); }
  void set_held() {  // the shared friction's held values: normal-force-weighted, for the summary and mu_law
    auto *held = system_.friction().state_law();
    double n = 0.0, kin = 0.0, stat = 0.0;
    for (std::size_t h = 0; h < surfaces_.size(); ++h) {
      n += surfaces_[h].normal_force;
      kin += mu_kin[h] * surfaces_[h].normal_force;
      stat += mu_stat[h] * surfaces_[h].normal_force;
    }
    held->held_kinetic = n > 0.0 ? kin / n : 0.0;
    held->held_static = n > 0.0 ? stat / n : 0.0;
  }

  const JournalBearingSystem &system_;
  std::vector<Surface> &surfaces_;
  JournalBearingReport &report_;
  double wear_fraction_, fixed_wear_step_;
  std::vector<NodeStateLaw> laws_;
  std::vector<double> counterface_volume_;
  std::vector<double> time_at_update_;  // s, per half: when its film last advanced
};

// y = (theta, w, s, R_0[, R_1]); R_h is half h's friction-law state (feedback roughness), constant
// otherwise. Both halves slide over the same shaft surface, so s and the wear-update points are
// shared; pressure, wear and R are per half. The pressures are frozen between wear updates, which
// are an extra root (s = next_wear) in slip and update every half.
struct JournalBearingHooks : StickSlipHooksBase {
  const JournalBearingSystem &system;
  const JournalBearingParameters &p;
  const SlidingFriction &friction;
  const double radius;
  std::vector<Surface> &surfaces;
  JournalBearingReport &report;
  double wear_step;
  double next_wear;
  // State law (null otherwise): the splitting driver's slow system and its sample hook and restart flag.
  BearingStateLaw *law = nullptr;
  std::function<void(const JournalBearingSample &)> split_sample;
  std::function<bool()> split_refresh;
  const JournalBearingObserver &observer;
  const JournalBearingFrameObserver &frames;
  std::vector<double> frame_times;
  std::size_t next_frame = 0;
  const double round_off;
  static constexpr std::size_t speed_index = 1;

  JournalBearingHooks(const JournalBearingSystem &sys, std::vector<Surface> &surf, JournalBearingReport &rep, double step,
                      bool wearing, const JournalBearingObserver &obs, const JournalBearingFrameObserver &fr,
                      const JournalBearingRun &run)
      : system(sys), p(sys.parameters()), friction(sys.friction()), radius(p.bore.shaft_radius), surfaces(surf),
        report(rep), wear_step(step), next_wear(wearing ? step : HUGE_VAL), observer(obs), frames(fr),
        frame_times(run.frame_times), round_off(64.0 * std::numeric_limits<double>::epsilon() * run.t_end) {
    std::sort(frame_times.begin(), frame_times.end());
  }

  double coupling_torque(double t, const double *y) const {
    return p.coupling_stiffness * (p.drive_angle(t) - y[0]) + p.coupling_damping * (p.drive_speed(t) - y[1]);
  }
  std::size_t halves() const { return surfaces.size(); }
  double half_static_limit(const double *y, std::size_t h) const {
    if (law) return law->mu_stat[h] * surfaces[h].normal_force * radius;
    return friction.static_coefficient(y[3 + h]) * surfaces[h].normal_force * radius;
  }
  double half_slip_torque(const double *y, int dir, std::size_t h) const {
    if (law)
      return dir * (law->mu_kin[h] + friction.speed_coefficient() * std::abs(radius * y[1])) *
             surfaces[h].normal_force * radius;
    return dir * friction.kinetic(y[2], radius * y[1], y[3 + h]) * surfaces[h].normal_force * radius;
  }
  // Restart after a slow step at a root or at a sample since the last restart (both flags consumed).
  bool refresh(StickSlipState &) {
    if (!law) return false;
    const bool at_root = std::exchange(law->root_changed, false);
    const bool at_sample = split_refresh();
    return at_root || at_sample;
  }
  double static_limit(const double *y) const {
    double sum = 0.0;
    for (std::size_t h = 0; h < halves(); ++h) sum += half_static_limit(y, h);
    return sum;
  }
  double slip_torque(const double *y, int dir) const {
    double sum = 0.0;
    for (std::size_t h = 0; h < halves(); ++h) sum += half_slip_torque(y, dir, h);
    return sum;
  }

  void rhs(double t, const double *y, double *dy, ContactState state, int dir) const {
    if (state == ContactState::Stick) {
      dy[0] = dy[1] = dy[2] = 0.0;
      for (std::size_t h = 0; h < halves(); ++h) dy[3 + h] = friction.state_rate(y[3 + h], 0.0, false);
      return;
    }
    dy[0] = y[1];
    dy[1] = (coupling_torque(t, y) - slip_torque(y, dir)) / p.inertia;
    dy[2] = dir * radius * y[1];  // = R|w| before the re-stick root, smooth through it
    for (std::size_t h = 0; h < halves(); ++h) dy[3 + h] = friction.state_rate(y[3 + h], radius * y[1], true);
  }
  double breakaway_function(double t, const double *y) const {
    return std::abs(coupling_torque(t, y)) - static_limit(y);
  }
  int breakaway_direction(double t, const double *y) const { return sign_of(coupling_torque(t, y)); }

  // Stick: a constant, so both phases have two roots.
  void extra_roots(double, const double *y, ContactState state, double *g) const {
    g[0] = state == ContactState::Stick ? -1.0 : y[2] - (law ? law->next_wear : next_wear);
  }
  std::vector<int> extra_root_directions(ContactState state) const {
    return {state == ContactState::Stick ? 0 : +1};
  }
  bool on_extra_roots(StickSlipState &s, const std::vector<int> &found, std::string &message) {
    if (s.state != ContactState::Slip || found[1] == 0) return true;
    ++report.wear_updates;
    if (law) {
      law->root_changed = true;
      return law->advance_to(s.y[2], s.t, message);
    }
    next_wear = s.y[2] + wear_step;
    for (std::size_t h = 0; h < halves(); ++h) {
      apply_wear(system, surfaces[h], s.y[2]);
      if (!solve_contact(system, surfaces[h], message, static_cast<int>(h))) return false;
    }
    return true;
  }

  JournalBearingSample sample(const StickSlipState &st) const {
    const double t = st.t;
    const std::vector<double> &y = st.y;
    JournalBearingSample s;
    s.t = t;
    s.drive_angle = p.drive_angle(t);
    s.drive_speed = p.drive_speed(t);
    s.journal_speed = st.state == ContactState::Stick ? 0.0 : y[1];
    s.coupling_torque = coupling_torque(t, y.data());
    const bool stick = st.state == ContactState::Stick;
    s.halves = static_cast<int>(halves());
    const double limit = stick ? static_limit(y.data()) : 0.0;
    // In stick the contact carries the coupling torque, up to its static limit: the coupling torque
    // exceeds it only in the sample just before an immediate break-away at the start (a damper torque
    // c w_d above mu_s N R), where the contact carries its limit.
    s.friction_torque = stick ? std::clamp(s.coupling_torque, -limit, limit) : slip_torque(y.data(), st.direction);
    double loaded = 0.0, loaded_force = 0.0;
    for (std::size_t h = 0; h < halves(); ++h) {
      const Surface &surface = surfaces[h];
      JournalBearingHalfSample &half = s.half[h];
      // Stick is statically indeterminate between the halves: shared in proportion to their static limits.
      half.friction_torque = stick ? (limit > 0.0 ? s.friction_torque * half_static_limit(y.data(), h) / limit
                                                  : s.friction_torque / static_cast<double>(halves()))
                                   : half_slip_torque(y.data(), st.direction, h);
      half.normal_force = surface.normal_force;
      half.mu = half.friction_torque / (radius * surface.normal_force);
      half.roughness = y[3 + h];
      half.wear_volume =
          surface.committed_volume + system.wear_law().volume(surface.normal_force, y[2] - surface.distance_at_update);
      half.contact_half_angle = surface.contact.contact_half_angle;
      half.peak_pressure = surface.contact.peak_pressure;
      half.mean_pressure = surface.contact.mean_pressure;
      s.normal_force += half.normal_force;
      s.wear_volume += half.wear_volume;
      s.contact_half_angle = std::max(s.contact_half_angle, half.contact_half_angle);
      s.peak_pressure = std::max(s.peak_pressure, half.peak_pressure);
      loaded += surface.contact.active_nodes;
      loaded_force += surface.contact.mean_pressure * surface.contact.active_nodes;
    }
    s.mean_pressure = loaded > 0.0 ? loaded_force / loaded : 0.0;
    s.friction_force = s.friction_torque / radius;
    s.mu = s.friction_force / s.normal_force;
    s.mu_law = friction.kinetic(y[2], 0.0, y[3]);
    s.roughness = y[3];
    s.sliding_speed = radius * s.journal_speed;
    s.distance = y[2];
    s.state = st.state;
    return s;
  }

  void emit(const StickSlipState &st) {
    const JournalBearingSample s = sample(st);
    if (law)
      split_sample(s);  // the slow step, then the observer (through the splitting driver)
    else
      observer(s);
    const double t = st.t;
    while (frames && next_frame < frame_times.size() && t >= frame_times[next_frame] - round_off) {
      JournalBearingFrame f;
      f.t = t;
      for (std::size_t h = 0; h < halves(); ++h) {
        const Surface &surface = surfaces[h];
        std::vector<double> pressure = surface.contact.pressure, depth = surface.wear;
        const double pending = st.y[2] - surface.distance_at_update;
        for (std::size_t i = 0; i < depth.size(); ++i) depth[i] += system.wear_law().depth_rate(pressure[i]) * pending;
        if (law) (h == 0 ? f.mu : f.upper_mu) = law->node_mu(h);
        (h == 0 ? f.pressure : f.upper_pressure) = std::move(pressure);
        (h == 0 ? f.wear_depth : f.upper_wear_depth) = std::move(depth);
      }
      frames(f);
      ++next_frame;
    }
  }
};

// A failed split as the exception the state-law bearing has always thrown (a law lookup: std::out_of_range).
[[noreturn]] void throw_split_failure(const SplitReport &split) {
  if (split.status == SplitStatus::LawOutOfRange) throw std::out_of_range(split.message);
  if (split.status == SplitStatus::InvalidState) throw std::invalid_argument(split.message);
  throw std::runtime_error(split.message);
}
}  // namespace

JournalBearingReport simulate(const JournalBearingSystem &system, const JournalBearingRun &run,
                              const JournalBearingObserver &observer, const JournalBearingFrameObserver &frames) {
  run.validate();
  const auto &p = system.parameters();

  JournalBearingReport report;
  std::vector<Surface> surfaces(static_cast<std::size_t>(p.halves));
  for (std::size_t h = 0; h < surfaces.size(); ++h) {
    surfaces[h].wear.assign(system.contact().nodes(), 0.0);
    if (!solve_contact(system, surfaces[h], report.message, static_cast<int>(h))) {
      report.status = SolveStatus::IntegratorFailure;
      return report;
    }
  }
  report.stable_wear_step = system.wear_law().stable_slip_step(system.contact().contact_stiffness_per_area());
  const double wear_step = run.fixed_wear_step > 0.0 ? run.fixed_wear_step : run.wear_step_fraction * report.stable_wear_step;
  const bool wearing = p.wear_coefficient > 0.0 && std::isfinite(wear_step);

  CvodeIntegrator integrator(3 + surfaces.size(), run.integrator);
  StickSlipState start;
  start.y = {0.0, 0.0, 0.0};
  for (std::size_t h = 0; h < surfaces.size(); ++h) start.y.push_back(system.friction().initial_state());
  for (const auto &surface : surfaces) report.initial_pressure.push_back(surface.contact.pressure);
  const StickSlipGrid grid{run.t_end, run.output_interval, p.ramp_time, run.max_events};
  JournalBearingHooks hooks(system, surfaces, report, wear_step, wearing, observer, frames, run);
  // The fast stepper: the stick/slip loop from the start (break-away at once if the drive is past the limit).
  const auto fast = [&]() -> SolveReport {
    StickSlipLoop<JournalBearingHooks> loop(hooks, grid, integrator, std::move(start), report);
    const auto &s = loop.state();
    if (hooks.breakaway_function(s.t, s.y.data()) > 0.0) {
      loop.emit();
      loop.break_away();
    }
    loop.run();
    return report;
  };
  if (!system.friction().state_law()) {
    fast();
  } else {
    BearingStateLaw law(system, surfaces, report, run);
    hooks.law = &law;
    const auto split = split_run<JournalBearingSample>(
        law,
        [&](const auto &on_sample, const auto &refresh) {
          hooks.split_sample = on_sample;
          hooks.split_refresh = refresh;
          return fast();
        },
        [&](const JournalBearingSample &sample) {
          JournalBearingSample s = sample;
          law.fill(s);
          observer(s);
        });
    if (split.status != SplitStatus::Success && split.status != SplitStatus::FastFailure) throw_split_failure(split);
    report.range_use = law.use();
    report.state_law_static = system.friction().state_law()->held_static;
  }
  for (const auto &surface : surfaces) report.final_pressure.push_back(surface.contact.pressure);
  return report;
}

LineContactStress bore_contact_stress(const ConformalContact &contact, const std::vector<double> &pressure, double mu,
                                      const tribo::Material &bearing, const tribo::Material &shaft, int points) {
  std::vector<double> x(static_cast<std::size_t>(contact.nodes()));
  for (int i = 0; i < contact.nodes(); ++i) x[i] = contact.geometry().shaft_radius * contact.node_angle(i);
  return line_contact_stress(x, pressure, mu, bearing, shaft, points);
}

LineContactStress bore_hertz_stress(const BoreGeometry &bore, double load_per_length, double mu,
                                    const tribo::Material &bearing, const tribo::Material &shaft, int points) {
  const double r_eff = hertz_effective_radius(bore.shaft_radius, bore.shaft_radius + bore.clearance);
  const double b = hertz_half_width(load_per_length, r_eff, bore.contact_modulus());
  return hertz_line_contact_stress(hertz_peak_pressure(load_per_length, b), b, mu, bearing, shaft, 0.0, points);
}

std::vector<StartEndStress> bore_start_end_stress(const JournalBearingParameters &p,
                                                  const std::vector<JournalBearingSample> &samples,
                                                  double start_friction_force, const JournalBearingReport &rep,
                                                  const tribo::Material &bearing, const tribo::Material &shaft) {
  std::vector<StartEndStress> out;
  if (samples.empty() || rep.initial_pressure.size() != static_cast<std::size_t>(p.halves) ||
      rep.final_pressure.size() != rep.initial_pressure.size())
    return out;
  const ConformalContact contact(p.bore);
  const auto sign = [](double v) { return v < 0.0 ? -1.0 : 1.0; };
  const JournalBearingSample *last_slip = nullptr, *first_slip = nullptr;
  for (const auto &s : samples)
    if (s.state == ContactState::Slip) {
      if (!first_slip) first_slip = &s;
      last_slip = &s;
    }
  const JournalBearingSample &end = last_slip ? *last_slip : samples.back();
  const double dir_start = first_slip ? sign(first_slip->journal_speed) : 1.0;
  const double mu_start = dir_start * start_friction_force / samples.front().normal_force;
  for (int h = 0; h < p.halves; ++h) {
    StartEndStress s;
    s.mu_start = mu_start;
    const auto &p_start = rep.initial_pressure[h];
    s.solved_peak = *std::max_element(p_start.begin(), p_start.end());
    const auto hertz = bore_hertz_stress(p.bore, p.half_load(h) / p.bore.axial_width, mu_start, bearing, shaft);
    s.hertz_peak = hertz.peak_pressure;
    s.closed_form = std::abs(s.solved_peak / hertz.peak_pressure - 1.0) <= StartEndStress::hertz_tolerance;
    s.start = s.closed_form ? hertz : bore_contact_stress(contact, p_start, mu_start, bearing, shaft);
    s.mu_end = sign(end.journal_speed) * std::abs(end.half[h].mu != 0.0 ? end.half[h].mu : end.mu);
    // The symmetric set-up: the upper half's end state equals the lower's (computed once).
    if (h == 1 && rep.final_pressure[1] == rep.final_pressure[0] && end.half[1].mu == end.half[0].mu)
      s.end = out.front().end;
    else
      s.end = bore_contact_stress(contact, rep.final_pressure[h], s.mu_end, bearing, shaft);
    out.push_back(std::move(s));
  }
  return out;
}

WearHistory wear_in(const JournalBearingSystem &system, double ds, int steps) {
  require(std::isfinite(ds) && ds > 0.0, "ds must be positive");
  require(steps >= 0, "steps must be >= 0");
  WearHistory history;
  Surface surface;
  surface.wear.assign(system.contact().nodes(), 0.0);
  std::string message;
  double distance = 0.0;
  if (!solve_contact(system, surface, message)) {
    history.status = surface.contact.status;
    return history;
  }
  for (int k = 0; k < steps; ++k) {
    distance += ds;
    apply_wear(system, surface, distance);
    if (!solve_contact(system, surface, message)) {
      history.status = surface.contact.status;
      break;
    }
    history.pressure.push_back(surface.contact.pressure);
    history.wear.push_back(surface.wear);
  }
  return history;
}

JournalBearingSummary summarise(const std::vector<JournalBearingSample> &samples) {
  JournalBearingSummary summary;
  if (samples.empty()) return summary;
  for (const auto &s : samples)
    if (std::abs(s.friction_force) > std::abs(summary.peak_friction_force)) summary.peak_friction_force = s.friction_force;
  double peak_speed = 0.0;
  for (const auto &s : samples) peak_speed = std::max(peak_speed, std::abs(s.journal_speed));
  for (const auto &s : samples)
    if (std::abs(s.friction_force) >= (1.0 - 1e-6) * std::abs(summary.peak_friction_force)) {
      summary.peak_time = s.t;
      break;
    }
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (samples[i - 1].state == ContactState::Stick && samples[i].state == ContactState::Slip) {
      summary.breakaway_time = samples[i].t;
      break;
    }
  const auto &first = samples.front(), &last = samples.back();
  for (const auto &s : samples) {  // up to the first slip sample: the stick sample at the event is mu_s N
    summary.start_friction_force = std::max(summary.start_friction_force, std::abs(s.friction_force));
    if (s.state == ContactState::Slip) break;
  }
  summary.steady_mu = last.mu;
  summary.steady_friction_force = last.friction_force;
  summary.wear_volume = last.wear_volume;
  summary.initial_peak_pressure = first.peak_pressure;
  summary.final_peak_pressure = last.peak_pressure;
  summary.initial_half_angle = first.contact_half_angle;
  summary.final_half_angle = last.contact_half_angle;
  const double tol = JournalBearingSummary::steady_tolerance;
  const double force_band = tol * std::abs(last.friction_force);
  const double speed_band = std::max(tol * std::abs(last.journal_speed), 1e-3 * peak_speed);
  double steady_from = first.t;
  for (std::size_t i = samples.size(); i-- > 0;) {
    const auto &s = samples[i];
    if (std::abs(s.friction_force - last.friction_force) > force_band ||
        std::abs(s.journal_speed - last.journal_speed) > speed_band) {
      steady_from = i + 1 < samples.size() ? samples[i + 1].t : last.t;
      break;
    }
  }
  if (steady_from <= first.t + 0.9 * (last.t - first.t)) summary.steady_time = steady_from;
  return summary;
}

}  // namespace runin::continuum
