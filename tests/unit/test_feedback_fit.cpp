// Fit of the ch. 3 feedback model to a run-in series (coupling/feedback_fit.h): round trips from the exact
// solution, seeded 1 % noise, laws the model cannot fit, degenerate data; the CSV reader it is fed by.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "coupling/csv_table.h"
#include "coupling/feedback_fit.h"
#include "tribo/feedback.h"

using namespace runin::coupling;
using runin::tribo::FeedbackCoefficients;
using runin::tribo::FeedbackKind;
using runin::tribo::FeedbackModel;

namespace {
// inputs/feedback_lubricated.toml (R0 = 6, 8000 s) and inputs/feedback_dry.toml (R0 = 0.5, 5000 s).
FeedbackCoefficients lubricated() { return {0.02, 0.08, 1e-3, 4e-3, 1.0, 1.0}; }
FeedbackCoefficients dry() { return {0.05, 0.2, 2e-3, 2e-3, 1.0, 2.0}; }

// Series from the exact solution on t = t0 + i dt, i = 0..n-1.
FeedbackSeries exact_series(const FeedbackModel &m, double r0, double t0, double dt, int n) {
  FeedbackSeries s;
  for (int i = 0; i < n; ++i) {
    const double t = t0 + dt * i;
    const double R = m.exact_roughness(r0, t - t0);
    s.t.push_back(t);
    s.R.push_back(R);
    s.mu.push_back(m.mu(R));
  }
  return s;
}

void add_noise(FeedbackSeries &s, double relative, unsigned seed) {
  std::mt19937 engine(seed);
  std::normal_distribution<double> noise(0.0, relative);
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    s.R[i] *= 1.0 + noise(engine);
    s.mu[i] *= 1.0 + noise(engine);
  }
}

void expect_relative(double actual, double expected, double tolerance, const char *what) {
  EXPECT_LE(std::abs(actual - expected), tolerance * std::abs(expected))
      << what << ": fitted " << actual << ", expected " << expected;
}

void expect_constants(const FeedbackFitResult &f, const FeedbackCoefficients &c, double r0, double tolerance) {
  ASSERT_TRUE(f.ok()) << to_string(f.status) << ": " << f.message;
  const double a = c.A * c.K1, bk2 = c.B * c.K2;
  expect_relative(f.R0, r0, tolerance, "R0");
  expect_relative(f.R_star, std::sqrt(bk2 / a), tolerance, "R*");
  expect_relative(f.rate, a, tolerance, "A K1");
  expect_relative(f.B_K2, bk2, tolerance, "B K2");
  expect_relative(f.C1, c.C1, tolerance, "C1");
  expect_relative(f.C2, c.C2, tolerance, "C2");
  // Written with A = B = 1: only the products are identified.
  const auto &k = f.model->coefficients();
  EXPECT_EQ(k.A, 1.0);
  EXPECT_EQ(k.B, 1.0);
  EXPECT_EQ(k.K1, f.rate);
  EXPECT_EQ(k.K2, f.B_K2);
}

FeedbackFitStatus status_of(const FeedbackSeries &s) { return fit_feedback(s).status; }
}  // namespace

TEST(FeedbackFit, RoundTripLubricatedExact) {
  const FeedbackModel m(lubricated());
  const auto f = fit_feedback(exact_series(m, 6.0, 0.0, 40.0, 201));
  expect_constants(f, lubricated(), 6.0, 1e-6);
  EXPECT_LE(f.R_max_rel_error, 1e-8);
  EXPECT_LE(f.mu_max_rel_error, 1e-8);
  EXPECT_LE(f.mu_of_R_max_rel_error, 1e-8);
  EXPECT_FALSE(f.C2_clamped);
}

TEST(FeedbackFit, RoundTripDryExactFromBelowWithOffset) {
  // R0 below R*, data starting at t = 1000: t0 is subtracted, R0 is R at the first point.
  const FeedbackModel m(dry(), FeedbackKind::dry);
  FeedbackFitOptions o;
  o.kind = FeedbackKind::dry;
  const auto f = fit_feedback(exact_series(m, 0.5, 1000.0, 25.0, 201), o);
  expect_constants(f, dry(), 0.5, 1e-6);
  EXPECT_EQ(f.t0, 1000.0);
  EXPECT_EQ(f.model->kind(), FeedbackKind::dry);
  EXPECT_NEAR(fitted_roughness(f, 1000.0), 0.5, 1e-7);
  EXPECT_NEAR(fitted_mu(f, 1000.0 + 300.0), m.mu(m.exact_roughness(0.5, 300.0)), 1e-8);
}

