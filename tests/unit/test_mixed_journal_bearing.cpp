// Mixed-lubrication run-in of the journal bearing on the micro state law (doc/lubricated_journal_bearing.md).
#include "continuum/mixed_journal_bearing.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>
#include <memory>

using namespace runin::continuum;

namespace {

// The shipped case's law: boundary-lubricated asperity contacts, k = 1e-6 (inputs/homogenise_steel_boundary.toml).
std::shared_ptr<const runin::coupling::StateLaw> steel_law()
{
  static auto law = std::make_shared<const runin::coupling::StateLaw>(
      runin::coupling::StateLaw::read_file(std::string(RUNIN_SOURCE_DIR) + "/inputs/state_law_steel_boundary.json"));
  return law;
}

// The shipped case inputs/journal_bearing_lubricated.toml (grid as given).
MixedJournalBearingParameters bearing(int n_theta = 72, int n_axial = 9)
{
  MixedJournalBearingParameters p;
  p.radius = 12.5e-3;
  p.length = 25e-3;
  p.clearance = 10e-6;
  p.load = 2000.0;
  p.viscosity = 0.01;
  p.speed = 0.15;
  p.n_theta = n_theta;
  p.n_axial = n_axial;
  p.law = steel_law();
  asperity_statistics_from_law(*p.law, p.summit_density, p.summit_radius);
  p.effective_modulus = 200e9 / (2.0 * (1.0 - 0.29 * 0.29));
  return p;
}

}    // namespace

// Stribeck curve at the unworn surface, 1 mm/s .. 100 m/s (50 points): boundary (asperity share ~1), mixed and
// full-film regimes in that order; the friction minimum near lambda = 3 (measured 3.18 on this grid); Petroff at
// the fast end.
TEST(MixedJournalBearing, StribeckRegimesMinimumAndPetroff)
{
  const MixedJournalBearingSystem sys(bearing());
  const auto t0 = std::chrono::steady_clock::now();
  const StribeckResult r = stribeck_sweep(sys, sys.initial_state(), 1e-3, 100.0, 50);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.points.size(), 50u);
  const auto &pts = r.points;
  // regimes in order as the speed rises: the asperity share falls monotonically from ~1 to ~0
  EXPECT_GT(pts.front().asperity_share, 0.9);
  EXPECT_LT(pts.back().asperity_share, 1e-12);
  for (std::size_t k = 1; k < pts.size(); ++k) {
    EXPECT_LE(pts[k].asperity_share, pts[k - 1].asperity_share * (1.0 + 1e-9)) << k;
    EXPECT_GT(pts[k].lambda, pts[k - 1].lambda) << k;
    EXPECT_GT(pts[k].hersey, pts[k - 1].hersey) << k;
  }
  std::size_t mixed = pts.size(), full = pts.size();
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (mixed == pts.size() && pts[k].asperity_share < 0.9) mixed = k;
    if (full == pts.size() && pts[k].asperity_share < 1e-3) full = k;
  }
  EXPECT_GT(mixed, 0u);       // a boundary stretch first
  EXPECT_LT(mixed + 2, full); // then a mixed stretch of several points
  EXPECT_LT(full + 10, pts.size());   // then a full film
  // friction minimum: where the falling boundary part meets the rising viscous part. The asperity share falls as
  // F_5/2(lambda) (1e-3 at lambda ~3), the viscous part grows ~ linearly in U, so the minimum lies at lambda 2.5-4
  // (classical: ~3); 1.5-5 excludes the boundary (share > 0.5 below 1.5) and the full film (share < 1e-7 above 5).
  std::size_t best = 0;
  for (std::size_t k = 1; k < pts.size(); ++k)
    if (pts[k].mu < pts[best].mu) best = k;
  std::printf("Stribeck: %.2f s; minimum mu %.5g at lambda %.4g (U %.4g m/s, share %.3g)\n", seconds, pts[best].mu,
              pts[best].lambda, pts[best].speed, pts[best].asperity_share);
  EXPECT_GT(pts[best].lambda, 1.5);
  EXPECT_LT(pts[best].lambda, 5.0);
  EXPECT_GT(best, mixed);
  EXPECT_LT(best + 5, pts.size());
  // Petroff at the full-film end: mu proportional to eta N / P (local log-log slope 1 within 5 %) and
  // mu (R/c) = 2 pi^2 S at the lightest load point (the fastest)
  const auto &a = pts[pts.size() - 2], &b = pts.back();
  const double slope = std::log(b.mu / a.mu) / std::log(b.hersey / a.hersey);
  const double petroff = 2.0 * M_PI * M_PI * b.sommerfeld;
  const double measured = b.mu * sys.parameters().radius / sys.parameters().clearance;
  std::printf("Petroff: slope %.5f, mu R/c %.6g vs 2 pi^2 S %.6g (%.3f %%), eps %.4f\n", slope, measured, petroff,
              100.0 * (measured / petroff - 1.0), b.eccentricity);
  EXPECT_NEAR(slope, 1.0, 0.05);
  EXPECT_NEAR(measured / petroff, 1.0, 0.02);
}

