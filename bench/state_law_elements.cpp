// Speed: the thesis cases with per-node state laws (friction.model = "state_law", the shipped
// inputs/state_law_steel.json, AISI 1020 on AISI 1020) next to the same set-up with the element's ordinary
// friction. Integration only: the contact grids, the ODE and the operator-splitting loop are timed; the case
// file and the law JSON are read once, before any timing; nothing is written.
//   build-bench/bench/state_law_elements            (taskset -c 1 ...: one core; doc/benchmarks.md)
// Wall time: Google Benchmark, median of 5 repetitions (each at least 0.1 s of back-to-back runs), one core.
//
// Set-ups (doc/benchmarks.md, "Per-node state law: thesis cases", says why each was chosen):
//  pin-on-disk    inputs/pin_on_disk_state_law.toml as read by the CLI's case reader: flat AISI 1020 pin,
//                 r_flat = 1.5 mm, 32 rings, 20 N (2.83 MPa, on the law's grid), speed drive 0.1 m/s, 1 s,
//                 output (= splitting) interval 2 ms. The thesis's pin (5 mm sphere, 0.981 N, torque ramp
//                 tuned to mu0 = 0.95) has a Hertz peak of ~450 MPa in steel, 22x the law's top pressure.
//                 Baseline: the same parameters and run with the thesis law mu0 + alpha V (0.95, 0.68).
//  journal bearing the wp_journal_bearing thesis set-up (two halves, R = 12.5 mm, c = 25 um, L = 25 mm,
//                 arc +-0.3 rad on 256 nodes, W = 9.81 N per half, 2 s, 1 ms output), steel as in the thesis;
//                 the conformal contact's edge nodes fall below the law's 0.2 MPa: friction.out_of_range =
//                 clamp (as inputs/journal_bearing_state_law.toml), counted. Baseline: static_kinetic(0.95,
//                 0.76) with the thesis's Archard wear (k = 1e-3, H = 1.2 GPa), wear re-solves included.
//  tribometer     inputs/pin_on_disk_tribometer.toml: flat pin, 20 N, 0.5 m/s on a 20 mm track, 1 km (2000 s)
//                 with adaptive wear steps (tolerance 1e-3), against the same case at the fixed 2 ms output
//                 interval over 1 m and 10 m (2 s, 20 s): the fixed-interval cost grows with the distance.
//  piston ring    inputs/piston_ring_state_law.toml as read by the CLI's case reader: the thesis pack (rings
//                 A and B, grooves 81.5 / 80.5 mm, tensions 0.2 / 0.15 MPa, 2 s ramp, BDF 1e-8 / 1e-12) in
//                 steel, half-plane face contact (128 ring cells, 512 liner cells), clamp, output 2 ms.
//                 Baselines: the same pack with static_kinetic(0.95, 0.665): dynamics only (what
//                 wp_piston_ring's thesis/ring_pack_k_geometry times), and dynamics + the Archard wear pass of
//                 the CLI's ordinary path (k = 1e-4, H = 2 GPa of inputs/piston_ring.toml) on the same grid.
//
// The pin-on-disk and piston-ring splitting loops live in the CLI (cmd_pin_on_disk.cpp run_state_law_case,
// cmd_piston_ring.cpp run_pack_state_law, file-local); the loops below make the same library calls in the same
// order (NodeStateLaw / RingLinerWear advance, mu_effective, CVODE restart via `refresh`) without the CSV rows
// and VTK frames. The journal bearing's loop is the library's (continuum::simulate).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli/case_file.h"
#include "cli/piston_ring_case.h"
#include "continuum/axisymmetric_contact.h"
#include "continuum/journal_bearing.h"
#include "continuum/node_state_law.h"
#include "continuum/pin_on_disk.h"
#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#include "wp_reporter.h"
#include "thesis_setups.h"

using namespace runin::continuum;
namespace coupling = runin::coupling;