TEST(FeedbackFit, OnlyProductsAreIdentified) {
  // A = 4, K1 = 2.5e-4 and B = 0.5, K2 = 8e-3 give the data of the lubricated case: the same fit.
  FeedbackCoefficients c = lubricated();
  c.A = 4.0, c.K1 = 2.5e-4, c.B = 0.5, c.K2 = 8e-3;
  const auto f = fit_feedback(exact_series(FeedbackModel(c), 6.0, 0.0, 40.0, 201));
  expect_constants(f, lubricated(), 6.0, 1e-6);
}

TEST(FeedbackFit, OnePercentNoiseWithinAFewPercent) {
  for (unsigned seed : {1u, 2u, 3u}) {
    FeedbackSeries lub = exact_series(FeedbackModel(lubricated()), 6.0, 0.0, 40.0, 201);
    add_noise(lub, 0.01, seed);
    const auto f = fit_feedback(lub);
    expect_constants(f, lubricated(), 6.0, 0.03);
    EXPECT_NEAR(f.R_rms_rel_error, 0.01, 0.003);  // the noise, not a model error
    EXPECT_NEAR(f.mu_rms_rel_error, 0.01, 0.003);

    FeedbackSeries d = exact_series(FeedbackModel(dry(), FeedbackKind::dry), 0.5, 0.0, 25.0, 201);
    add_noise(d, 0.01, seed + 10);
    expect_constants(fit_feedback(d), dry(), 0.5, 0.03);
  }
}

TEST(FeedbackFit, DecayToZeroIsNoEquilibrium) {
  // R = R0 exp(-t/tau): R^2 relaxes, but towards 0; mu from the lubricated mu(R).
  const FeedbackModel m(lubricated());
  for (double noise : {0.0, 0.01}) {
    FeedbackSeries s;
    for (int i = 0; i < 201; ++i) {
      const double t = 40.0 * i, R = 6.0 * std::exp(-t / 2000.0);
      s.t.push_back(t), s.R.push_back(R), s.mu.push_back(m.mu(R));
    }
    if (noise > 0.0) add_noise(s, noise, 7);
    const auto f = fit_feedback(s);
    EXPECT_EQ(f.status, FeedbackFitStatus::NoEquilibrium) << noise << ": " << f.message;
    EXPECT_FALSE(f.model.has_value());
    EXPECT_NE(f.message.find("R*^2"), std::string::npos) << f.message;
  }
}

TEST(FeedbackFit, OvershootIsPoorFit) {
  // R overshoots R* = 2 and comes back: the model's R never crosses R*.
  const FeedbackModel m(lubricated());
  FeedbackSeries s;
  for (int i = 0; i < 201; ++i) {
    const double t = 40.0 * i, R = 2.0 + 4.0 * std::exp(-t / 1500.0) * std::cos(t / 800.0);
    s.t.push_back(t), s.R.push_back(R), s.mu.push_back(m.mu(R));
  }
  const auto f = fit_feedback(s);
  EXPECT_EQ(f.status, FeedbackFitStatus::PoorFit) << f.message;
  EXPECT_GT(f.R_rms_rel_error, 0.05);
}

TEST(FeedbackFit, LinearGrowthIsNoEquilibrium) {
  // R^2 grows linearly without levelling off (the model's limit A K1 -> 0, R* -> infinity): R* is not
  // determined by the data.
  const FeedbackModel m(lubricated());
  FeedbackSeries s;
  for (int i = 0; i < 101; ++i) {
    const double t = 10.0 * i, R = std::sqrt(1.0 + 0.02 * t);
    s.t.push_back(t), s.R.push_back(R), s.mu.push_back(m.mu(R));
  }
  add_noise(s, 0.01, 11);
  const auto f = fit_feedback(s);
  EXPECT_EQ(f.status, FeedbackFitStatus::NoEquilibrium) << f.message;
  EXPECT_LE(f.R_rms_rel_error, 0.02);  // fitted well, but without an equilibrium
}

TEST(FeedbackFit, NoisyConstantRoughnessIsNoRunIn) {
  // R = 2 with 1 % noise: R* is well determined, the rate is not (it would fit the noise).
  const FeedbackModel m(lubricated());
  FeedbackSeries s;
  for (int i = 0; i < 201; ++i) {
    s.t.push_back(40.0 * i), s.R.push_back(2.0), s.mu.push_back(m.mu(2.0));
  }
  add_noise(s, 0.01, 5);
  const auto f = fit_feedback(s);
  EXPECT_EQ(f.status, FeedbackFitStatus::NoRunIn) << f.message;
  EXPECT_NE(f.message.find("is not determined"), std::string::npos) << f.message;
}

TEST(FeedbackFit, FrictionFallingWithRoughnessHasNoMinimum) {
  FeedbackSeries s = exact_series(FeedbackModel(lubricated()), 6.0, 0.0, 40.0, 101);
  // C1 = -0.01: mu falls as R grows, so there is no friction minimum
  for (std::size_t i = 0; i < s.t.size(); ++i) s.mu[i] = 0.5 / s.R[i] - 0.01 * s.R[i];
  EXPECT_EQ(status_of(s), FeedbackFitStatus::NoFrictionMinimum);
}