// Claim 1 from the micro scale: the shipped case (lambda 2 at the start) runs in: friction and asperity share fall
// to an equilibrium where the contact roughness R stops changing, because the film takes over (tiny asperity
// share, wear nearly stopped). After the run-in the conformal wear of the bore goes on slowly (~1e-5 of the load on
// the asperities, the law's severe dry wear rate) and the viscous friction creeps up by a few per cent.
TEST(MixedJournalBearing, RunInReachesFilmEquilibrium)
{
  const MixedJournalBearingSystem sys(bearing());   // the shipped case (its grid): 100 h, sampled every 600 s
  MixedRunSettings rs;
  rs.t_end = 360000.0;
  rs.output_interval = 600.0;
  std::vector<MixedSample> s;
  const MixedRunReport rep = run_in(sys, rs, [&](const MixedSample &x) { s.push_back(x); });
  ASSERT_TRUE(rep.ok()) << rep.message;
  ASSERT_GT(s.size(), 600u);
  const auto &law = *sys.parameters().law;
  const MixedSample &first = s.front(), &last = s.back();
  // starts mixed
  EXPECT_GT(first.lambda, 1.0);
  EXPECT_LT(first.lambda, 2.5);
  EXPECT_GT(first.asperity_share, 0.01);
  // the run-in: the asperity share and R fall at every sample; friction too, within the law's seed scatter of
  // mu_body (one step of 3e-4 at h ~ 0.1 nm) and the conformal creep of the viscous part once the film has the load
  std::size_t best = 0;
  double worst_rise = 0.0;
  for (std::size_t k = 1; k < s.size(); ++k) {
    if (s[k].mu < s[best].mu) best = k;
    worst_rise = std::max(worst_rise, s[k].mu / s[k - 1].mu - 1.0);
    EXPECT_LT(s[k].asperity_share, s[k - 1].asperity_share) << "t = " << s[k].t;
    EXPECT_LE(s[k].sigma_contact, s[k - 1].sigma_contact) << "t = " << s[k].t;
  }
  EXPECT_LT(worst_rise, 1e-3);
  EXPECT_LT(s[best].mu, 0.4 * first.mu);
  // equilibrium: friction settled (the last 30 % of the run within 1e-3), R's rate down by more than 1e3
  double mu_lo = HUGE_VAL, mu_hi = 0.0;
  for (const auto &x : s)
    if (x.t >= 0.7 * rs.t_end) mu_lo = std::min(mu_lo, x.mu), mu_hi = std::max(mu_hi, x.mu);
  EXPECT_LT((mu_hi - mu_lo) / mu_lo, 1e-3);
  const MixedSample &a1 = s[1], &b1 = s[s.size() - 2];
  const double r_rate0 = (first.sigma_contact - a1.sigma_contact) / (a1.t - first.t);
  const double r_rate1 = (b1.sigma_contact - last.sigma_contact) / (last.t - b1.t);
  EXPECT_LT(r_rate1, 1e-3 * r_rate0);
  EXPECT_LT(last.sigma_contact, 0.7 * first.sigma_contact);
  // because the film took over: the wear rate (bore volume per metre) fell by > 1e2
  const double rate0 = sys.wear_rates(rep.final_state, rep.initial).bore_volume;   // rates depend on p_a and h only
  const double rate1 = sys.wear_rates(rep.final_state, rep.final).bore_volume;
  std::printf("run-in: mu %.5g -> min %.5g (t %.4g s) -> %.5g (largest rise between samples %.3g, last 30 %% within "
              "%.3g); share %.3g -> %.3g; lambda %.3g -> %.3g; R %.4g -> %.4g nm (rate ratio %.3g); h_max %.4g nm "
              "(law's depths end at %.4g nm), journal %.4g nm; wear rate ratio %.3g; %ld steps\n",
              first.mu, s[best].mu, s[best].t, last.mu, worst_rise, (mu_hi - mu_lo) / mu_lo, first.asperity_share,
              last.asperity_share, first.lambda, last.lambda, 1e9 * first.sigma_contact, 1e9 * last.sigma_contact,
              r_rate1 / r_rate0, 1e9 * last.h_max, 1e9 * law.worn_depth().back(), 1e9 * last.shaft_depth, rate1 / rate0,
              rep.steps);
  EXPECT_LT(rate1, 1e-2 * rate0);
  EXPECT_LT(last.asperity_share, 1e-2 * first.asperity_share);
  // the equilibrium is the film's, not the law's end: the worn depth stays inside the law's table
  EXPECT_LT(last.h_max, law.worn_depth().back());
}

