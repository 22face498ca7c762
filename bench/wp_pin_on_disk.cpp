// Work-precision of the pin-on-disk thesis case (2 s: torque ramp to eq. 4.11's T_app,
// break-away at 1.866 s, slip to 2 s) and timing of the long pin-wear run.
//   build-bench/bench/wp_pin_on_disk [OUT_DIR]   -> OUT_DIR/wp_pin_on_disk.csv, .png, wear_timing.csv  (OUT_DIR default: build-bench/bench/out)
// Error: max relative error of speed and sliding distance over the 10 ms output grid after
// break-away (1.87 s .. 2 s, the first point 3.6 ms = 2.4 inertial time constants into the
// slip transient) against the closed form of the linear ODE m dV/dt = T(t)/r - mu0 W - alpha W V
// (ramp T linear in t).
// Wall time: timed by Google Benchmark (median of 5 repetitions, wall time; slow runs 3), one core.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "continuum/axisymmetric_contact.h"
#include "continuum/pin_on_disk.h"
#include "wp_reporter.h"

using namespace runin::continuum;

namespace {
constexpr double kMass = 0.001, kRadius = 0.102, kLoad = 0.981, kMu0 = 0.95, kAlpha = 0.68, kRamp = 2.0;
constexpr double kEnd = 2.0;

PinOnDiskParameters thesis() {
  PinOnDiskParameters p;
  p.mass = kMass;
  p.track_radius = kRadius;
  p.normal_load = kLoad;
  p.ramp_time = kRamp;
  p.applied_torque = thesis_torque_for_speed(p, kMu0, kAlpha, 0.0, 0.1, 2.0);
  return p;
}

struct Exact {
  double speed, distance;
};
// m dV/dt = k t - mu0 W - c m V (c = alpha W / m, k = T_app / (r t_ramp)), V(t_b) = 0.
Exact exact(const PinOnDiskParameters &p, double t) {
  const double c = kAlpha * kLoad / kMass, k = p.applied_torque / (kRadius * kRamp * kMass);
  const double tb = kMu0 * kLoad * kRadius * kRamp / p.applied_torque;
  const double b = k / c, a = (-kMu0 * kLoad / kMass - b) / c;
  const double cc = -(a + b * tb);  // V = a + b t + cc exp(-c (t - tb))
  const double speed = a + b * t + cc * std::exp(-c * (t - tb));
  const double distance = a * (t - tb) + 0.5 * b * (t * t - tb * tb) + cc * (1.0 - std::exp(-c * (t - tb))) / c;
  return {speed, distance};
}

constexpr double kGrid = 0.01;
double breakaway(const PinOnDiskParameters &p) { return kMu0 * kLoad * kRadius * kRamp / p.applied_torque; }

double error_of(const Exact &got, const Exact &ref) {
  return std::max(std::abs(got.speed / ref.speed - 1.0), std::abs(got.distance / ref.distance - 1.0));
}

// Naive baseline: fixed-step explicit Euler, stick tested at the start of each step.
double euler_error(const PinOnDiskParameters &p, double dt) {
  const PinOnDiskSystem system(p, SlidingFriction::constant(kMu0, kAlpha));
  const long steps = std::lround(kEnd / dt), every = std::lround(kGrid / dt);
  const double tb = breakaway(p);
  double y[3] = {0.0, 0.0, 0.0}, dy[3], worst = 0.0;
  for (long n = 0; n < steps; ++n) {
    const double t = n * dt;
    const bool slip = y[0] > 0.0 || system.breakaway_function(t) > 0.0;
    system.rhs(t, y, dy, slip ? ContactState::Slip : ContactState::Stick, 1);
    for (int i = 0; i < 3; ++i) y[i] += dt * dy[i];
    if (y[0] < 0.0) y[0] = 0.0;
    const double t_next = (n + 1) * dt;
    if ((n + 1) % every == 0 && t_next > tb) worst = std::max(worst, error_of({kRadius * y[0], y[1]}, exact(p, t_next)));
  }
  return worst;
}
}  // namespace

