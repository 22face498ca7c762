// Two-mechanism roughness-feedback model (thesis ch. 3): kernel identities at round-off,
// CVODE R(t) against the closed form R(t)^2 = R*^2 + (R0^2 - R*^2) exp(-2 A K1 t).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "continuum/feedback_system.h"
#include "tribo/feedback.h"

using runin::tribo::FeedbackCoefficients;
using runin::tribo::FeedbackKind;
using runin::tribo::FeedbackModel;
using runin::tribo::InvalidCoefficient;
using namespace runin::continuum;

namespace {
// inputs/feedback_lubricated.toml: R* = R_min_wear = R_min_friction = 2.
FeedbackCoefficients lubricated() { return {0.02, 0.08, 1e-3, 4e-3, 1.0, 1.0}; }
// inputs/feedback_dry.toml: R* = sqrt(2), R_min_wear = 1, R_min_friction = 2.
FeedbackCoefficients dry() { return {0.05, 0.2, 2e-3, 2e-3, 1.0, 2.0}; }

std::vector<FeedbackSample> run(const FeedbackModel &model, double r0, double t_end, double interval,
                                FeedbackReport *report_out = nullptr) {
  FeedbackRun r;
  r.initial_roughness = r0;
  r.t_end = t_end;
  r.output_interval = interval;  // FeedbackRun's default CVODE settings
  std::vector<FeedbackSample> samples;
  const auto report = simulate(FeedbackSystem(model), r, [&](const FeedbackSample &s) { samples.push_back(s); });
  EXPECT_TRUE(report.ok()) << report.message;
  if (report_out) *report_out = report;
  return samples;
}

std::string message_of(const FeedbackCoefficients &c) {
  try {
    FeedbackModel m(c);
  } catch (const InvalidCoefficient &e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(FeedbackModel, ClosedFormRoughnesses) {
  const FeedbackModel m(dry(), FeedbackKind::dry);
  EXPECT_DOUBLE_EQ(m.stationary_roughness(), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(m.min_wear_roughness(), 1.0);
  EXPECT_DOUBLE_EQ(m.min_friction_roughness(), 2.0);
  EXPECT_DOUBLE_EQ(m.min_mu(), m.mu(2.0));
  EXPECT_DOUBLE_EQ(m.min_k(), m.k(1.0));
  EXPECT_FALSE(m.stationary_minimises_wear());
  EXPECT_FALSE(m.stationary_minimises_friction());
  EXPECT_EQ(m.thesis_name("K2"), "K_adh");
  const FeedbackModel l(lubricated());
  EXPECT_TRUE(l.stationary_minimises_wear());
  EXPECT_TRUE(l.stationary_minimises_friction());
  EXPECT_EQ(l.thesis_name("C1"), "C_vis");
}

TEST(FeedbackModel, StationaryRoughnessIsFixedPoint) {
  for (const auto &c : {lubricated(), dry(), FeedbackCoefficients{3.0, 0.7, 0.37, 5.3, 0.11, 2.9}}) {
    const FeedbackModel m(c);
    const double rs = m.stationary_roughness();
    // Each term is ~A K1 R*; the difference must vanish to a few ulps of that.
    const double scale = c.A * c.K1 * rs;
    EXPECT_LE(std::abs(m.dRdt(rs)), 4.0 * std::numeric_limits<double>::epsilon() * scale);
    EXPECT_LT(m.dRdt(rs * 1.01), 0.0);  // stable: pushes back from both sides
    EXPECT_GT(m.dRdt(rs * 0.99), 0.0);
  }
}

TEST(FeedbackModel, MinimaOfWearAndFriction) {
  for (const auto &c : {lubricated(), dry(), FeedbackCoefficients{3.0, 0.7, 0.37, 5.3, 0.11, 2.9}}) {
    const FeedbackModel m(c);
    // Analytic derivatives of mu and k at the claimed minimisers.
    const double rw = m.min_wear_roughness(), rf = m.min_friction_roughness();
    const double dk = c.K1 - c.K2 / (rw * rw), d2k = 2.0 * c.K2 / (rw * rw * rw);
    const double dmu = c.C1 - c.C2 / (rf * rf), d2mu = 2.0 * c.C2 / (rf * rf * rf);
    EXPECT_LE(std::abs(dk), 4.0 * std::numeric_limits<double>::epsilon() * c.K1);
    EXPECT_LE(std::abs(dmu), 4.0 * std::numeric_limits<double>::epsilon() * c.C1);
    EXPECT_GT(d2k, 0.0);
    EXPECT_GT(d2mu, 0.0);
    // And they are minima of the functions themselves, not just of the formulas above.
    for (double f : {0.9, 0.99, 1.01, 1.1}) {
      EXPECT_GT(m.k(rw * f), m.k(rw));
      EXPECT_GT(m.mu(rf * f), m.mu(rf));
    }
  }
}

TEST(FeedbackModel, InvalidCoefficientsNameTheCoefficient) {
  struct Case {
    FeedbackCoefficients c;
    std::string name;
  };
  auto with = [](double FeedbackCoefficients::*field, double v) {
    FeedbackCoefficients c = lubricated();
    c.*field = v;
    return c;
  };
  const std::vector<Case> cases = {
      {with(&FeedbackCoefficients::C1, -1.0), "C1"}, {with(&FeedbackCoefficients::C2, -0.1), "C2"},
      {with(&FeedbackCoefficients::K1, -1.0), "K1"}, {with(&FeedbackCoefficients::K2, -1.0), "K2"},
      {with(&FeedbackCoefficients::A, -1.0), "A"},   {with(&FeedbackCoefficients::B, -1.0), "B"},
      {with(&FeedbackCoefficients::A, 0.0), "A"},    {with(&FeedbackCoefficients::K1, 0.0), "K1"},
      {with(&FeedbackCoefficients::C1, 0.0), "C1"},  {with(&FeedbackCoefficients::B, 0.0), "B"},
      {with(&FeedbackCoefficients::K2, NAN), "K2"},
  };
  for (const auto &k : cases) {
    const std::string what = message_of(k.c);
    EXPECT_NE(what.find("coefficient " + k.name + " "), std::string::npos) << k.name << ": '" << what << "'";
  }
  EXPECT_NO_THROW(FeedbackModel(with(&FeedbackCoefficients::C2, 0.0)));  // no roughening friction: allowed
}

TEST(FeedbackSystem, CvodeMatchesClosedFormAboveAndBelowStationary) {
  for (const auto &c : {lubricated(), dry()}) {
    const FeedbackModel m(c);
    const double rs = m.stationary_roughness();
    for (double r0 : {3.0 * rs, 0.25 * rs}) {
      const double t_end = 12.0 / m.relaxation_rate();
      const auto samples = run(m, r0, t_end, t_end / 600.0);
      ASSERT_EQ(samples.size(), 601u);
      EXPECT_DOUBLE_EQ(samples.back().t, t_end);
      double worst = 0.0;
      for (const auto &s : samples)
        worst = std::max(worst, std::abs(s.roughness / m.exact_roughness(r0, s.t) - 1.0));
      EXPECT_LT(worst, 1e-8) << "R0 = " << r0;
    }
  }
}

TEST(FeedbackSystem, WearIsIntegralOfWearRate) {
  const FeedbackModel m(dry());
  const double r0 = 4.0, t_end = 2000.0;
  const auto samples = run(m, r0, t_end, 1.0);
  // Composite Simpson on the closed-form R(t), 20000 panels.
  const int n = 20000;
  const double h = t_end / n;
  double sum = m.k(m.exact_roughness(r0, 0.0)) + m.k(m.exact_roughness(r0, t_end));
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * m.k(m.exact_roughness(r0, i * h));
  const double expected = sum * h / 3.0;
  EXPECT_NEAR(samples.back().wear / expected, 1.0, 1e-7);
  for (std::size_t i = 1; i < samples.size(); ++i) ASSERT_GT(samples[i].wear, samples[i - 1].wear);
}

// Thesis claim 1 (Figs. 3.3/3.4): from R0 > R*, mu(t) falls and settles at mu(R*).
TEST(FeedbackSystem, FrictionFallsToItsStationaryValue) {
  // Generic coefficients: R* = sqrt(2) lies above R_min_friction = 1, so mu falls monotonically from R0 > R*.
  const FeedbackModel m({0.5, 0.5, 1e-3, 2e-3, 1.0, 1.0});
  const double rs = m.stationary_roughness();
  const auto samples = run(m, 5.0, 15.0 / m.relaxation_rate(), 10.0);
  for (std::size_t i = 1; i < samples.size(); ++i) ASSERT_LE(samples[i].mu, samples[i - 1].mu) << i;
  EXPECT_NEAR(samples.back().mu / m.mu(rs), 1.0, 1e-6);

  // K2/K1 == C2/C1 and A == B: the final mu is the global minimum of mu.
  const FeedbackModel opt(lubricated());
  ASSERT_TRUE(opt.stationary_minimises_friction());
  const auto best = run(opt, 6.0, 25.0 / opt.relaxation_rate(), 50.0);
  for (std::size_t i = 1; i < best.size(); ++i) ASSERT_LE(best[i].mu, best[i - 1].mu * (1.0 + 1e-13)) << i;  // flat at the minimum
  EXPECT_NEAR(best.back().mu, opt.min_mu(), 1e-8 * opt.min_mu());
  EXPECT_NEAR(best.back().mu, 2.0 * std::sqrt(0.02 * 0.08), 1e-8 * opt.min_mu());
}

TEST(FeedbackSystem, SettlingTimeMatchesClosedForm) {
  const FeedbackModel m(lubricated());
  const double interval = 0.05;
  for (double r0 : {6.0, 0.5}) {
    const auto samples = run(m, r0, 6000.0, interval);
    const double exact = m.exact_settling_time(r0, 0.01);
    const double measured = settling_time(samples, m.stationary_roughness(), 0.01);
    EXPECT_GE(measured, exact - 1e-9);
    EXPECT_LE(measured, exact + interval + 1e-9);
  }
  EXPECT_EQ(m.exact_settling_time(2.001, 0.01), 0.0);
}

TEST(FeedbackSystem, BadRunSettingsThrow) {
  const FeedbackSystem system{FeedbackModel(lubricated())};
  FeedbackRun r;
  r.initial_roughness = -1.0;
  r.t_end = 1.0;
  r.output_interval = 0.1;
  EXPECT_THROW(simulate(system, r, [](const FeedbackSample &) {}), std::invalid_argument);
}