// Worn summits (wear.worn_surface = "truncated"): wear cuts the highest summits, so the contact ends once the film
// is thicker than the cut. Claim 1 with R constant: friction, the asperity share and R fall at every sample, settle
// (the last half of the hour: friction within 1e-4, R within 2e-4), and the run-in stops where the cut meets the film at the node of the
// smallest gap. The start is the Gaussian one (nothing worn yet).
TEST(MixedJournalBearing, WornSummitsRunInEndsWhereTheFilmClearsTheCut)
{
  MixedJournalBearingParameters p = bearing();
  p.worn_surface = WornSurface::TruncatedSummits;
  const MixedJournalBearingSystem sys(p), gaussian(bearing());
  MixedRunSettings rs;
  rs.t_end = 3600.0;
  rs.output_interval = 10.0;
  std::vector<MixedSample> s;
  const MixedRunReport rep = run_in(sys, rs, [&](const MixedSample &x) { s.push_back(x); });
  ASSERT_TRUE(rep.ok()) << rep.message;
  ASSERT_GT(s.size(), 360u);
  const MixedSample &first = s.front(), &last = s.back();
  const MixedEquilibrium g0 = gaussian.equilibrium(gaussian.initial_state(), p.speed);
  EXPECT_EQ(first.mu, (g0.viscous_friction + g0.boundary_friction) / p.load);
  EXPECT_EQ(first.asperity_share, g0.asperity_load / p.load);
  for (std::size_t k = 1; k < s.size(); ++k) {
    EXPECT_LE(s[k].mu, s[k - 1].mu * (1.0 + 1e-9)) << "t = " << s[k].t;
    EXPECT_LE(s[k].asperity_share, s[k - 1].asperity_share) << "t = " << s[k].t;
    EXPECT_LE(s[k].sigma_contact, s[k - 1].sigma_contact) << "t = " << s[k].t;
  }
  double mu_lo = HUGE_VAL, mu_hi = 0.0, r_lo = HUGE_VAL, r_hi = 0.0, t_settled = 0.0;
  for (const auto &x : s) {
    if (x.t >= 0.5 * rs.t_end) {
      mu_lo = std::min(mu_lo, x.mu), mu_hi = std::max(mu_hi, x.mu);
      r_lo = std::min(r_lo, x.sigma_contact), r_hi = std::max(r_hi, x.sigma_contact);
    }
    if (std::abs(x.mu / last.mu - 1.0) > 0.01) t_settled = x.t;
  }
  EXPECT_LT((mu_hi - mu_lo) / mu_lo, 1e-4);
  // R: the last half moves it by less than 2e-4 relative (0.05 nm) and by less than 1 % of its run-in fall
  EXPECT_LT((r_hi - r_lo) / r_lo, 2e-4);
  EXPECT_LT(r_hi - r_lo, 0.01 * (first.sigma_contact - last.sigma_contact));
  EXPECT_LT(last.mu, 0.5 * first.mu);
  EXPECT_LT(last.asperity_share, 1e-6);
  // the mechanism: at the smallest gap the cut has come down to the counterface (the film carries the load)
  const MixedEquilibrium &end = rep.final;
  std::size_t i_min = 0;
  for (std::size_t i = 1; i < end.gap.size(); ++i)
    if (end.gap[i] < end.gap[i_min]) i_min = i;
  const double reach = end.gap[i_min] - rep.final_state.bore[i_min] - rep.final_state.shaft;   // from the unworn plane
  const double sigma0 = sys.node_sigma(rep.final_state)[i_min];
  EXPECT_GT(end.top[i_min], reach - 1e-3 * sigma0);
  EXPECT_LT(end.top[i_min], reach + 2e-2 * sigma0);
  // only the summit tops went: the worn depth is a small fraction of sigma, R fell by a few per cent
  EXPECT_LT(last.h_max, 0.01 * sigma0);
  EXPECT_LT(last.sigma_contact, first.sigma_contact);
  EXPECT_GT(last.sigma_contact, 0.95 * first.sigma_contact);
  std::printf("worn summits: mu %.5g -> %.5g (within 1 %% of the end from t = %.4g s; last half within %.3g); share "
              "%.3g -> %.3g; R %.5g -> %.5g nm (last half within %.3g); cut - reach at the smallest gap %.3g sigma; "
              "h_max %.4g nm; %ld steps\n",
              first.mu, last.mu, t_settled, (mu_hi - mu_lo) / mu_lo, first.asperity_share, last.asperity_share,
              1e9 * first.sigma_contact, 1e9 * last.sigma_contact, (r_hi - r_lo) / r_lo,
              (end.top[i_min] - reach) / sigma0, 1e9 * last.h_max, rep.steps);
}

