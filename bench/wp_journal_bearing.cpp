// Work-precision of the journal-bearing run-in (thesis ch. 5, inputs/journal_bearing.toml physics):
// CVODE BDF / Adams at several tolerances and a naive fixed-step explicit Euler stepper (stick/slip
// switched at step ends, no event location) against a CVODE BDF rtol = 1e-12 reference.
// Error: max over the 1 ms output grid of |s(t) - s_ref(t)| / s_ref(2 s), s the sliding distance.
// Also times the long wear run-in: 1000 wear updates on a 512-node arc.
//   build-bench/bench/wp_journal_bearing [OUT.csv]   (default BUILD/bench/out/wp_journal_bearing.csv; PNG beside it)
// Wall time: timed by Google Benchmark (median of 5 repetitions, wall time; Euler h = 1e-6 and wear: 3), one core.
// Bearing halves: 2 (the thesis's two loaded halves, two contacts), RUNIN_BENCH_HALVES=1 for the single
// contact (the earlier one-contact model). The wear benchmark wears one contact either way.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "continuum/journal_bearing.h"
#include "thesis_setups.h"
#include "wp_reporter.h"

using namespace runin::continuum;

namespace {

JournalBearingParameters thesis(int nodes = 256) {
  const char *halves = std::getenv("RUNIN_BENCH_HALVES");
  return runin::bench::journal_bearing_thesis(nodes, halves && std::string(halves) == "1" ? 1 : 2);
}

constexpr double kTEnd = 2.0, kDt = 1e-3;

// Sliding distance on the output grid (the last sample at each grid time).
std::vector<double> cvode_distance(const JournalBearingParameters &p, const SlidingFriction &f,
                                   CvodeIntegrator::Method method, double rtol) {
  JournalBearingSystem system(p, f);
  JournalBearingRun run;
  run.t_end = kTEnd;
  run.output_interval = kDt;
  run.integrator.method = method;
  run.integrator.rtol = rtol;
  run.integrator.atol = 1e-2 * rtol;  // s ~ 1e-2 m, w ~ 1 rad/s
  run.integrator.max_steps = 1000000;
  std::vector<double> grid(static_cast<std::size_t>(std::llround(kTEnd / kDt)) + 1, 0.0);
  simulate(system, run, [&](const JournalBearingSample &s) {
    const double k = s.t / kDt;
    if (std::abs(k - std::round(k)) < 1e-9) grid[static_cast<std::size_t>(std::llround(k))] = s.distance;
  });
  return grid;
}

// Naive baseline: forward Euler on (theta, w, s); stick/slip decided at step ends; the same
// frozen-pressure wear updates as the CVODE stepper (when s passes the next wear point).
std::vector<double> euler_distance(const JournalBearingParameters &p, const SlidingFriction &f, double h) {
  JournalBearingSystem system(p, f);
  const auto &contact = system.contact();
  const int halves = p.halves;
  std::vector<std::vector<double>> wear(halves, std::vector<double>(contact.nodes(), 0.0));
  std::vector<ConformalSolution> sol;
  double normal = 0.0;  // summed over the halves (same mu on both: no state per half in this baseline)
  for (int h = 0; h < halves; ++h) {
    sol.push_back(contact.solve(system.load_per_length(h)));
    normal += sol[h].normal_force_per_length * p.bore.axial_width;
  }
  const double wear_step = 0.5 * system.wear_law().stable_slip_step(contact.contact_stiffness_per_area());
  double s_update = 0.0, next_wear = wear_step;
  const double r = p.bore.shaft_radius;
  double theta = 0.0, w = 0.0, s = 0.0, t = 0.0;
  bool slip = false;
  const long steps = std::lround(kTEnd / h), per_output = std::lround(kDt / h);
  std::vector<double> grid;
  grid.push_back(0.0);
  for (long n = 1; n <= steps; ++n) {
    const double tc = p.coupling_stiffness * (p.drive_angle(t) - theta) + p.coupling_damping * (p.drive_speed(t) - w);
    if (!slip) {
      if (std::abs(tc) > f.static_coefficient() * normal * r) slip = true;
    }
    if (slip) {
      const int dir = w > 0.0 ? 1 : (w < 0.0 ? -1 : (tc > 0.0 ? 1 : -1));
      const double tf = dir * f.kinetic(s, r * std::abs(w)) * normal * r;
      const double w_new = w + h * (tc - tf) / p.inertia;
      theta += h * w;
      s += h * r * std::abs(w);
      if (w != 0.0 && w_new * w <= 0.0 && std::abs(tc) <= f.static_coefficient() * normal * r) {
        w = 0.0;  // crossed zero: re-stick
        slip = false;
      } else {
        w = w_new;
      }
    }
    t = n * h;
    if (s >= next_wear) {
      const double ds = s - s_update;
      normal = 0.0;
      for (int h = 0; h < halves; ++h) {
        for (int i = 0; i < contact.nodes(); ++i) wear[h][i] += system.wear_law().depth_rate(sol[h].pressure[i]) * ds;
        const auto previous = sol[h].pressure;
        sol[h] = contact.solve(system.load_per_length(h), wear[h], &previous);
        normal += sol[h].normal_force_per_length * p.bore.axial_width;
      }
      s_update = s;
      next_wear = s + wear_step;
    }
    if (n % per_output == 0) grid.push_back(s);
  }
  return grid;
}

double error(const std::vector<double> &a, const std::vector<double> &ref) {
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.size() && i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - ref[i]));
  return worst / ref.back();
}

