// Work-precision of the piston-ring thesis cases (inputs/piston_ring.toml: 2 s displacement ramp,
// mu0 = 0.95 / 0.55 / 0.15, mu_kinetic = 0.7 mu0) and timing of the long wear run-in.
//   build-bench/bench/wp_piston_ring [OUT_DIR]  -> OUT_DIR/wp_piston_ring.csv, .png, wear_timing_piston_ring.csv  (OUT_DIR default: build-bench/bench/out)
// Reference: after break-away the ring obeys a linear damped oscillator (constant W, v_p, mu_k),
// so the closed form is exact: with eps = e + mu_k W / k,
//   eps'' + (c/m) eps' + (k/m) eps = 0,  eps(t_b) = -v_p t_b + mu_k W / k,  eps'(t_b) = -v_p,
//   t_b = (mu_s W - c v_p) / (k v_p),  s = eps - eps(t_b) + v_p (t - t_b),  F_land = -k e - c eps'.
// Error: max over the 1 ms output grid of |s - s_ex| / s_ex(2 s) and |F_land - F_ex| / (mu_k W),
// and |t_b - t_b,ex| / t_b,ex.
// Wall time: timed by Google Benchmark (median of 5 repetitions, wall time; slow runs 3), one core.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#include "wp_reporter.h"

using namespace runin::continuum;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kEnd = 2.0, kGrid = 1e-3;

PistonRingParameters thesis() {  // = inputs/piston_ring.toml
  PistonRingParameters p;
  p.crank = {0.045, 0.150};
  p.motion = PistonMotion::Ramp;
  p.start_angle = 75.0 * kPi / 180.0;
  p.ramp_time = 2.0;
  p.bore = 0.1;
  p.ring_width = 0.01;
  p.ring_mass = 7200.0 * kPi * 0.09 * 0.01 * 0.01;
  p.land_stiffness = 1e7;
  p.land_damping = 2.0 * 0.5 * std::sqrt(p.land_stiffness * p.ring_mass);
  p.elastic_pressure = 0.2e6;
  return p;
}

struct Exact {
  double t_b, v_p, e_ss, eps0, c_over_m, k_over_m, force_scale;
  Exact(const PistonRingSystem &sys, double mu_s, double mu_k) {
    const auto &p = sys.parameters();
    const double w = sys.normal_load(0.0);
    v_p = sys.piston_velocity(0.0);
    t_b = (mu_s * w - p.land_damping * v_p) / (p.land_stiffness * v_p);
    e_ss = -mu_k * w / p.land_stiffness;
    eps0 = -v_p * t_b - e_ss;
    c_over_m = p.land_damping / p.ring_mass;
    k_over_m = p.land_stiffness / p.ring_mass;
    force_scale = mu_k * w;
  }
  // eps and eps' of the underdamped oscillator from (eps0, -v_p) at t_b.
  void state(double t, double &eps, double &deps) const {
    const double a = 0.5 * c_over_m, wd = std::sqrt(k_over_m - a * a), tau = t - t_b;
    const double b = (-v_p + a * eps0) / wd;  // eps = exp(-a tau) (eps0 cos + b sin)
    const double ex = std::exp(-a * tau), co = std::cos(wd * tau), si = std::sin(wd * tau);
    eps = ex * (eps0 * co + b * si);
    deps = ex * (-a * (eps0 * co + b * si) + wd * (-eps0 * si + b * co));
  }
  double distance(double t) const {
    double eps, deps;
    state(t, eps, deps);
    return eps - eps0 + v_p * (t - t_b);
  }
  double land_force(double t, const PistonRingParameters &p) const {
    double eps, deps;
    state(t, eps, deps);
    return -p.land_stiffness * (eps + e_ss) - p.land_damping * deps;
  }
};

struct Trace {
  std::vector<double> t, s, f;
  double t_b = -1.0;
};

double error_of(const Trace &tr, const Exact &ex, const PistonRingParameters &p) {
  if (tr.t_b < 0.0) return INFINITY;
  double err = std::abs(tr.t_b - ex.t_b) / ex.t_b;
  const double s_scale = ex.distance(kEnd);
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    if (tr.t[i] < ex.t_b) continue;
    err = std::max(err, std::abs(tr.s[i] - ex.distance(tr.t[i])) / s_scale);
    err = std::max(err, std::abs(tr.f[i] - ex.land_force(tr.t[i], p)) / ex.force_scale);
  }
  return err;
}