// Wear bookkeeping: the worn volume (sum of h_i A_i) equals the integral over nodes and time of wear_rate ds.
TEST(MixedJournalBearing, WornVolumeIsTheIntegratedWearRate)
{
  const MixedJournalBearingSystem sys(bearing(48, 7));
  MixedRunSettings rs;
  rs.t_end = 60.0;
  rs.output_interval = 10.0;
  std::vector<MixedSample> s;
  const MixedRunReport rep = run_in(sys, rs, [&](const MixedSample &x) { s.push_back(x); });
  ASSERT_TRUE(rep.ok()) << rep.message;
  double volume = 0.0;
  for (double h : rep.final_state.bore) volume += h * sys.node_area();
  ASSERT_GT(volume, 0.0);
  EXPECT_NEAR(rep.rate_volume_integral / volume, 1.0, 1e-12);
  EXPECT_NEAR(s.back().bore_volume / volume, 1.0, 1e-12);
  // and the samples' volume never decreases
  for (std::size_t k = 1; k < s.size(); ++k) EXPECT_GE(s[k].bore_volume, s[k - 1].bore_volume);
}

// With flow factors off and the asperities gone (sigma -> 0), the mixed equilibrium is the classical bearing:
// solve_journal_bearing at the found eccentricity in its own (line-of-centres) frame carries W at the same attitude
// with the same friction.
TEST(MixedJournalBearing, HydrodynamicLimitIsSolveJournalBearing)
{
  MixedJournalBearingParameters p = bearing(120, 21);
  p.flow_factors = false;
  p.sigma_override = 1e-12;
  const MixedJournalBearingSystem sys(p);
  const MixedEquilibrium e = sys.equilibrium(sys.initial_state(), p.speed);
  ASSERT_TRUE(e.ok()) << e.message;
  EXPECT_EQ(e.asperity_load, 0.0);
  EXPECT_NEAR((e.film_load - p.load) / p.load, 0.0, 1e-8);
  // the same film on the bore-fixed grid, through solve_journal_bearing's own load integration
  HydroJournalBearing b;
  b.radius = p.radius, b.length = p.length, b.clearance = p.clearance, b.viscosity = p.viscosity;
  b.omega = p.speed / p.radius;
  b.eccentricity_ratio = e.eccentricity;
  b.n_theta = p.n_theta, b.n_axial = p.n_axial;
  b.groove_angle = p.groove_angle;
  b.line_of_centres = e.attitude + M_PI;
  const HydroJournalResult rotated = solve_journal_bearing(b);
  EXPECT_NEAR(rotated.load / p.load, 1.0, 1e-8);
  EXPECT_NEAR(rotated.friction_force / e.viscous_friction, 1.0, 1e-12);
  // the classical frame (grid on the line of centres, groove at the same place on the bore): equal to the grid's
  // discretisation error
  b.line_of_centres = 0.0;
  b.groove_angle = std::fmod(p.groove_angle - (e.attitude + M_PI) + 4.0 * M_PI, 2.0 * M_PI);
  const HydroJournalResult classical = solve_journal_bearing(b);
  std::printf("hydrodynamic limit: eps %.6f, attitude %.6f rad; classical load %.6g N (W %.6g), attitude angle %.6f, "
              "friction %.6g vs %.6g N\n",
              e.eccentricity, e.attitude, classical.load, p.load, classical.attitude_angle, classical.friction_force,
              e.viscous_friction);
  EXPECT_NEAR(classical.load / p.load, 1.0, 0.01);
  EXPECT_NEAR(classical.friction_force / e.viscous_friction, 1.0, 0.01);
  EXPECT_NEAR(classical.attitude_angle, e.attitude, 0.005);
}

