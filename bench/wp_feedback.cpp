// Work-precision of the lubricated roughness-feedback model (thesis ch. 3, inputs/feedback_lubricated.toml:
// C1 = 0.02, C2 = 0.08, K1 = 1e-3, K2 = 4e-3, A = B = 1, R0 = 6 um, R* = 2 um, 8000 s = 16 relaxation times).
//   build-bench/bench/wp_feedback [OUT_DIR]   -> OUT_DIR/wp_feedback.csv, OUT_DIR/wp_feedback.png  (OUT_DIR default: build-bench/bench/out)
// Reference: the closed form R^2(t) = R*^2 + (R0^2 - R*^2) exp(-2 A K1 t) (tribo::FeedbackModel::exact_roughness).
// Error: max relative error of R over the 40 s output grid (200 points).
// Methods: CVODE BDF and Adams (continuum::simulate, rtol 1e-4 ... 1e-12, atol = 1e-3 rtol) against
// naive fixed-step explicit Euler and classical RK4 on the same right-hand side (FeedbackSystem::rhs).
// Wall time: timed by Google Benchmark (median of 5 repetitions, wall time), one thread.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "continuum/feedback_system.h"
#include "wp_reporter.h"

using namespace runin;
using namespace runin::continuum;

namespace {
constexpr double kR0 = 6.0, kEnd = 8000.0, kGrid = 40.0;

tribo::FeedbackModel lubricated() {
  tribo::FeedbackCoefficients c;
  c.C1 = 0.02;
  c.C2 = 0.08;
  c.K1 = 1e-3;
  c.K2 = 4e-3;
  c.A = 1.0;
  c.B = 1.0;
  return tribo::FeedbackModel(c, tribo::FeedbackKind::lubricated);
}

double relative_error(const tribo::FeedbackModel &m, double t, double r) {
  return std::abs(r / m.exact_roughness(kR0, t) - 1.0);
}

// Fixed-step explicit baseline on y = (R, W): Euler (order 1) or classical RK4 (order 4).
double fixed_step_error(const FeedbackSystem &system, double dt, bool rk4) {
  const long steps = std::lround(kEnd / dt), every = std::lround(kGrid / dt);
  double y[2] = {kR0, 0.0}, worst = 0.0;
  double k1[2], k2[2], k3[2], k4[2], tmp[2];
  for (long n = 0; n < steps; ++n) {
    const double t = n * dt;
    system.rhs(t, y, k1);
    if (!rk4) {
      for (int i = 0; i < 2; ++i) y[i] += dt * k1[i];
    } else {
      for (int i = 0; i < 2; ++i) tmp[i] = y[i] + 0.5 * dt * k1[i];
      system.rhs(t + 0.5 * dt, tmp, k2);
      for (int i = 0; i < 2; ++i) tmp[i] = y[i] + 0.5 * dt * k2[i];
      system.rhs(t + 0.5 * dt, tmp, k3);
      for (int i = 0; i < 2; ++i) tmp[i] = y[i] + dt * k3[i];
      system.rhs(t + dt, tmp, k4);
      for (int i = 0; i < 2; ++i) y[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    if ((n + 1) % every == 0) worst = std::max(worst, relative_error(system.model(), (n + 1) * dt, y[0]));
  }
  return worst;
}

}  // namespace

int main(int argc, char **argv) {
  const std::string out = runin::bench::initialize(argc, argv, ".");
  static const tribo::FeedbackModel model = lubricated();
  static const FeedbackSystem system(model);
  std::printf("lubricated case: R0 = %g um, R* = %.10g um, relaxation time 1/(2 A K1) = %g s, t_end = %g s\n", kR0,
              model.stationary_roughness(), 1.0 / model.relaxation_rate(), kEnd);

  std::vector<runin::bench::WorkPrecisionRow> rows;
  for (const auto method : {CvodeIntegrator::Method::Bdf, CvodeIntegrator::Method::Adams}) {
    const char *name = method == CvodeIntegrator::Method::Bdf ? "cvode_bdf" : "cvode_adams";
    for (const double rtol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
      FeedbackRun run;
      run.initial_roughness = kR0;
      run.t_end = kEnd;
      run.output_interval = kGrid;
      run.integrator.method = method;
      run.integrator.rtol = rtol;
      run.integrator.atol = rtol * 1e-3;  // R is O(1) um, W grows to O(10)
      rows.push_back({runin::bench::label(name, rtol), name, rtol});
      runin::bench::timed(benchmark::RegisterBenchmark(rows.back().name.c_str(), [run, name](benchmark::State &state) {
        double error = 0.0;
        long steps = 0;
        for (auto _ : state) {
          error = 0.0;  // the max over 200 output points: negligible next to the solve
          const auto report = simulate(system, run, [&](const FeedbackSample &s) {
            error = std::max(error, relative_error(model, s.t, s.roughness));
          });
          if (!report.ok()) state.SkipWithError((std::string(name) + ": " + report.message).c_str());
          steps = report.steps;
        }
        state.counters["rel_error"] = error;
        state.counters["steps"] = static_cast<double>(steps);
      }));
    }
  }
  for (const bool rk4 : {false, true}) {
    const char *name = rk4 ? "rk4_fixed" : "euler_fixed";
    for (const double dt : {40.0, 10.0, 1.0, 0.1, 0.01, 0.001}) {
      if (rk4 && dt < 0.1) continue;  // RK4 is at round-off long before
      rows.push_back({runin::bench::label(name, dt), name, dt});
      auto *b = benchmark::RegisterBenchmark(rows.back().name.c_str(), [dt, rk4](benchmark::State &state) {
        double error = 0.0;
        for (auto _ : state) benchmark::DoNotOptimize(error = fixed_step_error(system, dt, rk4));
        state.counters["rel_error"] = error;
        state.counters["steps"] = static_cast<double>(std::lround(kEnd / dt));
      });
      if (dt < 0.01) runin::bench::timed_once(b, 3);
      else runin::bench::timed(b);
    }
  }
  runin::bench::MedianReporter reporter;
  runin::bench::run_benchmarks(reporter);

  const std::string csv_path = out + "/wp_feedback.csv";
  if (!runin::bench::write_work_precision_csv(csv_path, rows, reporter)) return 1;

  const std::string plot = std::string("/usr/bin/python3 ") + RUNIN_SOURCE_DIR + "/tools/plot_wp.py " + csv_path +
                           " " + out + "/wp_feedback.png --title 'lubricated feedback model (8000 s)' --ylabel "
                           "'max relative error of R vs closed form, 40 s grid' --target-error 1e-8";
  if (std::system(plot.c_str()) != 0) std::fprintf(stderr, "plot failed: %s\n", plot.c_str());
  return 0;
}
