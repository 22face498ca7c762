// Mixed-lubrication run-in of the piston ring (doc/lubricated_piston_ring.md).
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "continuum/mixed_piston_ring.h"
#include "coupling/state_law.h"
#include "tribo/contact.h"
#include "tribo/greenwood_tripp.h"

namespace {

using namespace runin;
using continuum::MixedPistonRing;
using continuum::MixedRingParameters;

constexpr double kPi = 3.14159265358979323846;

// The shipped case's law: boundary-lubricated asperity contacts, k = 1e-6 (inputs/homogenise_steel_boundary.toml).
std::shared_ptr<const coupling::StateLaw> steel_law() {
  static const auto law = std::make_shared<const coupling::StateLaw>(
      coupling::StateLaw::read_file(std::string(RUNIN_SOURCE_DIR) + "/inputs/state_law_steel_boundary.json"));
  return law;
}

// A severe-wear law (k = 7e-3): one cycle wears nanometres, which the stepper's status and jump tests need.
std::shared_ptr<const coupling::StateLaw> severe_law() {
  static const auto law = std::make_shared<const coupling::StateLaw>(
      coupling::StateLaw::read_file(std::string(RUNIN_SOURCE_DIR) + "/inputs/state_law_steel_rough.json"));
  return law;
}

// The shipped case's ring (inputs/piston_ring_lubricated.toml) on the steel law.
MixedRingParameters ring_parameters(const coupling::StateLaw &law) {
  MixedRingParameters p;
  p.crank.crank_radius = 0.045;
  p.crank.link_length = 0.15;
  p.crank_speed = 1500.0 * 2.0 * kPi / 60.0;
  p.bore = 0.1;
  p.face_width = 1.5e-3;
  p.crown_height = 5e-6;
  p.elastic_pressure = 0.3e6;
  p.viscosity = 0.004;
  p.nodes = 81;
  p.steps_per_cycle = 360;
  p.effective_modulus = 200e9 / (2.0 * (1.0 - 0.29 * 0.29));
  p.summits = continuum::summit_statistics(law);
  return p;
}

// A law with uniform fields (mu_body, rq, wear rate per Pa) and the surface statistics of the steel law.
std::shared_ptr<const coupling::StateLaw> uniform_law(double rq, double mu = 0.05, double wear_per_pa = 1e-12,
                                                      bool statistics = true) {
  std::array<coupling::StateFieldTable, coupling::state_field_count> f;
  const std::vector<double> pressure = {1e6, 1e7}, depth = {0.0, 1e-8};
  auto set = [&](coupling::StateField field, double v1, double v2) {
    f[static_cast<std::size_t>(field)].mean = {{v1, v1}, {v2, v2}};
  };
  set(coupling::StateField::MuBody, mu, mu);
  set(coupling::StateField::Rq, rq, rq);
  set(coupling::StateField::Rsk, 0.0, 0.0);
  set(coupling::StateField::AreaFraction, 1e-3, 1e-2);
  set(coupling::StateField::WearRate, wear_per_pa * 1e6, wear_per_pa * 1e7);
  set(coupling::StateField::CounterfaceWearRate, wear_per_pa * 1e6, wear_per_pa * 1e7);
  f[static_cast<std::size_t>(coupling::StateField::SlidingDistance)].mean = {{0.0, 1e-3}, {0.0, 1e-4}};
  nlohmann::json meta = nlohmann::json::object();
  if (statistics) meta["surface"] = {{"R", 1e-4}, {"spacing", 2e-5}};
  return std::make_shared<const coupling::StateLaw>(pressure, depth, f, meta);
}

TEST(MixedPistonRing, F52TableMatchesQuadrature) {
  double worst = 0.0;
  for (double H = 0.0; H <= 9.0; H += 0.0137)
    worst = std::max(worst, std::abs(continuum::f52_interpolated(H) / tribo::greenwood_tripp_f(2.5, H) - 1.0));
  EXPECT_LT(worst, 1e-8);
}

TEST(MixedPistonRing, LawWithoutSurfaceStatisticsIsRejected) {
  const auto law = uniform_law(1e-7, 0.05, 1e-12, false);
  try {
    continuum::summit_statistics(*law);
    FAIL() << "no throw";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("a law without the statistics mixed lubrication needs"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(continuum::summit_statistics(*steel_law()));
}

// RingFace::fill_prev and dt reach the transient fill term: separating plates over one step keep their oil,
// theta = h / (h + dh/dt dt) (the same plates as Reynolds.SeparatingSqueezeFilmCavitatesConservingMass, through the
// ring face's own fields); a fill_prev of the wrong size or outside [0, 1] is refused naming the field.
TEST(MixedPistonRing, RingFaceCarriesThePreviousFill) {
  continuum::RingFace ring;
  ring.width = 2e-3;
  ring.viscosity = 0.01;
  ring.min_gap = 2e-6;
  ring.squeeze_velocity = 1e-4;
  ring.profile.assign(51, 0.0);
  ring.fill_prev.assign(51, 1.0);
  ring.dt = 5e-3;
  const auto r = continuum::solve_ring_face(ring);
  ASSERT_TRUE(r.film.ok());
  const double theta = ring.min_gap / (ring.min_gap + ring.squeeze_velocity * ring.dt);
  for (int i = 1; i < 50; ++i) EXPECT_NEAR(r.film.fill[i], theta, 1e-12) << i;
  ring.fill_prev.assign(50, 1.0);
  EXPECT_THROW(ring.system(), tribo::InvalidCoefficient);
  ring.fill_prev.assign(51, 1.5);
  try {
    ring.system();
    FAIL() << "no throw";
  } catch (const tribo::InvalidCoefficient &e) {
    EXPECT_NE(std::string(e.what()).find("fill_prev"), std::string::npos) << e.what();
  }
}

// Parallel squeeze film of a flat face (crown 0) at U = 0, no contact (rq 1 nm, H ~ 1e3): per unit length
// W' = mu b^3 (-dh/dt) / h^3 (p = 6 mu (-dh/dt) x (b - x) / h^3), so under a constant W'
//   1 / h^2 = 1 / h0^2 + 2 W' t / (mu b^3).
TEST(MixedPistonRing, SqueezeFilmMatchesTheFlatPlateClosedForm) {
  const auto law = uniform_law(1e-9);
  auto p = ring_parameters(*law);
  p.crown_height = 0.0;
  p.nodes = 101;
  MixedPistonRing ring(p, law);
  const double W = 450.0, h0 = 2e-6, mu = p.viscosity, b = p.face_width;
  const double t_end = 3.0 * mu * b * b * b / (2.0 * W * h0 * h0);   // h0 -> h0 / 2
  const int steps = 1000;
  const double dt = t_end / steps;
  continuum::FaceState state;
  state.h_min = h0;
  state.fill.assign(p.nodes, 1.0);
  double worst = 0.0;
  long solves = 0;
  for (int k = 1; k <= steps; ++k) {
    const auto s = ring.step(state, 0.0, W, dt, nullptr);
    solves += s.film_solves;
    ASSERT_EQ(s.status, continuum::RingFilmStatus::Ok);
    ASSERT_EQ(s.asperity_load, 0.0);
    state.h_min = s.h_min;
    state.fill = s.fill;
    const double exact = 1.0 / std::sqrt(1.0 / (h0 * h0) + 2.0 * W * k * dt / (mu * b * b * b));
    worst = std::max(worst, std::abs(s.h_min / exact - 1.0));
  }
  std::printf("squeeze: h(t_end) %.6g m (closed form %.6g), worst relative error %.3g, %ld film solves\n", state.h_min, 0.5 * h0, worst, solves);
  EXPECT_NEAR(state.h_min / (0.5 * h0), 1.0, 0.02);
  EXPECT_LT(worst, 0.02);
}

// Stribeck curve of the shipped ring (W' = 450 N/m, 50 speeds 1 mm/s .. 30 m/s): boundary (asperity share ~1),
// mixed, full film (share ~0) in that order; the friction minimum where the asperity share has just vanished.
TEST(MixedPistonRing, StribeckRegimesInOrderAndFrictionMinimumNearLambdaThree) {
  const auto law = steel_law();
  auto p = ring_parameters(*law);
  MixedPistonRing ring(p, law);
  const auto t0 = std::chrono::steady_clock::now();
  const auto sweep = continuum::stribeck_sweep(ring, 450.0, 1e-3, 30.0, 50);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(sweep.size(), 50u);
  std::size_t best = 0;
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    ASSERT_EQ(sweep[k].status, continuum::RingFilmStatus::Ok) << k;
    if (k > 0) {
      EXPECT_LE(sweep[k].asperity_share, sweep[k - 1].asperity_share + 1e-12) << k;   // regimes in order
      EXPECT_GE(sweep[k].lambda, sweep[k - 1].lambda) << k;
    }
    if (sweep[k].mu < sweep[best].mu) best = k;
  }
  EXPECT_GT(sweep.front().asperity_share, 0.95);   // boundary
  EXPECT_LT(sweep.back().asperity_share, 1e-6);    // full film
  EXPECT_LT(sweep.front().lambda, 2.0);
  // the minimum: between the boundary (mu_body ~0.04) and the rising viscous branch
  std::printf("stribeck: %.3f s; mu %.5g (share %.4g) -> min %.5g at lambda %.3f (U %.4g, share %.3g) -> %.5g (lambda %.3g)\n",
              seconds, sweep.front().mu, sweep.front().asperity_share, sweep[best].mu, sweep[best].lambda,
              sweep[best].speed, sweep[best].asperity_share, sweep.back().mu, sweep.back().lambda);
  EXPECT_GT(sweep[best].lambda, 2.0);
  EXPECT_LT(sweep[best].lambda, 4.0);
  EXPECT_LT(sweep[best].mu, 0.5 * sweep.front().mu);
  EXPECT_LT(sweep[best].mu, 0.5 * sweep.back().mu);
}

// Full film of a rigid parabolic slider, h = h0 + x^2 / (2 R) (Martin 1916, Reynolds conditions): W' =
// 2.448 eta U R / h0 for one surface sliding at U, so h0 / R = 2.448 eta U / W' (h0 ~ duty parameter); the
// shear over the contact scale sqrt(2 R h0) gives F ~ eta U sqrt(R / h0), hence mu = F / W' ~ sqrt(h0 / R) ~
// (eta U / W')^(1/2) -- not eta N / P (that is the journal bearing's Sommerfeld variable). The face must be wide
// against the contact (crown c >> h0: the face's tails add -8 eta U R / b to F, a relative (2/pi) sqrt(h0/c)).
TEST(MixedPistonRing, FullFilmFollowsTheDutyParameterWithSquareRootFriction) {
  const auto law = steel_law();
  auto p = ring_parameters(*law);
  p.viscosity = 0.01;
  p.face_width = 0.02;
  p.crown_height = 0.01;   // R = b^2 / (8 c) = 5 mm
  p.nodes = 2001;
  MixedPistonRing ring(p, law);
  const double W = 450.0, R = p.face_width * p.face_width / (8.0 * p.crown_height);
  const auto sweep = continuum::stribeck_sweep(ring, W, 20.0, 40.0, 3);
  for (const auto &s : sweep) {
    ASSERT_EQ(s.status, continuum::RingFilmStatus::Ok);
    EXPECT_LT(s.asperity_share, 1e-12);
    EXPECT_GT(s.lambda, 15.0);
  }
  const double dlog = std::log(sweep.back().duty / sweep.front().duty);
  const double mu_exponent = std::log(sweep.back().mu / sweep.front().mu) / dlog;
  const double h_exponent = std::log(sweep.back().h_min / sweep.front().h_min) / dlog;
  const double martin = sweep.back().h_min * W / (p.viscosity * sweep.back().speed * R);
  std::printf("full film: mu exponent %.4f, h exponent %.4f, h0 W' / (eta U R) %.4f (Martin 2.448)\n", mu_exponent,
              h_exponent, martin);
  EXPECT_NEAR(mu_exponent, 0.5, 0.025);
  EXPECT_NEAR(h_exponent, 1.0, 0.05);
  EXPECT_NEAR(martin / 2.448, 1.0, 0.01);
}

// Starved inlet: the film forms from the oil layer on the liner (inlet fill 2 h_oil / h_T,in), so at one speed and
// load a thin layer carries less film (smaller h_min, more asperity load) and a layer thicker than the inlet gap
// gives the flooded result.
TEST(MixedPistonRing, StarvedInletCarriesLessFilm) {
  const auto law = steel_law();
  auto p = ring_parameters(*law);
  const MixedPistonRing flooded(p, law);
  p.supply = continuum::OilSupply::Starved;
  p.oil_film = 0.3e-6;
  const MixedPistonRing thin(p, law);
  p.oil_film = 1e-3;
  const MixedPistonRing thick(p, law);
  const double U = 2.0, W = 450.0;
  const auto a = flooded.steady(U, W, nullptr), b = thin.steady(U, W, nullptr), c = thick.steady(U, W, nullptr);
  std::printf("starved: h_min flooded %.4g, h_oil 0.3 um %.4g, h_oil 1 mm %.4g m; share %.3g, %.3g\n", a.h_min, b.h_min,
              c.h_min, a.asperity_share(), b.asperity_share());
  ASSERT_EQ(b.status, continuum::RingFilmStatus::Ok);
  EXPECT_LT(b.h_min, 0.8 * a.h_min);
  EXPECT_GT(b.asperity_share(), a.asperity_share());
  EXPECT_NEAR(c.h_min / a.h_min, 1.0, 1e-6);
}

// The run-in of the shipped ring at eta = 4 mPa s (dead centres mixed, lambda 1.9), 3e6 cycles: over the cycles the
// asperity share and R fall monotonically, mu too within the law's scatter (1e-3); R settles because the film takes
// over (share < 1 % of the first cycle's) while the worn depth is still inside the law's table.
MixedRingParameters run_in_parameters(const coupling::StateLaw &law) {
  auto p = ring_parameters(law);
  p.nodes = 41;
  p.steps_per_cycle = 180;
  return p;
}

TEST(MixedPistonRing, RunInFrictionAndAsperityShareFallUntilTheFilmTakesOver) {
  const auto law = steel_law();
  MixedPistonRing ring(run_in_parameters(*law), law);
  continuum::RunInSettings rs;
  rs.cycles = 3000000;   // 33 h at 1500 rpm: boundary-lubricated wear (k = 1e-6) runs in over millions of cycles
  std::vector<continuum::CycleSample> rows;
  const auto report = continuum::run_in(ring, rs, [&](const continuum::CycleSample &s) { rows.push_back(s); });
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_GE(rows.size(), 5u);
  double worst_rise = 0.0;   // mu may rise within the law's seed scatter of mu_body between two depths
  for (std::size_t k = 1; k < rows.size(); ++k) {
    worst_rise = std::max(worst_rise, rows[k].mu / rows[k - 1].mu - 1.0);
    EXPECT_LE(rows[k].asperity_share, rows[k - 1].asperity_share) << k;
    EXPECT_LE(rows[k].rq, rows[k - 1].rq) << k;
  }
  const auto &a = rows.front(), &b = rows.back(), &c = rows[rows.size() - 2];
  const double rate0 = (rows[0].rq - rows[1].rq) / (rows[1].cycle - rows[0].cycle);
  const double rate_end = (c.rq - b.rq) / (b.cycle - c.cycle);
  double h_max = 0.0;
  for (double h : ring.worn_depth()) h_max = std::max(h_max, h);
  EXPECT_LT(worst_rise, 1e-3);
  std::printf("run-in: %ld cycles (%ld computed): mu %.5g -> %.5g (largest rise %.3g), share %.4g -> %.4g, min lambda %.3f -> %.3f, R %.4g -> "
              "%.4g nm, dR/dcycle %.3g -> %.3g nm, h_max %.4g nm (law table ends at %.4g nm)\n",
              report.cycles, report.computed_cycles, a.mu, b.mu, worst_rise, a.asperity_share, b.asperity_share, a.min_lambda,
              b.min_lambda, 1e9 * a.rq, 1e9 * b.rq, 1e9 * rate0, 1e9 * rate_end, 1e9 * h_max,
              1e9 * law->worn_depth().back());
  EXPECT_LT(a.min_lambda, 3.0);                       // mixed at the dead centres
  EXPECT_LT(b.mu, a.mu);
  EXPECT_LT(b.asperity_share, 0.01 * a.asperity_share);   // the film carries the ring
  EXPECT_LT(rate_end, 1e-3 * rate0);                   // R has stopped changing
  EXPECT_LT(h_max, law->worn_depth().back());          // ... with the worn depth still inside the law's table
  EXPECT_NEAR(report.booked_wear_volume / ring.worn_volume(), 1.0, 1e-12);
}

// Worn summits (lubrication.worn_surface = "truncated"): the dead centres' asperities cut the face's highest summits
// until the film clears the cut. Claim 1 with R constant: share, R and mu fall at every computed cycle, the share
// ends below 1e-5 of the load, R settles (the second half of the cycles moves it by less than 1e-3), and only
// summit tops went (worn depth below 1 % of sigma). The first cycle is the Gaussian one.
TEST(MixedPistonRing, WornSummitsRunInEndsWhereTheFilmClearsTheCut) {
  const auto law = steel_law();
  auto p = run_in_parameters(*law);
  p.worn_surface = continuum::WornSurface::TruncatedSummits;
  MixedPistonRing ring(p, law), gaussian(run_in_parameters(*law), law);
  continuum::RunInSettings rs;
  rs.cycles = 3000000;
  std::vector<continuum::CycleSample> rows, gaussian_rows;
  const auto report = continuum::run_in(ring, rs, [&](const continuum::CycleSample &s) { rows.push_back(s); });
  ASSERT_TRUE(report.ok()) << report.message;
  continuum::RunInSettings one;
  one.cycles = 1;
  continuum::run_in(gaussian, one, [&](const continuum::CycleSample &s) { gaussian_rows.push_back(s); });
  ASSERT_GE(rows.size(), 5u);
  EXPECT_EQ(rows.front().mu, gaussian_rows.front().mu);
  EXPECT_EQ(rows.front().asperity_share, gaussian_rows.front().asperity_share);
  for (std::size_t k = 1; k < rows.size(); ++k) {
    EXPECT_LE(rows[k].asperity_share, rows[k - 1].asperity_share) << k;
    EXPECT_LE(rows[k].rq, rows[k - 1].rq) << k;
    EXPECT_LE(rows[k].mu, rows[k - 1].mu * (1.0 + 1e-9)) << k;
  }
  const auto &a = rows.front(), &b = rows.back();
  double rq_at_half = a.rq;
  for (const auto &r : rows)
    if (r.cycle <= rs.cycles / 2) rq_at_half = r.rq;
  double h_max = 0.0;
  for (double h : ring.worn_depth()) h_max = std::max(h_max, h);
  std::printf("worn summits: %ld cycles (%ld computed): mu %.5g -> %.5g, share %.4g -> %.4g, R %.5g -> %.5g nm "
              "(%.5g at half the cycles), h_max %.4g nm\n",
              report.cycles, report.computed_cycles, a.mu, b.mu, a.asperity_share, b.asperity_share, 1e9 * a.rq,
              1e9 * b.rq, 1e9 * rq_at_half, 1e9 * h_max);
  EXPECT_LT(b.mu, a.mu);
  EXPECT_LT(b.asperity_share, 1e-5);
  EXPECT_LT(rq_at_half - b.rq, 1e-3 * b.rq);
  EXPECT_LT(h_max, 0.01 * a.sigma);
  EXPECT_NEAR(report.booked_wear_volume / ring.worn_volume(), 1.0, 1e-12);
}

// A flat face (no wedge) rides on its asperities and wears 300 nm in its first cycle, more than half its sigma:
// not a gradual run-in at fixed geometry, so the stepper stops with a status instead of jumping.
TEST(MixedPistonRing, RunInStopsWhenOneCycleWearsMoreThanHalfSigma) {
  const auto law = severe_law();
  auto p = run_in_parameters(*law);
  p.crown_height = 0.0;
  MixedPistonRing ring(p, law);
  continuum::RunInSettings rs;
  rs.cycles = 10;
  long observed = 0;
  const auto report = continuum::run_in(ring, rs, [&](const continuum::CycleSample &) { ++observed; });
  EXPECT_EQ(report.status, continuum::RunInStatus::WearPerCycleTooLarge);
  EXPECT_NE(report.message.find("not a gradual run-in"), std::string::npos) << report.message;
  EXPECT_EQ(report.computed_cycles, 1);
  EXPECT_EQ(observed, 0);
  p.crown_height = 5e-6;   // the shipped barrel: a gradual run-in
  MixedPistonRing barrel(p, law);
  rs.cycles = 2;
  EXPECT_TRUE(continuum::run_in(barrel, rs).ok());
}

// Combined roughness: the "law" liner runs in like the ring (sigma = sqrt 2 rq), a "fixed" liner keeps its sigma.
// A gas table makes the cycle its own (720 deg) and adds factor x p_gas to the ring tension.
TEST(MixedPistonRing, LinerRoughnessAndGasLoad) {
  const auto law = steel_law();
  auto p = run_in_parameters(*law);
  const double rq0 = law->value(coupling::StateField::Rq, law->pressure().front(), 0.0);
  EXPECT_NEAR(MixedPistonRing(p, law).sigma()[5], std::sqrt(2.0) * rq0, 1e-12 * rq0);
  p.liner = continuum::LinerRoughness::Fixed;
  p.liner_sigma = 100e-9;
  EXPECT_NEAR(MixedPistonRing(p, law).sigma()[5], std::hypot(rq0, 100e-9), 1e-12 * rq0);
  p.liner = continuum::LinerRoughness::Law;
  p.gas.crank_angle = {0.0, kPi, 2.0 * kPi};
  p.gas.pressure = {1e6, 0.1e6, 0.1e6};
  p.gas.cycle = 4.0 * kPi;
  p.gas.factor = 0.2;
  MixedPistonRing ring(p, law);
  EXPECT_DOUBLE_EQ(p.load_per_length(0.0), (0.3e6 + 0.2e6) * p.face_width);
  EXPECT_DOUBLE_EQ(p.period(), 4.0 * kPi / p.crank_speed);
  continuum::FaceState state;
  std::string message;
  ASSERT_EQ(ring.start(state, message), continuum::RingFilmStatus::Ok) << message;
  const auto c = ring.cycle(state, true);
  ASSERT_TRUE(c.ok()) << c.message;
  ASSERT_EQ(c.curve.size(), static_cast<std::size_t>(p.steps_per_cycle));
  EXPECT_NEAR(c.curve.back().crank_angle, 4.0 * kPi, 1e-12);
  // two revolutions, 4 stroke lengths (rectangle rule of |U| dt over 4 deg steps: 4e-4 relative)
  EXPECT_NEAR(c.sliding_distance, 8.0 * p.crank.crank_radius, 1e-3 * 8.0 * p.crank.crank_radius);
  EXPECT_NEAR(c.curve.front().load, p.load_per_length(c.curve.front().crank_angle) * p.circumference(), 1e-9);
}

// Cycle jumping against every cycle computed over 16 cycles of the same run-in.
TEST(MixedPistonRing, CycleJumpingMatchesEveryCycleComputed) {
  const auto law = severe_law();
  auto run = [&](bool jumping, std::vector<continuum::CycleSample> &rows) {
    MixedPistonRing ring(run_in_parameters(*law), law);
    continuum::RunInSettings rs;
    rs.cycles = 16;
    rs.jumping = jumping;
    const auto report = continuum::run_in(ring, rs, [&](const continuum::CycleSample &s) { rows.push_back(s); });
    EXPECT_TRUE(report.ok()) << report.message;
    EXPECT_NEAR(report.booked_wear_volume / ring.worn_volume(), 1.0, 1e-12);
    return std::make_pair(ring.worn_volume(), report.computed_cycles);
  };
  std::vector<continuum::CycleSample> every, jumped;
  const auto [v_every, n_every] = run(false, every);
  const auto [v_jumped, n_jumped] = run(true, jumped);
  const double dv = v_jumped / v_every - 1.0, dmu = jumped.back().mu / every.back().mu - 1.0;
  const double dshare = jumped.back().asperity_share / every.back().asperity_share - 1.0;
  std::printf("jumping: %ld vs %ld computed cycles; worn volume %.6g vs %.6g m^3 (%.3g), final mu %.3g, share %.3g\n",
              n_jumped, n_every, v_jumped, v_every, dv, dmu, dshare);
  EXPECT_EQ(n_every, 16);
  EXPECT_LT(n_jumped, 10);
  EXPECT_LT(std::abs(dv), 0.05);
  EXPECT_LT(std::abs(dmu), 1e-3);
}

// A run whose jumps stay at one cycle (here: jumping off) stops at the cap on computed cycles with a status naming
// the jump fractions, instead of computing every one of millions of cycles (the CLI's 1e-300 jump fraction did).
TEST(MixedPistonRing, RunInStopsAtTheCapOnComputedCycles) {
  const auto law = severe_law();
  MixedPistonRing ring(run_in_parameters(*law), law);
  continuum::RunInSettings rs;
  rs.cycles = 1000000;
  rs.jumping = false;
  rs.max_computed_cycles = 3;
  long observed = 0;
  const auto report = continuum::run_in(ring, rs, [&](const continuum::CycleSample &) { ++observed; });
  EXPECT_EQ(report.status, continuum::RunInStatus::TooManyCycles);
  EXPECT_EQ(report.computed_cycles, 3);
  EXPECT_EQ(report.cycles, 3);
  EXPECT_EQ(observed, 3);
  EXPECT_NE(report.message.find("jump fractions"), std::string::npos) << report.message;
}

}  // namespace