TEST(MixedJournalBearing, BadInputAndGapClosing)
{
  // a law without surface.R / surface.spacing
  auto json = steel_law()->to_json();
  json.erase("surface");
  const auto bare = runin::coupling::StateLaw::from_json(json, "bare.json");
  double eta = 0.0, beta = 0.0;
  try {
    asperity_statistics_from_law(bare, eta, beta);
    FAIL() << "no throw";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("a law without the statistics mixed lubrication needs"), std::string::npos);
  }
  // a load the film and the asperities cannot carry before the gap closes
  MixedJournalBearingParameters p = bearing(48, 7);
  p.load = 1e9;
  const MixedJournalBearingSystem sys(p);
  const MixedEquilibrium e = sys.equilibrium(sys.initial_state(), p.speed);
  EXPECT_EQ(e.status, MixedStatus::GapCloses) << e.message;
  for (auto [field, set] : std::vector<std::pair<std::string, void (*)(MixedJournalBearingParameters &)>>{
           {"viscosity", [](MixedJournalBearingParameters &q) { q.viscosity = 0.0; }},
           {"clearance", [](MixedJournalBearingParameters &q) { q.clearance = -1e-6; }},
           {"supply_pressure", [](MixedJournalBearingParameters &q) { q.supply_pressure = -1.0; }},
           {"speed", [](MixedJournalBearingParameters &q) { q.speed = 0.0; }}}) {
    MixedJournalBearingParameters q = bearing(48, 7);
    set(q);
    try {
      MixedJournalBearingSystem bad(q);
      ADD_FAILURE() << field << ": no throw";
    } catch (const std::exception &e) {
      EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << e.what();
    }
  }
}

// A speed table: the quasi-static film follows U(t) (linear between the points, held after them), the sliding
// distance is the integral of U, and a step ends at every corner of the table.
TEST(MixedJournalBearing, SpeedTableIsFollowedAndIntegrated)
{
  MixedJournalBearingParameters p = bearing(48, 7);
  p.speed_time = {0.0, 20.0, 40.0};
  p.speed_value = {0.15, 0.6, 0.3};
  const MixedJournalBearingSystem sys(p);
  MixedRunSettings rs;
  rs.t_end = 60.0;
  rs.output_interval = 7.0;   // not a divisor of the corners: the steps must stop at 20 s and 40 s themselves
  std::vector<MixedSample> s;
  const MixedRunReport rep = run_in(sys, rs, [&](const MixedSample &x) { s.push_back(x); });
  ASSERT_TRUE(rep.ok()) << rep.message;
  const auto distance = [](double t) {   // integral of the table
    if (t <= 20.0) return 0.15 * t + 0.5 * (0.45 / 20.0) * t * t;
    if (t <= 40.0) return 7.5 + 0.6 * (t - 20.0) - 0.5 * (0.3 / 20.0) * (t - 20.0) * (t - 20.0);
    return 7.5 + 9.0 + 0.3 * (t - 40.0);
  };
  for (const auto &x : s) {
    EXPECT_NEAR(x.speed, p.speed_at(x.t), 1e-15);
    EXPECT_NEAR(x.distance, distance(x.t), 1e-9 * distance(rs.t_end)) << "t = " << x.t;
  }
  EXPECT_NEAR(s.back().t, rs.t_end, 1e-9);
  // faster means a thicker film: lambda at 20 s (0.6 m/s) above that at 60 s (0.3 m/s) above the start (0.15 m/s)
  const auto at = [&](double t) {
    const MixedSample *best = &s.front();
    for (const auto &x : s)
      if (std::abs(x.t - t) < std::abs(best->t - t)) best = &x;
    return *best;
  };
  EXPECT_GT(at(21.0).lambda, s.back().lambda);
  EXPECT_GT(s.back().lambda, s.front().lambda);
}

// The warm-started balance Newton rebuilds a stale Jacobian before it gives up: on the coarse 48 x 7 grid the
// sweep down from 150 m/s stopped at 36.6 m/s ("no descent along the Newton direction") before that.
TEST(MixedJournalBearing, StribeckSweepRecoversFromAStaleJacobian)
{
  const MixedJournalBearingSystem sys(bearing(48, 7));
  const StribeckResult r = stribeck_sweep(sys, sys.initial_state(), 1.5e-4, 150.0, 50);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.points.size(), 50u);
  EXPECT_LT(r.points.back().eccentricity, 0.05);
}
