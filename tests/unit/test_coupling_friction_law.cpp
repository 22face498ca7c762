// Friction laws mu(s): interpolation, run-in fit, law-file round trip.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/friction_law.h"

using namespace runin::coupling;

namespace {
// Spring loading to the peak, then the exact run-in form.
TabulatedLaw synthetic_run_in(double mu_0, double mu_ss, double s0, double s_peak, double s_end, int points) {
  std::vector<double> s, mu;
  for (int i = 0; i < points; ++i) {
    const double x = s_end * i / (points - 1);
    s.push_back(x);
    mu.push_back(x < s_peak ? mu_0 * x / s_peak : mu_ss + (mu_0 - mu_ss) * std::exp(-(x - s_peak) / s0));
  }
  return TabulatedLaw(s, mu);
}
}  // namespace

TEST(CouplingFrictionLaw, InterpolationIsExactAtNodesLinearBetweenClampedOutside) {
  const TabulatedLaw law({0.0, 1.0, 3.0}, {0.2, 0.8, 0.5});
  EXPECT_EQ(law(0.0), 0.2);
  EXPECT_EQ(law(1.0), 0.8);
  EXPECT_EQ(law(3.0), 0.5);
  EXPECT_NEAR(law(0.25), 0.2 + 0.25 * 0.6, 1e-15);
  EXPECT_NEAR(law(2.0), 0.65, 1e-15);
  EXPECT_EQ(law(-1.0), 0.2);
  EXPECT_EQ(law(10.0), 0.5);
  EXPECT_EQ(law.peak_index(), 1u);
  EXPECT_THROW(TabulatedLaw({0.0, 0.0}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(TabulatedLaw({0.0}, {1.0}), std::invalid_argument);
}

TEST(CouplingFrictionLaw, FitRecoversExactSyntheticParameters) {
  // Micro-scale SI distances (1e-7 m) and Angstrom-sized numbers (1e3) give the same relative accuracy.
  for (const double unit : {1e-9, 1.0, 1e3}) {
    const double mu_0 = 0.72, mu_ss = 0.38, s0 = 250 * unit, s_peak = 100 * unit;
    const auto result = fit_run_in(synthetic_run_in(mu_0, mu_ss, s0, s_peak, 2000 * unit, 201));
    ASSERT_EQ(result.status, FitStatus::Converged) << result.message;
    EXPECT_NEAR(result.fit.mu_0 / mu_0, 1.0, 1e-6);
    EXPECT_NEAR(result.fit.mu_ss / mu_ss, 1.0, 1e-6);
    EXPECT_NEAR(result.fit.s0 / s0, 1.0, 1e-6);
    EXPECT_DOUBLE_EQ(result.fit.s_peak, s_peak);
    EXPECT_LT(result.fit.rms_residual, 1e-9);
    EXPECT_EQ(result.fit.points, 191u);
  }
}

TEST(CouplingFrictionLaw, FitReportsWhyItCannotFit) {
  EXPECT_EQ(fit_run_in(TabulatedLaw({0, 1, 2, 3}, {0.1, 0.2, 0.3, 0.4})).status, FitStatus::TooFewPoints);
  EXPECT_EQ(fit_run_in(TabulatedLaw({0, 1, 2, 3, 4, 5}, {0.5, 0.5, 0.5, 0.5, 0.5, 0.5})).status,
            FitStatus::NoDecay);
}

TEST(CouplingFrictionLaw, FitBranchUsesTableBeforePeakAndFitAfter) {
  const auto table = synthetic_run_in(0.7, 0.4, 3e-7, 1e-7, 2e-6, 101);
  FrictionLaw law{"fric.txt", "v_slide", "c_fric[3]", "m", 1.0, table, fit_run_in(table).fit};
  EXPECT_EQ(law.evaluate(0.5e-7, FrictionLaw::Branch::Fit), table(0.5e-7));
  EXPECT_EQ(law.evaluate(7.7e-7, FrictionLaw::Branch::Fit), (*law.fit)(7.7e-7));
  EXPECT_EQ(law.evaluate(7.7e-7, FrictionLaw::Branch::Table), table(7.7e-7));
}

TEST(CouplingFrictionLaw, JsonRoundTripIsExact) {
  const auto table = synthetic_run_in(0.7, 0.4, 3e-7, 1e-7, 2e-6, 57);
  const FrictionLaw law{"fric.txt", "v_slide", "c_fric[3]", "nm", 1e-9, table, fit_run_in(table).fit};
  ASSERT_TRUE(law.fit.has_value());
  const FrictionLaw back = law_from_json_text(law_to_json_text(law), "law.json");
  EXPECT_EQ(back.source_file, law.source_file);
  EXPECT_EQ(back.distance_column, law.distance_column);
  EXPECT_EQ(back.mu_column, law.mu_column);
  EXPECT_EQ(back.distance_unit, "nm");
  EXPECT_EQ(back.distance_unit_in_m, 1e-9);
  EXPECT_EQ(back.table.distance(), law.table.distance());
  EXPECT_EQ(back.table.mu(), law.table.mu());
  ASSERT_TRUE(back.fit.has_value());
  EXPECT_EQ(back.fit->mu_0, law.fit->mu_0);
  EXPECT_EQ(back.fit->mu_ss, law.fit->mu_ss);
  EXPECT_EQ(back.fit->s0, law.fit->s0);
  EXPECT_EQ(back.fit->s_peak, law.fit->s_peak);
  EXPECT_EQ(back.fit->rms_residual, law.fit->rms_residual);
  EXPECT_EQ(back.fit->points, law.fit->points);

  FrictionLaw no_fit = law;
  no_fit.fit.reset();
  EXPECT_FALSE(law_from_json_text(law_to_json_text(no_fit), "law.json").fit.has_value());
}

TEST(CouplingFrictionLaw, BadLawFileNamesTheFile) {
  try {
    law_from_json_text(R"({"format": "runin-friction-law", "version": 1})", "law.json");
    FAIL() << "accepted a law file without a table";
  } catch (const InputFormatError &e) {
    EXPECT_EQ(std::string(e.what()).rfind("law.json: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(law_from_json_text("{ not json", "law.json"), InputFormatError);
}