int main(int argc, char **argv) {
  const std::string out = runin::bench::initialize(argc, argv, ".");
  static const auto p = thesis();
  const Exact ref = exact(p, kEnd);
  std::printf("thesis case: T_app = %.6g N m, break-away %.8g s, exact V(2 s) = %.10g m/s, s(2 s) = %.10g m\n",
              p.applied_torque, breakaway(p), ref.speed, ref.distance);

  std::vector<runin::bench::WorkPrecisionRow> rows;
  for (const auto method : {CvodeIntegrator::Method::Bdf, CvodeIntegrator::Method::Adams}) {
    const char *name = method == CvodeIntegrator::Method::Bdf ? "cvode_bdf" : "cvode_adams";
    for (const double rtol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
      PinOnDiskRun run;
      run.t_end = kEnd;
      run.output_interval = kGrid;
      run.integrator.method = method;
      run.integrator.rtol = rtol;
      run.integrator.atol = rtol * 1e-3;  // speed and distance are O(0.1) m/s, O(0.01) m
      rows.push_back({runin::bench::label(name, rtol), name, rtol});
      runin::bench::timed(benchmark::RegisterBenchmark(rows.back().name.c_str(), [run](benchmark::State &state) {
        const PinOnDiskSystem system(p, SlidingFriction::constant(kMu0, kAlpha));
        const double tb = breakaway(p);
        double error = 0.0;
        long steps = 0;
        for (auto _ : state) {
          error = 0.0;  // a closed form at 13 output points: negligible next to the solve
          const auto report = simulate(system, run, [&](const PinOnDiskSample &s) {
            const double on_grid = std::round(s.t / kGrid) * kGrid;
            if (s.t > tb && std::abs(s.t - on_grid) < 1e-12)
              error = std::max(error, error_of({s.speed, s.distance}, exact(p, s.t)));
          });
          steps = report.steps;
        }
        state.counters["rel_error"] = error;
        state.counters["steps"] = static_cast<double>(steps);
      }));
    }
  }
  for (const double dt : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    rows.push_back({runin::bench::label("euler_fixed", dt), "euler_fixed", dt});
    auto *b = benchmark::RegisterBenchmark(rows.back().name.c_str(), [dt](benchmark::State &state) {
      double error = 0.0;
      for (auto _ : state) benchmark::DoNotOptimize(error = euler_error(p, dt));
      state.counters["rel_error"] = error;
      state.counters["steps"] = static_cast<double>(std::lround(kEnd / dt));
    });
    if (dt < 1e-5) runin::bench::timed_once(b, 3);
    else runin::bench::timed(b);
  }

  // Long wear run-in: 1000 wear updates on a 512-ring contact grid (thesis pin, k = 1e-4, H = 0.9 GPa).
  static const runin::tribo::ArchardWear archard(1e-4, 0.9e9);
  static PinWearParameters wp;
  wp.tip_radius = 5e-3;
  wp.effective_modulus = runin::tribo::effective_modulus({110e9, 0.37, 0.9e9}, {69e9, 0.33, 0.5e9});
  wp.rings = 512;
  static constexpr double distance = 0.1;  // the thesis case slides ~0.1 m by 3 s
  wp.grid_radius = suggested_grid_radius(wp.tip_radius, wp.effective_modulus, kLoad, &archard, distance);
  static double step = 0.0;
  {
    PinWear pin(wp, archard, kLoad);
    step = pin.stable_step();  // the adaptive bound at the start (it grows as the flat widens)
  }
  runin::bench::timed_once(benchmark::RegisterBenchmark("wear/fixed_1000", [](benchmark::State &state) {
    long steps = 0;
    double volume = 0.0;
    for (auto _ : state) {
      PinWear pin(wp, archard, kLoad);
      for (int k = 0; k < 1000; ++k) pin.step(step);
      steps = pin.steps();
      volume = pin.wear_volume();
    }
    state.counters["updates"] = static_cast<double>(steps);
    state.counters["volume"] = volume;
  }), 5);
  runin::bench::timed_once(benchmark::RegisterBenchmark("wear/adaptive", [](benchmark::State &state) {
    long steps = 0;
    for (auto _ : state) {
      PinWear pin(wp, archard, kLoad);
      pin.advance(distance);
      steps = pin.steps();
    }
    state.counters["updates"] = static_cast<double>(steps);
  }), 3);

  runin::bench::MedianReporter reporter;
  runin::bench::run_benchmarks(reporter);

  const std::string csv_path = out + "/wp_pin_on_disk.csv";
  if (!runin::bench::write_work_precision_csv(csv_path, rows, reporter)) return 1;

  const auto *fixed = reporter.find("wear/fixed_1000");
  const auto *adaptive = reporter.find("wear/adaptive");
  if (fixed)
    std::printf("wear: %ld updates of %.3g m on %d rings in %.3f s (median of %ld), V = %.6e m^3 (Archard %.6e)\n",
                std::lround(fixed->counter("updates")), step, wp.rings, fixed->seconds, fixed->repetitions,
                fixed->counter("volume"), archard.volume(kLoad, 1000 * step));
  if (adaptive)
    std::printf("wear: adaptive run over %.3g m: %ld updates in %.3f s (median of %ld)\n", distance,
                std::lround(adaptive->counter("updates")), adaptive->seconds, adaptive->repetitions);
  if (fixed && adaptive) {
    FILE *wear = std::fopen((out + "/wear_timing.csv").c_str(), "w");
    if (wear) {
      std::fprintf(wear, "run,rings,updates,wall_time_s\nfixed_1000,%d,%ld,%.6e\nadaptive,%d,%ld,%.6e\n", wp.rings,
                   std::lround(fixed->counter("updates")), fixed->seconds, wp.rings,
                   std::lround(adaptive->counter("updates")), adaptive->seconds);
      std::fclose(wear);
    }
  }

  const std::string plot = std::string("/usr/bin/python3 ") + RUNIN_SOURCE_DIR + "/tools/plot_wp.py " + csv_path +
                           " " + out + "/wp_pin_on_disk.png --title 'pin-on-disk thesis case (2 s)' --ylabel "
                           "'max relative error of V and s, 10 ms grid after break-away' --target-error 1e-6 "
                           "--target-ms 20";
  if (std::system(plot.c_str()) != 0) std::fprintf(stderr, "plot failed: %s\n", plot.c_str());
  return 0;
}
