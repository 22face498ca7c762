// runin homogenise: one sample's cell output on the state law's worn-depth grid (src/coupling/homogenise_curves.h).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "coupling/homogenise_curves.h"

namespace {

using runin::coupling::CellSeries;
using runin::coupling::depth_grid;
using runin::coupling::resample_on_depth_grid;
using runin::coupling::StateField;

const std::vector<double> &field(const runin::coupling::DepthCurves &c, StateField f) {
  return c.field[static_cast<std::size_t>(f)];
}

// Loading rows (s = 0), then h = a s, mu = 0.2 + 10 h / depth-ish, counterface at half the rate.
CellSeries linear_cell(double a, double rows, double ds) {
  CellSeries c;
  for (int i = 0; i < 3; ++i) {
    c.s.push_back(0.0), c.h.push_back(0.0), c.h_cf.push_back(0.0), c.mu_body.push_back(0.0);
    c.rq.push_back(2e-7), c.rsk.push_back(0.0), c.area_fraction.push_back(0.001);
  }
  for (int i = 1; i <= rows; ++i) {
    const double s = i * ds, h = a * s;
    c.s.push_back(s), c.h.push_back(h), c.h_cf.push_back(0.5 * h), c.mu_body.push_back(0.2 + 1e8 * h);
    c.rq.push_back(2e-7 - h), c.rsk.push_back(-1e7 * h), c.area_fraction.push_back(0.01 + 1e6 * h);
  }
  return c;
}

TEST(HomogeniseCurves, LinearWearGivesExactRatesAndPhysicalDistance) {
  const double a = 1e-3, accel = 50.0;  // cell h = 1e-3 s
  const auto grid = depth_grid(2e-9, 5);
  ASSERT_EQ(grid.size(), 5u);
  EXPECT_EQ(grid.back(), 2e-9);
  const auto c = resample_on_depth_grid(linear_cell(a, 100, 1e-7), grid, accel);  // reaches h = 1e-8
  for (std::size_t j = 0; j < grid.size(); ++j) {
    EXPECT_NEAR(field(c, StateField::WearRate)[j], a / accel, 1e-12 * a);
    EXPECT_NEAR(field(c, StateField::CounterfaceWearRate)[j], 0.5 * a / accel, 1e-12 * a);
    // the distance is exact from h = 0 on (it runs from the end of loading, s = h = 0)
    EXPECT_NEAR(field(c, StateField::SlidingDistance)[j], grid[j] / a * accel, 1e-9 * grid[j] / a * accel + 1e-20);
    if (j == 0) continue;  // below the first sliding row: that row's values
    EXPECT_NEAR(field(c, StateField::MuBody)[j], 0.2 + 1e8 * grid[j], 1e-12);
    EXPECT_NEAR(field(c, StateField::Rq)[j], 2e-7 - grid[j], 1e-20);
  }
  // h = 0: the state when sliding begins (the first row with s > 0), not the loading rows
  EXPECT_NEAR(field(c, StateField::MuBody)[0], 0.2 + 1e8 * a * 1e-7, 1e-12);
  EXPECT_EQ(field(c, StateField::SlidingDistance)[0], 0.0);
}

TEST(HomogeniseCurves, GeometricGridResolvesTheFirstNanometresAndKeepsLinearFieldsExact) {
  const auto grid = depth_grid(1e-7, 6, 1e-9);  // 0, then 1, 3.16, 10, 31.6, 100 nm
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid[0], 0.0);
  EXPECT_DOUBLE_EQ(grid[1], 1e-9);
  EXPECT_NEAR(grid[3], 1e-8, 1e-20);
  EXPECT_EQ(grid.back(), 1e-7);
  for (std::size_t j = 2; j < grid.size(); ++j) EXPECT_NEAR(grid[j] / grid[j - 1], std::sqrt(10.0), 1e-12);
  // a cell whose fields are linear in h: every field exact on the uneven grid (the windows follow the local steps)
  const double a = 1e-3;
  const auto c = resample_on_depth_grid(linear_cell(a, 2000, 1e-7), grid, 1.0);  // reaches h = 2e-7
  for (std::size_t j = 1; j < grid.size(); ++j) {
    EXPECT_NEAR(field(c, StateField::MuBody)[j], 0.2 + 1e8 * grid[j], 1e-12);
    EXPECT_NEAR(field(c, StateField::AreaFraction)[j], 0.01 + 1e6 * grid[j], 1e-14);
    EXPECT_NEAR(field(c, StateField::WearRate)[j], a, 1e-12 * a);
    EXPECT_NEAR(field(c, StateField::SlidingDistance)[j], grid[j] / a, 1e-9 * grid[j] / a);
  }
}