Trace run_cvode(const PistonRingSystem &sys, CvodeIntegrator::Method method, double rtol, double atol) {
  PistonRingRun run;
  run.t_end = kEnd;
  run.output_interval = kGrid;
  run.integrator.method = method;
  run.integrator.rtol = rtol;
  run.integrator.atol = atol;
  run.integrator.max_steps = 10000000;
  Trace tr;
  const auto report = simulate(sys, run, [&](const PistonRingSample &s) {
    if (s.state != ContactState::Slip) return;  // the closed form holds from break-away on
    tr.t.push_back(s.t);
    tr.s.push_back(s.distance);
    tr.f.push_back(s.land_force);
  });
  if (!report.breakaway_times.empty()) tr.t_b = report.breakaway_times.front();
  return tr;
}

// Naive baseline: fixed step, explicit Euler or classical RK4, stick/slip switched at step ends
// (no event location).
Trace run_fixed(const PistonRingSystem &sys, double h, bool rk4) {
  Trace tr;
  double y[4] = {0.0, 0.0, 0.0, 0.0};
  ContactState state = ContactState::Stick;
  int dir = 0;
  const long steps = static_cast<long>(std::llround(kEnd / h));
  const long every = std::max(1L, static_cast<long>(std::llround(kGrid / h)));
  auto f = [&](double t, const double *yy, double *dy) { sys.rhs(t, yy, dy, state, dir); };
  for (long n = 0; n < steps; ++n) {
    const double t = n * h;
    if (!rk4) {
      double d[4];
      f(t, y, d);
      for (int i = 0; i < 4; ++i) y[i] += h * d[i];
    } else {
      double k1[4], k2[4], k3[4], k4[4], tmp[4];
      f(t, y, k1);
      for (int i = 0; i < 4; ++i) tmp[i] = y[i] + 0.5 * h * k1[i];
      f(t + 0.5 * h, tmp, k2);
      for (int i = 0; i < 4; ++i) tmp[i] = y[i] + 0.5 * h * k2[i];
      f(t + 0.5 * h, tmp, k3);
      for (int i = 0; i < 4; ++i) tmp[i] = y[i] + h * k3[i];
      f(t + h, tmp, k4);
      for (int i = 0; i < 4; ++i) y[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    const double tn = t + h;
    double stuck[4] = {y[0], 0.0, y[2], y[3]};
    const double force = sys.land_force(tn, stuck);
    if (state == ContactState::Stick && std::abs(force) > sys.static_limit(tn, y)) {
      state = ContactState::Slip;
      dir = force > 0 ? 1 : -1;
      if (tr.t_b < 0.0) tr.t_b = tn;
    } else if (state == ContactState::Slip && dir * y[1] <= 0.0) {
      y[1] = 0.0;
      if (std::abs(force) <= sys.static_limit(tn, y)) state = ContactState::Stick, dir = 0;
      else dir = force > 0 ? 1 : -1;
    }
    if ((n + 1) % every == 0 && state == ContactState::Slip) {
      tr.t.push_back(tn);
      tr.s.push_back(y[2]);
      tr.f.push_back(sys.land_force(tn, y));
    }
  }
  return tr;
}

struct Row {
  std::string name, method;
  double mu0, setting;
};
}  // namespace

int main(int argc, char **argv) {
  const std::string out = runin::bench::initialize(argc, argv, ".");
  static const auto p = thesis();
  std::vector<Row> rows;
  for (double mu0 : {0.95, 0.55, 0.15}) {
    const auto sys = std::make_shared<const PistonRingSystem>(p, SlidingFriction::static_kinetic(mu0, 0.7 * mu0));
    const Exact ex(*sys, mu0, 0.7 * mu0);
    char mu[32];
    std::snprintf(mu, sizeof mu, "mu0_%g/", mu0);
    for (auto method : {CvodeIntegrator::Method::Bdf, CvodeIntegrator::Method::Adams}) {
      const char *name = method == CvodeIntegrator::Method::Bdf ? "cvode_bdf" : "cvode_adams";
      for (double rtol : {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10}) {
        const double atol = 1e-5 * rtol;  // states: e ~ 1e-5 m, u ~ 1e-2 m/s, s ~ 1e-2 m
        rows.push_back({mu + runin::bench::label(name, rtol), name, mu0, rtol});
        runin::bench::timed(benchmark::RegisterBenchmark(
            rows.back().name.c_str(), [sys, ex, method, rtol, atol](benchmark::State &state) {
              Trace tr;
              for (auto _ : state) tr = run_cvode(*sys, method, rtol, atol);
              state.counters["rel_error"] = error_of(tr, ex, p);
            }));
      }
    }
    for (bool rk4 : {false, true})
      for (double h : {1e-4, 3e-5, 1e-5, 3e-6, 1e-6}) {
        const char *name = rk4 ? "fixed_rk4" : "fixed_euler";
        rows.push_back({mu + runin::bench::label(name, h), name, mu0, h});
        auto *b = benchmark::RegisterBenchmark(rows.back().name.c_str(), [sys, ex, h, rk4](benchmark::State &state) {
          Trace tr;
          for (auto _ : state) tr = run_fixed(*sys, h, rk4);
          state.counters["rel_error"] = error_of(tr, ex, p);
        });
        if (h < 1e-5) runin::bench::timed_once(b, 3);
        else runin::bench::timed(b);
      }
  }

  // Long wear run-in (= inputs/piston_ring_long.toml: 1200 rpm, gas table, k = 1e-3): dynamics for
  // 0.3 s, then wear on a 512-cell liner / 64-cell ring grid along it, timed per 1000 updates.
  static auto lp = p;
  lp.motion = PistonMotion::Crank;
  lp.crank_speed = 1200.0 * 2.0 * kPi / 60.0;
  lp.gas.crank_angle = {0.0, 10.0, 30.0, 60.0, 120.0, 180.0, 360.0, 540.0, 600.0, 660.0, 700.0};
  for (auto &a : lp.gas.crank_angle) a *= kPi / 180.0;
  lp.gas.pressure = {5.0e6, 6.9e6, 5.0e6, 2.5e6, 0.8e6, 0.3e6, 0.1e6, 0.1e6, 0.3e6, 1.5e6, 3.5e6};
  lp.gas.cycle = 4.0 * kPi;
  static const PistonRingSystem long_sys(lp, SlidingFriction::static_kinetic(0.95, 0.665));
  static std::vector<PistonRingSample> samples;
  static auto dynamics = [] {
    PistonRingRun run;
    run.t_end = 5.0;
    run.output_interval = 2.5e-4;
    samples.clear();
    simulate(long_sys, run, [&](const PistonRingSample &s) { samples.push_back(s); });
  };
  runin::bench::timed_once(benchmark::RegisterBenchmark("long/dynamics_100_revolutions", [](benchmark::State &state) {
    for (auto _ : state) dynamics();
    state.counters["samples"] = static_cast<double>(samples.size());
  }), 5);
  static RingLinerWearSettings ws;
  ws.crown_height = 2e-6;
  // Liner grid as the CLI builds it: travel + w/2 + 1 mm + 4 mu_s W_max / k.
  const double margin = 0.5 * lp.ring_width + 1e-3 + 4.0 * 0.95 * (0.2e6 + 6.9e6) * lp.contact_area() / lp.land_stiffness;
  ws.liner_begin = lp.crank.bottom_dead_centre() - margin;
  ws.liner_end = lp.crank.top_dead_centre() + margin;
  ws.foundation_modulus = 66e9 / (1.0 - 0.27 * 0.27) / 0.01;
  runin::bench::timed_once(benchmark::RegisterBenchmark("long/wear_pass", [](benchmark::State &state) {
    if (samples.empty()) dynamics();  // untimed when run alone (--benchmark_filter)
    long updates = 0;
    for (auto _ : state) {
      RingLinerWear wear(ws, runin::tribo::ArchardWear(1e-3, 2e9));
      for (std::size_t i = 1; i < samples.size(); ++i) {
        wear.slide(samples[i - 1].ring_position, samples[i].ring_position, samples[i - 1].normal_load,
                   samples[i].normal_load);
        wear.pressure(samples[i].ring_position, samples[i].normal_load);  // the CSV's pressure columns
      }
      updates = wear.updates();
    }
    state.counters["updates"] = static_cast<double>(updates);
  }), 5);

  // The thesis case as RunIn models it now (inputs/piston_ring.toml): two rings in grooves
  // A and B with the land stiffness from the land and ring geometry (2.36e9 and 2.16e9 N/m), tensions
  // 0.2 and 0.15 MPa, next to the former one-ring model (k = 1e7 N/m); CVODE BDF rtol 1e-8 / atol
  // 1e-12 as the CLI, mu0 = 0.95, mu_k = 0.7 mu0. And the long wear pass above on the half-plane ring
  // face (BEM, 64 cells as the long case), one ring and two rings sharing the liner (ring B 15 mm
  // below A on the same trajectory, 0.75 of its load: timing only).
  static std::vector<PistonRingParameters> pack;
  {
    const double grooves[2] = {0.0815, 0.0805}, tensions[2] = {0.2e6, 0.15e6};
    for (int k = 0; k < 2; ++k) {
      auto q = p;
      q.land_stiffness = land_stiffness({0.1, grooves[k], 0.005, 0.01, 0.01, 66e9, 0.27}).total;
      q.land_damping = 2.0 * 0.5 * std::sqrt(q.land_stiffness * q.ring_mass);
      q.elastic_pressure = tensions[k];
      pack.push_back(q);
    }
  }
  auto thesis_run = [](const std::vector<PistonRingParameters> &rings) {
    long steps = 0;
    for (const auto &q : rings) {
      const PistonRingSystem sys(q, SlidingFriction::static_kinetic(0.95, 0.665));
      PistonRingRun run;
      run.t_end = kEnd;
      run.output_interval = 5e-4;  // as inputs/piston_ring.toml
      run.integrator.rtol = 1e-8;
      run.integrator.atol = 1e-12;
      steps += simulate(sys, run, [](const PistonRingSample &) {}).steps;
    }
    return steps;
  };
  runin::bench::timed(benchmark::RegisterBenchmark("thesis/one_ring_k1e7", [thesis_run](benchmark::State &state) {
    long steps = 0;
    for (auto _ : state) steps = thesis_run({p});
    state.counters["steps"] = static_cast<double>(steps);
  }));
  runin::bench::timed(benchmark::RegisterBenchmark("thesis/ring_pack_k_geometry", [thesis_run](benchmark::State &state) {
    long steps = 0;
    for (auto _ : state) steps = thesis_run(pack);
    state.counters["steps"] = static_cast<double>(steps);
  }));
  static RingLinerWearSettings hs = ws;
  hs.contact = FaceContact::HalfPlane;
  hs.contact_modulus = 66e9 / (2.0 * (1.0 - 0.27 * 0.27));
  hs.liner_begin -= 0.015;
  auto half_plane_pass = [](int rings) {
    std::vector<RingLinerWear> wear;
    wear.reserve(rings);
    for (int k = 0; k < rings; ++k) wear.emplace_back(hs, runin::tribo::ArchardWear(1e-3, 2e9));
    for (int k = 1; k < rings; ++k) wear[k].share_liner(wear[0]);
    for (std::size_t i = 1; i < samples.size(); ++i)
      for (int k = 0; k < rings; ++k) {
        const double offset = -0.015 * k, scale = k ? 0.75 : 1.0;
        wear[k].slide(samples[i - 1].ring_position + offset, samples[i].ring_position + offset,
                      scale * samples[i - 1].normal_load, scale * samples[i].normal_load);
        wear[k].pressure(samples[i].ring_position + offset, scale * samples[i].normal_load);
      }
    long updates = 0;
    for (const auto &w : wear) updates += w.updates();
    return updates;
  };
  runin::bench::timed_once(benchmark::RegisterBenchmark("long/wear_pass_half_plane", [half_plane_pass](benchmark::State &state) {
    if (samples.empty()) dynamics();
    long updates = 0;
    for (auto _ : state) updates = half_plane_pass(1);
    state.counters["updates"] = static_cast<double>(updates);
  }), 5);
  runin::bench::timed_once(benchmark::RegisterBenchmark("long/wear_pass_half_plane_two_rings", [half_plane_pass](benchmark::State &state) {
    if (samples.empty()) dynamics();
    long updates = 0;
    for (auto _ : state) updates = half_plane_pass(2);
    state.counters["updates"] = static_cast<double>(updates);
  }), 5);

  runin::bench::MedianReporter reporter;
  runin::bench::run_benchmarks(reporter);

  const std::string csv_path = out + "/wp_piston_ring.csv";
  FILE *csv = std::fopen(csv_path.c_str(), "w");
  if (!csv) {
    std::fprintf(stderr, "wp_piston_ring: cannot write %s\n", csv_path.c_str());
    return 1;
  }
  std::fprintf(csv, "mu0,method,setting,error,seconds\n");
  for (const Row &row : rows)
    if (const auto *m = reporter.find(row.name)) {
      std::fprintf(csv, "%g,%s,%g,%.6g,%.6g\n", row.mu0, row.method.c_str(), row.setting, m->counter("rel_error"),
                   m->seconds);
      std::printf("mu0 %-5g %-12s %s %-6g error %-10.3g %8.3f ms\n", row.mu0, row.method.c_str(),
                  row.method.rfind("cvode", 0) == 0 ? "rtol" : "h   ", row.setting, m->counter("rel_error"),
                  1e3 * m->seconds);
    }
  std::fclose(csv);

  const auto *dyn = reporter.find("long/dynamics_100_revolutions");
  const auto *wear = reporter.find("long/wear_pass");
  if (dyn && wear) {
    const long updates = std::lround(wear->counter("updates"));
    const std::string timing_path = out + "/wear_timing_piston_ring.csv";
    FILE *timing = std::fopen(timing_path.c_str(), "w");
    if (!timing) return 1;
    std::fprintf(timing, "what,seconds,updates,liner_cells,seconds_per_1000_updates\n");
    std::fprintf(timing, "dynamics_100_revolutions,%.6g,0,512,0\n", dyn->seconds);
    std::fprintf(timing, "wear_pass,%.6g,%ld,512,%.6g\n", wear->seconds, updates, 1e3 * wear->seconds / updates);
    std::fclose(timing);
    std::printf("long run-in: dynamics (100 revolutions, %zu samples) %.3f s; wear %ld updates on 512 liner cells "
                "%.3f s = %.4f s per 1000 updates\n",
                samples.size(), dyn->seconds, updates, wear->seconds, 1e3 * wear->seconds / updates);
  }

  {
    const auto *one = reporter.find("thesis/one_ring_k1e7");
    const auto *two = reporter.find("thesis/ring_pack_k_geometry");
    if (one && two)
      std::printf("thesis dynamics (2 s, BDF 1e-8): one ring k = 1e7 %.3f ms (%g steps), ring pack %.3f ms (%g steps), "
                  "ratio %.2f\n",
                  1e3 * one->seconds, one->counter("steps"), 1e3 * two->seconds, two->counter("steps"),
                  two->seconds / one->seconds);
    const auto *w1 = reporter.find("long/wear_pass");
    const auto *h1 = reporter.find("long/wear_pass_half_plane");
    const auto *h2 = reporter.find("long/wear_pass_half_plane_two_rings");
    if (w1 && h1 && h2)
      std::printf("long wear pass: Winkler %.3f s, half-plane %.3f s (ratio %.2f), half-plane two rings %.3f s "
                  "(ratio %.2f)\n",
                  w1->seconds, h1->seconds, h1->seconds / w1->seconds, h2->seconds, h2->seconds / w1->seconds);
  }

  const std::string plot = std::string("/usr/bin/python3 ") + RUNIN_SOURCE_DIR + "/tools/plot_piston_ring.py wp " +
                           csv_path + " " + out + "/wp_piston_ring.png";
  return std::system(plot.c_str()) == 0 ? 0 : 1;
}