TEST(FeedbackFit, NegativeC2IsClampedToZero) {
  FeedbackSeries s = exact_series(FeedbackModel(lubricated()), 6.0, 0.0, 40.0, 201);
  for (std::size_t i = 0; i < s.t.size(); ++i) s.mu[i] = 0.05 * s.R[i] - 0.01 / s.R[i];
  FeedbackFitOptions o;
  o.max_rms_relative_error = 1.0;  // judge the constants, not the misfit
  const auto f = fit_feedback(s, o);
  ASSERT_TRUE(f.ok()) << f.message;
  EXPECT_TRUE(f.C2_clamped);
  EXPECT_EQ(f.C2, 0.0);
  EXPECT_GT(f.C1, 0.0);
}

TEST(FeedbackFit, DegenerateDataNamesTheColumnAndRow) {
  const FeedbackSeries good = exact_series(FeedbackModel(lubricated()), 6.0, 0.0, 40.0, 20);
  auto named = good;
  named.t_name = "time_s", named.mu_name = "mu_body", named.R_name = "Ra";

  auto few = named;
  for (auto *v : {&few.t, &few.mu, &few.R}) v->resize(5);
  EXPECT_TRUE(fit_feedback(few).ok()) << fit_feedback(few).message;  // 5 rows suffice for exact data
  for (auto *v : {&few.t, &few.mu, &few.R}) v->resize(4);
  auto f = fit_feedback(few);
  EXPECT_EQ(f.status, FeedbackFitStatus::TooFewPoints);
  EXPECT_NE(f.message.find("4 rows; the fit needs at least 5"), std::string::npos) << f.message;

  auto nan = named;
  nan.mu[3] = std::nan("");
  f = fit_feedback(nan);
  EXPECT_EQ(f.status, FeedbackFitStatus::NonFinite);
  EXPECT_NE(f.message.find("column 'mu_body', row 4"), std::string::npos) << f.message;

  auto back = named;
  back.t[5] = back.t[4];
  f = fit_feedback(back);
  EXPECT_EQ(f.status, FeedbackFitStatus::TimeNotIncreasing);
  EXPECT_NE(f.message.find("column 'time_s', row 6"), std::string::npos) << f.message;

  auto zero = named;
  zero.R[7] = 0.0;
  f = fit_feedback(zero);
  EXPECT_EQ(f.status, FeedbackFitStatus::NonPositive);
  EXPECT_NE(f.message.find("column 'Ra', row 8"), std::string::npos) << f.message;

  auto flat = named;
  for (auto &r : flat.R) r = 2.0;
  f = fit_feedback(flat);
  EXPECT_EQ(f.status, FeedbackFitStatus::ConstantRoughness);
  EXPECT_NE(f.message.find("column 'Ra' is constant"), std::string::npos) << f.message;

  auto ragged = named;
  ragged.mu.pop_back();
  EXPECT_EQ(status_of(ragged), FeedbackFitStatus::TooFewPoints);
}

TEST(CsvTable, NamedColumnsCommentsAndErrors) {
  std::istringstream in("\xEF\xBB\xBF# produced by a test\n"
                        "\"t\", mu ,R,note\r\n0,0.5,6,start\n\n1,+0.4,5e0,x\n# trailing comment\n2,nan,4,y\n");
  const CsvTable t = parse_csv_table(in, "data.csv");
  EXPECT_EQ(t.column_names(), (std::vector<std::string>{"t", "mu", "R", "note"}));
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.numbers("R"), (std::vector<double>{6.0, 5.0, 4.0}));
  EXPECT_EQ(t.numbers("mu")[1], 0.4);
  EXPECT_TRUE(std::isnan(t.numbers("mu")[2]));  // the caller names non-finite values
  EXPECT_EQ(t.line_of(2), 7u);
  try {
    t.numbers("Ra");
    FAIL() << "no throw";
  } catch (const InputFormatError &e) {
    EXPECT_STREQ(e.what(), "data.csv: no column 'Ra' (columns: t, mu, R, note)");
  }
  try {
    t.numbers("note");
    FAIL() << "no throw";
  } catch (const InputFormatError &e) {
    EXPECT_STREQ(e.what(), "data.csv:3: column 'note': 'start' is not a number");
  }
  std::istringstream ragged("t,mu\n1,2\n3\n");
  EXPECT_THROW(parse_csv_table(ragged, "r.csv"), InputFormatError);
  std::istringstream twice("t,t\n1,2\n");
  EXPECT_THROW(parse_csv_table(twice, "d.csv"), InputFormatError);
  std::istringstream header_only("t,mu\n");
  EXPECT_THROW(parse_csv_table(header_only, "h.csv"), InputFormatError);
}
