// Seed averaging of runin homogenise (src/coupling/homogenise.h): mean and seed band of hand-computable samples.
#include <gtest/gtest.h>

#include <stdexcept>

#include "coupling/homogenise.h"

namespace {

using runin::coupling::DepthCurves;
using runin::coupling::HomogenisationSamples;
using runin::coupling::StateField;
using runin::coupling::state_field_count;

constexpr std::size_t index(StateField f) { return static_cast<std::size_t>(f); }

// Every field on the 3-point depth grid: `base` + j * `slope` (j the depth index); mu_body decreasing by it.
DepthCurves curves(double base, double slope) {
  DepthCurves c;
  for (std::size_t f = 0; f < state_field_count; ++f)
    for (int j = 0; j < 3; ++j) c.field[f].push_back(base + j * slope);
  for (int j = 0; j < 3; ++j) c.field[index(StateField::MuBody)][j] = 0.5 - j * slope;
  return c;
}

HomogenisationSamples two_pressures() {
  HomogenisationSamples s;
  s.pressure = {1e6, 4e6};
  s.worn_depth = {0.0, 1e-9, 2e-9};
  // p = 1 MPa: three seeds 0.1, 0.2, 0.6 (+ 0.01 j); p = 4 MPa: one seed 0.3 (+ 0.02 j)
  s.seeds = {{curves(0.1, 0.01), curves(0.2, 0.01), curves(0.6, 0.01)}, {curves(0.3, 0.02)}};
  return s;
}

}  // namespace

TEST(Homogenise, MeanIsTheSeedMeanAndTheBandTheirMinimumAndMaximum) {
  const auto law = runin::coupling::homogenise(two_pressures());
  ASSERT_EQ(law.pressure().size(), 2u);
  ASSERT_TRUE(law.has_band());
  const auto &rq = law.table(StateField::Rq);
  for (int j = 0; j < 3; ++j) {
    EXPECT_DOUBLE_EQ(rq.mean[0][j], (0.1 + 0.2 + 0.6) / 3.0 + 0.01 * j) << j;  // 0.3 + 0.01 j
    EXPECT_DOUBLE_EQ(rq.low[0][j], 0.1 + 0.01 * j);
    EXPECT_DOUBLE_EQ(rq.high[0][j], 0.6 + 0.01 * j);
    // one seed: mean = low = high
    EXPECT_DOUBLE_EQ(rq.mean[1][j], 0.3 + 0.02 * j);
    EXPECT_DOUBLE_EQ(rq.low[1][j], rq.mean[1][j]);
    EXPECT_DOUBLE_EQ(rq.high[1][j], rq.mean[1][j]);
  }
  // mu_body is the same curve at every seed: no band
  const auto &mu = law.table(StateField::MuBody);
  EXPECT_DOUBLE_EQ(mu.mean[0][2], 0.48);
  EXPECT_DOUBLE_EQ(mu.low[0][2], mu.high[0][2]);
  // the law reads back what was averaged
  EXPECT_DOUBLE_EQ(law.value(StateField::WearRate, 1e6, 1e-9), 0.31);
}

TEST(Homogenise, MeanStaysInsideAFlatBandDespiteRoundOff) {
  auto s = two_pressures();
  s.seeds[0] = {curves(0.1, 0.0), curves(0.1, 0.0), curves(0.1, 0.0)};  // 0.1 + 0.1 + 0.1 = 0.30000000000000004
  const auto law = runin::coupling::homogenise(s);
  const auto &rq = law.table(StateField::Rq);
  EXPECT_LE(rq.mean[0][0], rq.high[0][0]);
  EXPECT_GE(rq.mean[0][0], rq.low[0][0]);
}

TEST(Homogenise, APressureWithoutSeedsOrACurveOffTheGridIsRefused) {
  auto none = two_pressures();
  none.seeds[1].clear();
  EXPECT_THROW(runin::coupling::homogenise(none), std::invalid_argument);
  auto short_curve = two_pressures();
  short_curve.seeds[0][1].field[0].pop_back();
  EXPECT_THROW(runin::coupling::homogenise(short_curve), std::invalid_argument);
}