TEST(HomogeniseCurves, FlatStretchesAndDipsAreCrossedWithoutDivisionByZero) {
  CellSeries c;
  // h: 0, 1, 1, 1, 0.999999 (a round-off dip), 1, 2, 3, 4 (nm); s: 1..9 (um)
  const std::vector<double> h = {0, 1, 1, 1, 0.999999, 1, 2, 3, 4};
  for (std::size_t i = 0; i < h.size(); ++i) {
    c.s.push_back((i + 1) * 1e-6), c.h.push_back(h[i] * 1e-9), c.h_cf.push_back(0.0);
    c.mu_body.push_back(static_cast<double>(i)), c.rq.push_back(1e-7), c.rsk.push_back(0.0);
    c.area_fraction.push_back(0.1);
  }
  const auto grid = depth_grid(4e-9, 9);  // 0, 0.5, 1, 1.5, ... nm
  const auto out = resample_on_depth_grid(c, grid, 1.0);
  for (std::size_t f = 0; f < out.field.size(); ++f)
    for (double v : out.field[f]) EXPECT_TRUE(std::isfinite(v));
  const auto &mu = field(out, StateField::MuBody);
  EXPECT_DOUBLE_EQ(mu[2], 1.0);                  // h = 1 nm: the first row that reaches it
  EXPECT_NEAR(mu[3], 5.5, 1e-9);                 // h = 1.5 nm: between the end of the flat stretch (row 5) and row 6
  for (double r : field(out, StateField::WearRate)) EXPECT_GE(r, 0.0);
  EXPECT_DOUBLE_EQ(field(out, StateField::CounterfaceWearRate)[4], 0.0);  // the counterface did not wear
}

TEST(HomogeniseCurves, ASampleShortOfTheDepthIsAnErrorNamingItsReach) {
  const auto grid = depth_grid(1e-6, 3);
  try {
    resample_on_depth_grid(linear_cell(1e-3, 10, 1e-7), grid, 1.0);  // reaches 1e-9
    FAIL() << "no error";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("reached h = 1e-09 m of depth 1e-06 m"), std::string::npos) << e.what();
  }
}

TEST(HomogeniseCurves, NoSlidingRowsIsAnError) {
  CellSeries c = linear_cell(1e-3, 0, 1e-7);  // the loading rows only
  EXPECT_THROW(resample_on_depth_grid(c, depth_grid(1e-9, 2), 1.0), std::runtime_error);
}

// (the ave/time reader refuses a non-finite value itself, naming file, line and column; cell_series checks again)
TEST(HomogeniseCurves, CellSeriesRejectsNonFiniteValuesAndMissingColumns) {
  std::istringstream good("# TimeStep v_s v_h v_h_cf v_mu_body v_rq v_rsk v_area_fraction\n1 0 0 0 0 1e-7 0 0.1\n");
  EXPECT_EQ(runin::coupling::cell_series(runin::coupling::parse_ave_time(good, "good.dat")).s.size(), 1u);
  std::istringstream nan_row("# TimeStep v_s v_h v_h_cf v_mu_body v_rq v_rsk v_area_fraction\n1 0 0 0 nan 1e-7 0 0.1\n");
  try {
    runin::coupling::cell_series(runin::coupling::parse_ave_time(nan_row, "nan.dat"));
    FAIL() << "no error";
  } catch (const std::exception &e) {
    EXPECT_NE(std::string(e.what()).find("nan.dat:2: column 'v_mu_body': non-finite"), std::string::npos)
        << e.what();
  }
  std::istringstream missing("# TimeStep v_s v_h\n1 0 0\n");
  EXPECT_THROW(runin::coupling::cell_series(runin::coupling::parse_ave_time(missing, "missing.dat")), std::runtime_error);
}

}  // namespace

// Friction from a few contacts is noisy row to row: mu_body and the area fraction at a grid depth are the
// least-squares line over the rows within half a grid step, so a +-0.01 alternation around a linear trend
// (what two bracketing rows would carry whole) averages out, and the trend itself is kept.
TEST(HomogeniseCurves, NoisyFrictionIsFittedOverHalfAGridStepAroundEachDepth) {
  CellSeries c = linear_cell(1e-3, 400, 1e-7);  // h to 4e-8 m, 0.1 nm per row
  for (std::size_t i = 0; i < c.s.size(); ++i)
    if (c.s[i] > 0.0) {
      const double sign = (i % 2 == 0) ? 1.0 : -1.0;
      c.mu_body[i] += 0.01 * sign;
      c.area_fraction[i] += 1e-3 * sign;
    }
  const auto grid = depth_grid(2e-8, 11);  // 2 nm steps: 21 rows per window inside, 11 at h = 0
  const auto out = resample_on_depth_grid(c, grid, 1.0);
  // h = 0 is the first sliding row, as it is (the state when sliding begins)
  EXPECT_NEAR(field(out, StateField::MuBody)[0], c.mu_body[3], 1e-15);
  for (std::size_t j = 1; j < grid.size(); ++j) {  // a centred window of 21 rows
    EXPECT_NEAR(field(out, StateField::MuBody)[j], 0.2 + 1e8 * grid[j], 0.01 / 5.0) << j;
    EXPECT_NEAR(field(out, StateField::AreaFraction)[j], 0.01 + 1e6 * grid[j], 1e-3 / 5.0) << j;
    EXPECT_NEAR(field(out, StateField::Rq)[j], 2e-7 - grid[j], 1e-20) << j;  // smooth fields: the bracket
  }
}
