// Mixed-lubrication run-in of the journal bearing on the micro state law (doc/lubricated_journal_bearing.md).
#include "continuum/mixed_journal_bearing.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

using namespace runin::continuum;

namespace {

std::shared_ptr<const runin::coupling::StateLaw> steel_law()
{
  static auto law = std::make_shared<const runin::coupling::StateLaw>(
      runin::coupling::StateLaw::read_file(std::string(RUNIN_SOURCE_DIR) + "/inputs/state_law_steel_rough.json"));
  return law;
}

double env(const char *name, double fallback)
{
  const char *v = std::getenv(name);
  return v ? std::atof(v) : fallback;
}

MixedJournalBearingParameters bearing()
{
  MixedJournalBearingParameters p;
  p.radius = 12.5e-3;
  p.length = 25e-3;
  p.clearance = env("MJB_C", 10e-6);
  p.load = env("MJB_W", 2000.0);
  p.viscosity = env("MJB_ETA", 0.01);
  p.speed = env("MJB_U", 0.08);
  p.n_theta = static_cast<int>(env("MJB_NX", 72));
  p.n_axial = static_cast<int>(env("MJB_NY", 9));
  p.law = steel_law();
  asperity_statistics_from_law(*p.law, p.summit_density, p.summit_radius);
  p.effective_modulus = 200e9 / (2.0 * (1.0 - 0.29 * 0.29));
  return p;
}

}    // namespace

TEST(MixedJournalBearing, DISABLED_Explore)
{
  const MixedJournalBearingSystem sys(bearing());
  auto t0 = std::chrono::steady_clock::now();
  const auto st = sys.initial_state();
  const auto sw = stribeck_sweep(sys, st, env("MJB_UMIN", 1e-4), env("MJB_UMAX", 100.0), 50);
  auto t1 = std::chrono::steady_clock::now();
  std::printf("stribeck %s %.3f s\n", to_string(sw.status), std::chrono::duration<double>(t1 - t0).count());
  for (const auto &p : sw.points)
    std::printf("U %.4g hersey %.4g S %.4g mu %.5g mv %.5g mb %.5g lam %.4g share %.4g eps %.5f att %.3f\n", p.speed,
                p.hersey, p.sommerfeld, p.mu, p.mu_viscous, p.mu_boundary, p.lambda, p.asperity_share, p.eccentricity,
                p.attitude);
  MixedRunSettings rs;
  rs.t_end = env("MJB_T", 3600.0);
  rs.output_interval = rs.t_end / 40;
  t0 = std::chrono::steady_clock::now();
  const auto rep = run_in(sys, rs, [](const MixedSample &s) {
    std::printf("t %.5g s %.5g eps %.5f att %.4f hmin %.4g lam %.4g share %.5g mu %.5g mv %.5g mb %.5g R %.5g hmax %.4g "
                "hmean %.4g V %.4g shaft %.4g pf %.4g pa %.4g steps %ld\n",
                s.t, s.distance, s.eccentricity, s.attitude, s.h_min, s.lambda, s.asperity_share, s.mu, s.mu_viscous,
                s.mu_boundary, s.sigma_contact, s.h_max, s.h_mean, s.bore_volume, s.shaft_depth, s.peak_film_pressure,
                s.peak_asperity_pressure, s.steps);
  });
  t1 = std::chrono::steady_clock::now();
  std::printf("run %s %s steps %ld solves %ld %.3f s; Vint %.6g\n", to_string(rep.status), rep.message.c_str(), rep.steps,
              rep.film_solves, std::chrono::duration<double>(t1 - t0).count(), rep.rate_volume_integral);
}
