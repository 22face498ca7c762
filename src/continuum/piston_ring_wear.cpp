#include "continuum/piston_ring_wear.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "continuum/ring_state_law.h"

namespace runin::continuum {

RingWearSnapshot snapshot(const RingLinerWear &wear, const PistonRingSample &s) {
  RingWearSnapshot snap;
  snap.time = s.t;
  snap.ring_position = s.ring_position;
  snap.liner_wear = wear.liner_wear();
  snap.liner_pressure = wear.liner_pressure(s.ring_position, s.normal_load);
  snap.ring_wear = wear.ring_wear();
  snap.ring_pressure = wear.pressure(s.ring_position, s.normal_load).pressure;
  if (const auto *law = wear.state_law()) snap.ring_mu = law->node_mu(snap.ring_pressure);
  return snap;
}

namespace {
PistonRingSample interpolate(const PistonRingSample &a, const PistonRingSample &b, double t) {
  const double f = (t - a.t) / (b.t - a.t);
  auto mix = [f](double x, double y) { return x + f * (y - x); };
  PistonRingSample s = a;
  s.t = t;
  s.crank_angle = mix(a.crank_angle, b.crank_angle);
  s.piston_position = mix(a.piston_position, b.piston_position);
  s.piston_velocity = mix(a.piston_velocity, b.piston_velocity);
  s.ring_position = mix(a.ring_position, b.ring_position);
  s.speed = mix(a.speed, b.speed);
  s.distance = mix(a.distance, b.distance);
  s.friction_force = mix(a.friction_force, b.friction_force);
  s.land_force = mix(a.land_force, b.land_force);
  s.normal_load = mix(a.normal_load, b.normal_load);
  s.mu = s.normal_load > 0.0 ? std::abs(s.friction_force) / s.normal_load : 0.0;
  s.mu_law = mix(a.mu_law, b.mu_law);
  s.roughness = mix(a.roughness, b.roughness);
  s.state = a.speed == 0.0 && b.speed == 0.0 ? ContactState::Stick : ContactState::Slip;
  if (s.state == ContactState::Stick) s.speed = 0.0;
  return s;
}
}  // namespace

std::vector<std::vector<PistonRingSample>> common_grid(const std::vector<const std::vector<PistonRingSample> *> &rings) {
  if (rings.size() == 1) return {*rings.front()};
  std::vector<double> times;
  for (const auto *r : rings)
    for (const auto &s : *r) times.push_back(s.t);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  std::vector<std::vector<PistonRingSample>> out(rings.size());
  for (std::size_t k = 0; k < rings.size(); ++k) {
    const auto &own = *rings[k];
    std::size_t j = 0;
    for (double t : times) {
      while (j + 1 < own.size() && own[j + 1].t <= t) ++j;
      if (own[j].t == t || j + 1 >= own.size()) {
        out[k].push_back(own[j]);
        out[k].back().t = t;
        continue;
      }
      out[k].push_back(interpolate(own[j], own[j + 1], t));
    }
  }
  return out;
}

std::vector<PistonRingSample> pack_samples(const std::vector<std::vector<PistonRingSample>> &grid) {
  if (grid.size() == 1) return grid.front();
  std::vector<PistonRingSample> out = grid.front();
  for (std::size_t i = 0; i < out.size(); ++i) {
    auto &s = out[i];
    s.friction_force = s.land_force = s.normal_load = s.speed = 0.0;
    bool slip = false;
    for (const auto &ring : grid) {
      s.friction_force += ring[i].friction_force;
      s.land_force += ring[i].land_force;
      s.normal_load += ring[i].normal_load;
      s.speed += ring[i].speed / static_cast<double>(grid.size());
      slip = slip || ring[i].state == ContactState::Slip;
    }
    s.state = slip ? ContactState::Slip : ContactState::Stick;
    s.mu = s.normal_load > 0.0 ? std::abs(s.friction_force) / s.normal_load : 0.0;
  }
  return out;
}

namespace {
// Ring k slides from the previous grid sample to sample i.
void slide_ring(RingLinerWear &w, std::size_t k, const PistonRingSample &prev, const PistonRingSample &s) {
  bool ok = true;
  try {
    ok = w.slide(prev.ring_position, s.ring_position, prev.normal_load, s.normal_load);
  } catch (const std::out_of_range &e) {
    throw RingWearError(RingWearError::Kind::LeftTheLiner, k, s.t, e.what());
  }
  if (!ok) throw RingWearError(RingWearError::Kind::WornThrough, k, s.t, w.message());
}
}  // namespace

std::vector<RingWearPass> ring_wear_pass(std::vector<RingLinerWear> &wear,
                                         const std::vector<std::vector<PistonRingSample>> &rings,
                                         const std::vector<double> &frame_times) {
  std::vector<RingWearPass> passes(rings.size());
  std::vector<double> times = frame_times;
  std::sort(times.begin(), times.end());
  std::size_t next_frame = 0;
  const auto &grid = rings.front();
  for (std::size_t i = 0; i < grid.size(); ++i) {
    for (std::size_t k = 0; k < rings.size(); ++k) {
      const auto &s = rings[k][i];
      auto &w = wear[k];
      if (i > 0) slide_ring(w, k, rings[k][i - 1], s);
      const auto contact = w.pressure(s.ring_position, s.normal_load);
      if (i == 0) passes[k].initial_peak = contact.peak, passes[k].initial_pressure = contact.pressure;
      if (i + 1 == grid.size()) passes[k].final_pressure = contact.pressure;
      passes[k].rows.push_back({w.ring_volume(), w.liner_volume(), contact.width, contact.peak, contact.mean});
    }
    const double t = grid[i].t;
    while (next_frame < times.size() && t >= times[next_frame] - 1e-12 * std::max(1.0, t)) {
      for (std::size_t k = 0; k < rings.size(); ++k) passes[k].snapshots.push_back(snapshot(wear[k], rings[k][i]));
      ++next_frame;
    }
  }
  return passes;
}

double pressure_settling_time(const PistonRingParameters &p, const std::vector<PistonRingSample> &samples,
                              const std::vector<RingWearRow> &rows) {
  constexpr double kPi = 3.14159265358979323846;
  if (p.motion != PistonMotion::Crank) return -1.0;
  const double period = (p.gas.empty() ? 2.0 * kPi : p.gas.cycle) / p.crank_speed;
  const long cycles = static_cast<long>(std::floor(samples.back().t / period + 1e-9));
  if (cycles < 3) return -1.0;
  std::vector<double> peak(cycles, 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const long cycle = static_cast<long>(std::floor(samples[i].t / period));
    if (cycle < cycles) peak[cycle] = std::max(peak[cycle], rows[i].peak);
  }
  long first = cycles - 1;
  while (first > 0 && std::abs(peak[first - 1] - peak.back()) <= 0.01 * peak.back()) --first;
  return first < cycles - 1 ? first * period : -1.0;
}

StartEndStress ring_face_start_end_stress(const RingLinerWear &wear, const std::vector<PistonRingSample> &samples,
                                          double start_friction_force, const std::vector<double> &initial_pressure,
                                          const std::vector<double> &final_pressure, const tribo::Material &liner,
                                          const tribo::Material &ring) {
  const auto sign = [](double v) { return v < 0.0 ? -1.0 : 1.0; };
  const PistonRingSample *first_slip = nullptr, *last_slip = nullptr;
  for (const auto &s : samples)
    if (s.state == ContactState::Slip) {
      if (!first_slip) first_slip = &s;
      last_slip = &s;
    }
  const auto &first = samples.front();
  const PistonRingSample &end = last_slip ? *last_slip : samples.back();
  StartEndStress out;
  out.mu_start = (first_slip ? sign(first_slip->speed) : 1.0) * start_friction_force / first.normal_load;
  out.mu_end = sign(end.speed) * end.mu;
  out.solved_peak = *std::max_element(initial_pressure.begin(), initial_pressure.end());
  const auto hertz = ring_face_hertz_stress(wear.settings(), first.normal_load, out.mu_start, liner, ring);
  if (hertz) out.hertz_peak = hertz->peak_pressure;
  out.closed_form =
      hertz && std::abs(out.solved_peak / hertz->peak_pressure - 1.0) <= StartEndStress::hertz_tolerance;
  out.start = out.closed_form ? *hertz : ring_face_stress(wear, initial_pressure, out.mu_start, liner, ring);
  out.end = ring_face_stress(wear, final_pressure, out.mu_end, liner, ring);
  return out;
}

RingStateLawRun simulate_state_law(const PistonRingSystem &system, const PistonRingRun &run, RingLinerWear &wear,
                                   StateLawFriction &held, double groove_position,
                                   const std::vector<double> &frame_times) {
  RingStateLawRun out;
  RingStateLaw ring(wear, held, system, groove_position);
  std::vector<double> times = frame_times;
  std::sort(times.begin(), times.end());
  std::size_t next_frame = 0;
  auto &pass = out.pass;
  const auto observer = [&](const PistonRingSample &s) {
    const auto state = ring.state(s);
    RingWearRow row{state.ring_volume, state.liner_volume, state.contact.width, state.contact.peak, state.contact.mean,
                    state.mu_eff, state.h_mean, state.h_max, state.film_coverage};
    if (pass.rows.empty()) pass.initial_peak = state.contact.peak, pass.initial_pressure = state.contact.pressure;
    pass.final_pressure = state.contact.pressure;
    pass.rows.push_back(row);
    for (; next_frame < times.size() && s.t >= times[next_frame] - 1e-12 * std::max(1.0, s.t); ++next_frame)
      pass.snapshots.push_back(snapshot(wear, s));
    out.samples.push_back(s);
  };
  // the fast stepper: the ring's dynamics, its samples moved to the groove's place on the piston
  const auto fast = [&](const std::function<void(const PistonRingSample &)> &on_sample,
                        const std::function<bool()> &refresh) {
    return simulate(system, run, [&](const PistonRingSample &sample) {
      PistonRingSample s = sample;
      s.ring_position += groove_position;
      on_sample(s);
    }, refresh);
  };
  out.report = split_run<PistonRingSample>(ring, fast, observer);
  out.mu_static = held.held_static;
  return out;
}

}  // namespace runin::continuum