struct Row {
  std::string name, method;
  double mu0, setting;
};

}  // namespace

int main(int argc, char **argv) {
  const std::string out_path = runin::bench::initialize(argc, argv, "wp_journal_bearing.csv");
  static const auto p = thesis();
  std::vector<Row> rows;
  for (double mu0 : {0.95, 0.55, 0.15}) {
    const auto f = SlidingFriction::static_kinetic(mu0, 0.8 * mu0);
    // The reference is computed once, before (and outside) every timed run of this mu0.
    auto ref = std::make_shared<std::vector<double>>();
    auto reference = [p = p, f, ref] {
      if (ref->empty()) *ref = cvode_distance(p, f, CvodeIntegrator::Method::Bdf, 1e-12);
      return *ref;
    };
    char mu[32];
    std::snprintf(mu, sizeof mu, "mu0_%g/", mu0);
    for (auto [method, name] : {std::pair{CvodeIntegrator::Method::Bdf, "cvode_bdf"},
                                std::pair{CvodeIntegrator::Method::Adams, "cvode_adams"}})
      for (double rtol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-10}) {
        rows.push_back({mu + runin::bench::label(name, rtol), name, mu0, rtol});
        runin::bench::timed(benchmark::RegisterBenchmark(
            rows.back().name.c_str(), [f, method = method, rtol, reference](benchmark::State &state) {
              const auto ref = reference();
              std::vector<double> d;
              for (auto _ : state) d = cvode_distance(p, f, method, rtol);
              state.counters["rel_error"] = error(d, ref);
            }));
      }
    for (double h : {1e-4, 1e-5, 1e-6}) {
      rows.push_back({mu + runin::bench::label("euler_fixed", h), "euler_fixed", mu0, h});
      auto *b = benchmark::RegisterBenchmark(rows.back().name.c_str(), [f, h, reference](benchmark::State &state) {
        const auto ref = reference();
        std::vector<double> d;
        for (auto _ : state) d = euler_distance(p, f, h);
        state.counters["rel_error"] = error(d, ref);
      });
      if (h < 1e-5) runin::bench::timed_once(b, 3);
      else runin::bench::timed(b);
    }
  }
  // Long wear run-in: 1000 wear updates (adaptive step 0.5 * 2H/(k k_c)) on 512 nodes.
  static auto wide = thesis(512);
  wide.bore.arc_half_angle = 0.5;
  static const JournalBearingSystem system(wide, SlidingFriction::static_kinetic(0.95, 0.76));
  static const double step = 0.5 * system.wear_law().stable_slip_step(system.contact().contact_stiffness_per_area());
  static WearHistory history;
  runin::bench::timed_once(benchmark::RegisterBenchmark("wear_1000_updates_512_nodes", [](benchmark::State &state) {
    for (auto _ : state) history = wear_in(system, step, 1000);
  }), 3);
  runin::bench::timed(benchmark::RegisterBenchmark("contact_setup_512_nodes", [](benchmark::State &state) {
    for (auto _ : state) {
      ConformalContact c(wide.bore);
      benchmark::DoNotOptimize(c);
    }
  }), 3);

  runin::bench::MedianReporter reporter;
  runin::bench::run_benchmarks(reporter);

  std::ofstream out(out_path + ".tmp");
  out << "case,mu0,method,tolerance_or_step,error,wall_seconds\n";
  for (const Row &row : rows)
    if (const auto *m = reporter.find(row.name)) {
      out << "thesis_2s," << row.mu0 << "," << row.method << "," << row.setting << "," << m->counter("rel_error") << ","
          << m->seconds << "\n";
      std::printf("mu0 %.2f %-11s %s %-6g error %.3e  wall %6.2f ms\n", row.mu0, row.method.c_str(),
                  row.method == "euler_fixed" ? "h   " : "rtol", row.setting, m->counter("rel_error"),
                  1e3 * m->seconds);
    }
  const auto *wear = reporter.find("wear_1000_updates_512_nodes");
  const auto *setup = reporter.find("contact_setup_512_nodes");
  if (wear) out << "wear_1000_updates_512_nodes,,wear_in," << step << ",," << wear->seconds << "\n";
  if (setup) out << "contact_setup_512_nodes,,ConformalContact,,," << setup->seconds << "\n";
  if (wear && setup)
    std::printf("wear run-in: 1000 updates on 512 nodes (ds = %.3g m): wall %.3f s (+ influence matrix wall %.3f s); "
                "status %s\n",
                step, wear->seconds, setup->seconds, to_string(history.status));
  out.close();
  std::rename((out_path + ".tmp").c_str(), out_path.c_str());
  // PNG beside the CSV with Debian's matplotlib.
  const std::string png = out_path.substr(0, out_path.rfind('.')) + ".png";
  const std::string plot = "/usr/bin/python3 " RUNIN_SOURCE_DIR "/tools/plot_wp_journal_bearing.py '" + out_path +
                           "' '" + png + "' 'journal bearing, 2 s thesis case: work-precision (wall time)'";
  if (std::system(plot.c_str()) != 0) std::fprintf(stderr, "plot failed: %s\n", plot.c_str());
  std::printf("wrote %s and %s\n", out_path.c_str(), png.c_str());
  return 0;
}