namespace {

const std::string kSource = RUNIN_SOURCE_DIR;

struct Outcome {
  long steps = 0, wear_updates = 0;
  double mu_eff = 0.0, h_max = 0.0;  // final, state law only
  coupling::RangeUse use;
};

void add(coupling::RangeUse &to, const coupling::RangeUse &u) {
  to.lookups += u.lookups;
  to.below_pressure += u.below_pressure;
  to.above_pressure += u.above_pressure;
  to.beyond_depth += u.beyond_depth;
}

void check(const SolveReport &report, const char *what) {
  if (!report.ok()) throw std::runtime_error(std::string(what) + ": " + to_string(report.status) + ": " + report.message);
}

void set_counters(benchmark::State &state, const Outcome &o) {
  state.counters["steps"] = static_cast<double>(o.steps);
  state.counters["wear_updates"] = static_cast<double>(o.wear_updates);
  state.counters["mu_eff"] = o.mu_eff;
  state.counters["h_max_nm"] = 1e9 * o.h_max;
  state.counters["lookups"] = static_cast<double>(o.use.lookups);
  state.counters["clamped_low"] = static_cast<double>(o.use.below_pressure);
  state.counters["clamped_high"] = static_cast<double>(o.use.above_pressure);
}

// ---------------------------------------------------------------- pin-on-disk (flat pin, speed drive)

// cmd_pin_on_disk.cpp run_state_law_case, flat tip: one node-state advance per output interval at the uniform
// nominal pressure, the disk worn by the counterface rate, mu_eff recomputed, CVODE restarted.
Outcome pin_state_law(const runin::cli::PinOnDiskCase &c) {
  auto *law = c.friction->state_law();
  const auto &k = *c.contact;
  const AxisymmetricContact grid(k.flat_radius, k.rings, k.effective_modulus());
  const int n = grid.rings();
  std::vector<double> area(n);
  double flat_area = 0.0;
  for (int i = 0; i < n; ++i) flat_area += area[i] = grid.ring_area(i);
  const std::vector<double> pressure(n, c.parameters.normal_load / flat_area);
  NodeStateLaw nodes(law->law, law->policy, n);
  DiskTrackWear disk(runin::tribo::ArchardWear(0.0, 1.0), c.parameters.track_radius);
  law->held_static = law->mu_static ? *law->mu_static : nodes.peak_mu(pressure, area);
  law->held_kinetic = nodes.mu_effective(pressure, area);
  const PinOnDiskSystem system(c.parameters, *c.friction);
  double slid = 0.0;
  bool changed = false;
  Outcome o;
  std::vector<PinOnDiskSample> samples;
  const auto report = simulate(
      system, c.run,
      [&](const PinOnDiskSample &s) {
        samples.push_back(s);
        const double ds = s.distance - slid;
        if (ds <= 0.0) return;
        const auto inc = nodes.advance(pressure, ds);
        double volume = 0.0;
        for (int i = 0; i < n; ++i) volume += inc.counterface[i] * area[i];
        disk.slide_volume(volume, ds, 2.0 * k.flat_radius);
        ++o.wear_updates;
        slid = s.distance;
        law->held_kinetic = nodes.mu_effective(pressure, area);
        changed = true;
      },
      [&] { return std::exchange(changed, false); });
  check(report, "pin-on-disk (state law)");
  o.steps = report.steps;
  o.mu_eff = law->held_kinetic;
  o.h_max = *std::max_element(nodes.state().begin(), nodes.state().end());
  o.use = nodes.use();
  return o;
}

Outcome pin_baseline(const runin::cli::PinOnDiskCase &c, const SlidingFriction &friction) {
  const PinOnDiskSystem system(c.parameters, friction);
  std::vector<PinOnDiskSample> samples;
  const auto report = simulate(system, c.run, [&](const PinOnDiskSample &s) { samples.push_back(s); });
  check(report, "pin-on-disk (baseline)");
  Outcome o;
  o.steps = report.steps;
  return o;
}

// ---------------------------------------------------------------- tribometer (1 km, adaptive wear steps)

// inputs/pin_on_disk_tribometer.toml as cmd_pin_on_disk.cpp runs it (run_state_law_case: PinStateLaw on the case's
// flat pin, continuum::run_pin_split, the pin's state read at every sample), with `steps` and `t_end` set here.
Outcome pin_tribometer(const runin::cli::PinOnDiskCase &c, const WearSteps &steps, double t_end) {
  auto *law = c.friction->state_law();
  const auto &k = *c.contact;
  PinStateLawSettings settings;
  settings.flat_radius = k.flat_radius;
  settings.tip.rings = k.rings;
  settings.tip.effective_modulus = k.effective_modulus();
  settings.load = c.parameters.normal_load;
  settings.track_radius = c.parameters.track_radius;
  PinStateLaw pin(settings, *law);
  const PinOnDiskSystem system(c.parameters, *c.friction);
  PinOnDiskRun run = c.run;
  run.t_end = t_end;
  std::vector<PinOnDiskSample> samples;
  double volume = 0.0;
  const auto report = run_pin_split(system, run, pin, steps, [&](const PinOnDiskSample &s) {
    samples.push_back(s);
    volume = pin.state().wear_volume;
  });
  if (!report.ok())
    throw std::runtime_error(std::string("tribometer: ") + to_string(report.status) + ": " + report.message);
  Outcome o;
  o.steps = report.fast.steps;
  o.wear_updates = report.slow_steps;
  o.mu_eff = law->held_kinetic;
  o.h_max = *std::max_element(pin.nodes().state().begin(), pin.nodes().state().end());
  o.use = pin.nodes().use();
  benchmark::DoNotOptimize(volume);
  return o;
}

// ---------------------------------------------------------------- journal bearing (wp_journal_bearing thesis)

JournalBearingParameters bearing_thesis() { return runin::bench::journal_bearing_thesis(256, 2); }

JournalBearingRun bearing_run() {
  JournalBearingRun run;  // CVODE defaults (BDF, rtol 1e-8, atol 1e-12), as the CLI without [solver]
  run.t_end = 2.0;
  run.output_interval = 1e-3;
  return run;
}

Outcome bearing(const JournalBearingParameters &p, const SlidingFriction &friction) {
  const JournalBearingSystem system(p, friction);
  std::vector<JournalBearingSample> samples;
  const auto report = simulate(system, bearing_run(), [&](const JournalBearingSample &s) { samples.push_back(s); });
  check(report, "journal bearing");
  Outcome o;
  o.steps = report.steps;
  o.wear_updates = report.wear_updates;
  if (const auto *held = friction.state_law()) {
    o.mu_eff = held->held_kinetic;
    if (report.range_use) o.use = *report.range_use;
  }
  return o;
}

// ---------------------------------------------------------------- piston ring pack (state-law input)

std::vector<RingLinerWear> pack_wear(const runin::cli::PistonRingCase &c, const runin::tribo::ArchardWear &archard,
                                     bool state_law) {
  std::vector<RingLinerWear> wear;
  wear.reserve(c.rings.size());
  for (const auto &ring : c.rings) wear.emplace_back(ring.wear_settings, archard);
  for (std::size_t k = 1; k < wear.size(); ++k) wear[k].share_liner(wear.front());
  if (state_law)
    for (auto &w : wear) w.attach_state_law(c.friction->state_law()->law, c.friction->state_law()->policy);
  return wear;
}

// cmd_piston_ring.cpp run_pack_state_law: per ring, CVODE over one output interval with the ring's mu_eff held,
// the face slid over the liner along it (law dh_i on the face cells, counterface rate on the liner), mu_eff at
// the new pressures, CVODE restarted. Rings one after the other on the shared liner.
Outcome ring_pack_state_law(const runin::cli::PistonRingCase &c) {
  const auto *law = c.friction->state_law();
  auto wear = pack_wear(c, *c.archard, true);
  Outcome o;
  for (std::size_t k = 0; k < c.rings.size(); ++k) {
    const auto &ring = c.rings[k];
    auto &w = wear[k];
    auto held = std::make_shared<StateLawFriction>(*law);
    const PistonRingSystem system(ring.parameters, SlidingFriction::state_law(held, c.friction->speed_coefficient()));
    const double x0 = system.piston_position(0.0) + ring.position, w0 = system.normal_load(0.0);
    held->held_static = law->mu_static ? *law->mu_static : w.peak_mu(x0, w0);
    held->held_kinetic = w.mu_effective(x0, w0);
    bool changed = false;
    bool have_prev = false;
    PistonRingSample prev;
    std::vector<PistonRingSample> samples;
    const auto report = simulate(
        system, c.run,
        [&](const PistonRingSample &sample) {
          PistonRingSample s = sample;
          s.ring_position += ring.position;
          if (have_prev && s.distance > prev.distance) {
            if (!w.slide(prev.ring_position, s.ring_position, prev.normal_load, s.normal_load))
              throw std::runtime_error(std::string("piston ring (state law): ") + w.message());
            held->held_kinetic = w.mu_effective(s.ring_position, s.normal_load);
            changed = true;
          }
          // The CLI solves the face pressure at every sample for its wear row (contact width, peak, h_mean):
          // part of the run, kept here.
          benchmark::DoNotOptimize(w.pressure(s.ring_position, s.normal_load));
          prev = s;
          have_prev = true;
          samples.push_back(s);
        },
        [&] { return std::exchange(changed, false); });
    check(report, "piston ring (state law)");
    o.steps += report.steps;
    o.wear_updates += w.updates();
    o.mu_eff = held->held_kinetic;  // the last ring's
    const auto &h = w.state_law()->state();
    o.h_max = std::max(o.h_max, *std::max_element(h.begin(), h.end()));
    add(o.use, w.state_law()->use());
  }
  return o;
}

// Ordinary friction: each ring's dynamics (cmd_piston_ring.cpp run_dynamics); with `archard`, then the wear
// pass of the CLI's ordinary path over the output grid (run_wear: slide between samples, face pressure at each).
Outcome ring_pack_baseline(const runin::cli::PistonRingCase &c, const SlidingFriction &friction,
                           const runin::tribo::ArchardWear *archard) {
  Outcome o;
  std::vector<std::vector<PistonRingSample>> rings;
  for (const auto &ring : c.rings) {
    const PistonRingSystem system(ring.parameters, friction);
    std::vector<PistonRingSample> samples;
    const auto report = simulate(system, c.run, [&](const PistonRingSample &s) {
      samples.push_back(s);
      samples.back().ring_position += ring.position;
    });
    check(report, "piston ring (baseline)");
    o.steps += report.steps;
    rings.push_back(std::move(samples));
  }
  if (!archard) return o;
  auto wear = pack_wear(c, *archard, false);
  std::size_t n = rings.front().size();
  for (const auto &r : rings) n = std::min(n, r.size());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < rings.size(); ++k) {
      const auto &s = rings[k][i];
      if (i > 0) {
        const auto &p = rings[k][i - 1];
        if (!wear[k].slide(p.ring_position, s.ring_position, p.normal_load, s.normal_load))
          throw std::runtime_error(std::string("piston ring (baseline wear): ") + wear[k].message());
      }
      benchmark::DoNotOptimize(wear[k].pressure(s.ring_position, s.normal_load));
    }
  for (const auto &w : wear) o.wear_updates += w.updates();
  return o;
}

struct Case {
  std::string name, law_name, base_name;
  double target_ms;
};

}  // namespace

int main(int argc, char **argv) {
  runin::bench::initialize(argc, argv, "");

  // Read once, outside every timed region (the CLI's case readers: the same set-up as `runin <element> FILE`).
  static const auto pod = runin::cli::read_pin_on_disk_case(kSource + "/inputs/pin_on_disk_state_law.toml", {});
  static const auto pr = runin::cli::read_piston_ring_case(kSource + "/inputs/piston_ring_state_law.toml", {});
  if (!pod.contact || !pod.contact->flat || !pod.friction->state_law() || !pr.friction->state_law()) {
    std::fprintf(stderr, "state_law_elements: the *_state_law.toml inputs changed (flat pin, state law expected)\n");
    return 1;
  }
  static const auto steel_law = pod.friction->state_law()->law;  // inputs/state_law_steel.json
  static const auto tribometer = runin::cli::read_pin_on_disk_case(kSource + "/inputs/pin_on_disk_tribometer.toml", {});
  if (!tribometer.wear_steps.adaptive || tribometer.run.t_end != 2000.0) {
    std::fprintf(stderr,
                 "state_law_elements: inputs/pin_on_disk_tribometer.toml changed (2000 s, adaptive expected)\n");
    return 1;
  }

  static const SlidingFriction pod_thesis = SlidingFriction::constant(0.95, 0.68);
  static const auto jb = bearing_thesis();
  static const SlidingFriction jb_thesis = SlidingFriction::static_kinetic(0.95, 0.76);
  static auto jb_law = [] {
    auto held = std::make_shared<StateLawFriction>();
    held->law = steel_law;
    held->policy = coupling::OutOfRange::Clamp;
    held->path = "inputs/state_law_steel.json";
    return held;
  }();
  static const auto jb_law_parameters = [] {
    auto p = jb;
    p.wear_coefficient = 0.0;  // the law's wear_rate wears the bore (as the CLI's journal_bearing_case.cpp)
    p.hardness = 1.0;
    return p;
  }();
  static const SlidingFriction jb_state_law = SlidingFriction::state_law(jb_law, 0.0);
  static const SlidingFriction pr_thesis = SlidingFriction::static_kinetic(0.95, 0.665);
  static const runin::tribo::ArchardWear pr_archard(1e-4, 2e9);  // inputs/piston_ring.toml [wear]

  auto reg = [](const char *name, auto run) {
    runin::bench::timed(benchmark::RegisterBenchmark(name, [run](benchmark::State &state) {
      Outcome o;
      for (auto _ : state) o = run();
      set_counters(state, o);
    }));
  };
  reg("pin_on_disk/state_law", [] { return pin_state_law(pod); });
  reg("pin_on_disk/baseline_mu0_alpha", [] { return pin_baseline(pod, pod_thesis); });
  // 1 km with adaptive wear steps against the fixed output interval (2 ms) over 1 m and 10 m of the same case
  reg("pin_on_disk_tribometer/adaptive_1km", [] { return pin_tribometer(tribometer, tribometer.wear_steps, 2000.0); });
  reg("pin_on_disk_tribometer/fixed_1m", [] { return pin_tribometer(tribometer, WearSteps{}, 2.0); });
  reg("pin_on_disk_tribometer/fixed_10m", [] { return pin_tribometer(tribometer, WearSteps{}, 20.0); });
  reg("journal_bearing/state_law", [] { return bearing(jb_law_parameters, jb_state_law); });
  reg("journal_bearing/baseline_static_kinetic_archard", [] { return bearing(jb, jb_thesis); });
  reg("piston_ring_pack/state_law", [] { return ring_pack_state_law(pr); });
  reg("piston_ring_pack/baseline_dynamics", [] { return ring_pack_baseline(pr, pr_thesis, nullptr); });
  reg("piston_ring_pack/baseline_dynamics_archard_wear", [] { return ring_pack_baseline(pr, pr_thesis, &pr_archard); });

  runin::bench::MedianReporter reporter;
  runin::bench::run_benchmarks(reporter);

  const Case cases[] = {
      {"pin-on-disk", "pin_on_disk/state_law", "pin_on_disk/baseline_mu0_alpha", 20.0},
      {"journal bearing (2 halves)", "journal_bearing/state_law", "journal_bearing/baseline_static_kinetic_archard",
       100.0},
      {"piston ring pack (A + B)", "piston_ring_pack/state_law", "piston_ring_pack/baseline_dynamics_archard_wear",
       100.0},
      {"piston ring pack, dynamics-only baseline", "piston_ring_pack/state_law", "piston_ring_pack/baseline_dynamics",
       100.0},
  };
  std::printf("\n%-42s %12s %12s %7s %8s %s\n", "case", "state law ms", "baseline ms", "ratio", "target", "");
  for (const Case &c : cases) {
    const auto *law = reporter.find(c.law_name);
    const auto *base = reporter.find(c.base_name);
    if (!law || !base) continue;
    const double ms = 1e3 * law->seconds, base_ms = 1e3 * base->seconds;
    std::printf("%-42s %12.3f %12.3f %7.2f %6.0f ms %s\n", c.name.c_str(), ms, base_ms, ms / base_ms, c.target_ms,
                ms < c.target_ms ? "met" : "NOT met");
  }
  const auto *adaptive = reporter.find("pin_on_disk_tribometer/adaptive_1km");
  const auto *fixed1 = reporter.find("pin_on_disk_tribometer/fixed_1m");
  const auto *fixed10 = reporter.find("pin_on_disk_tribometer/fixed_10m");
  if (adaptive && fixed1 && fixed10)
    std::printf("\ntribometer, 1 km with adaptive wear steps: %.3f ms (%ld slow steps; target < 10 s %s); fixed 2 ms "
                "interval: 1 m %.3f ms (%ld steps), 10 m %.3f ms (%ld steps), 1 km at that rate ~%.3g s\n",
                1e3 * adaptive->seconds, std::lround(adaptive->counter("wear_updates")),
                adaptive->seconds < 10.0 ? "met" : "NOT met", 1e3 * fixed1->seconds,
                std::lround(fixed1->counter("wear_updates")), 1e3 * fixed10->seconds,
                std::lround(fixed10->counter("wear_updates")), 100.0 * fixed10->seconds);
  for (const char *name : {"pin_on_disk/state_law", "journal_bearing/state_law", "piston_ring_pack/state_law"})
    if (const auto *m = reporter.find(name))
      std::printf("%-28s final mu_eff %.5f, h_max %.3g nm, %ld node-law lookups (%ld clamped below p_min, %ld above "
                  "p_max), %ld wear updates, %ld CVODE steps\n",
                  name, m->counter("mu_eff"), m->counter("h_max_nm"), std::lround(m->counter("lookups")),
                  std::lround(m->counter("clamped_low")), std::lround(m->counter("clamped_high")),
                  std::lround(m->counter("wear_updates")), std::lround(m->counter("steps")));
  return 0;
}
