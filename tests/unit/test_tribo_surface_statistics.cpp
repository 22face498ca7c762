// Surface statistics (Ra, Rq, Rsk, Rku, Rp, Rv, Rz, bearing ratio) against closed forms.
#include "tribo/surface_statistics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace runin::tribo;

namespace {

// The definitions, computed directly (two-pass) from the heights.
struct Direct {
  double mean, Ra, Rq, Rsk, Rku, Rp, Rv;
  std::vector<double> bearing;
};

Direct direct(const std::vector<double> &z, const std::vector<double> &depths)
{
  const double n = static_cast<double>(z.size());
  double mean = 0.0;
  for (double v : z) mean += v;
  mean /= n;
  double a = 0.0, m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double v : z) {
    const double d = v - mean;
    a += std::fabs(d);
    m2 += d * d;
    m3 += d * d * d;
    m4 += d * d * d * d;
  }
  m2 /= n, m3 /= n, m4 /= n;
  const double top = *std::max_element(z.begin(), z.end());
  const double bottom = *std::min_element(z.begin(), z.end());
  Direct out{mean, a / n, std::sqrt(m2), m3 / std::pow(m2, 1.5), m4 / (m2 * m2), top - mean, mean - bottom, {}};
  for (double depth : depths)
    out.bearing.push_back(std::count_if(z.begin(), z.end(), [&](double v) { return v >= top - depth; }) / n);
  return out;
}

void expect_rel(double actual, double expected, double rel, const char *what)
{
  EXPECT_NEAR(actual, expected, rel * std::max(std::fabs(expected), 1e-300)) << what;
}

void expect_matches(const RoughnessStatistics &s, const Direct &d, double rel)
{
  expect_rel(s.mean, d.mean, rel, "mean");
  expect_rel(s.Ra, d.Ra, rel, "Ra");
  expect_rel(s.Rq, d.Rq, rel, "Rq");
  expect_rel(s.Rsk, d.Rsk, rel, "Rsk");
  expect_rel(s.Rku, d.Rku, rel, "Rku");
  expect_rel(s.Rp, d.Rp, rel, "Rp");
  expect_rel(s.Rv, d.Rv, rel, "Rv");
  expect_rel(s.Rz, d.Rp + d.Rv, rel, "Rz");
  ASSERT_EQ(s.bearing.size(), d.bearing.size());
  for (std::size_t k = 0; k < d.bearing.size(); ++k) EXPECT_EQ(s.bearing[k], d.bearing[k]) << "bearing " << k;
}

// Skewed, with an offset plane far from zero (1 mm) and micrometre roughness.
const std::vector<double> kHeights = {1.0e-3 + 0.12e-6, 1.0e-3 - 0.31e-6, 1.0e-3 + 0.05e-6, 1.0e-3 + 0.47e-6,
                                      1.0e-3 - 0.02e-6, 1.0e-3 - 0.18e-6, 1.0e-3 + 0.91e-6, 1.0e-3 - 0.27e-6,
                                      1.0e-3 + 0.01e-6, 1.0e-3 - 0.09e-6};
const std::vector<double> kDepths = {0.0, 0.1e-6, 0.5e-6, 0.85e-6, 2.0e-6};

}    // namespace

TEST(SurfaceStatistics, KnownHeightsMatchClosedForm)
{
  const auto s = roughness(kHeights, kDepths);
  ASSERT_TRUE(s.valid());
  EXPECT_EQ(s.count, 10.0);
  expect_matches(s, direct(kHeights, kDepths), 1e-12);
  // hand-checked: top +0.91 um; summits >= +0.91, +0.81, +0.41, +0.06, -1.09 um: 1, 1, 2, 3, 10 of 10
  EXPECT_EQ(s.bearing, (std::vector<double>{0.1, 0.1, 0.2, 0.3, 1.0}));
}

TEST(SurfaceStatistics, SimpleClosedForm)
{
  // heights -1, 0, 0, 1 (mean 0): Ra = 1/2, Rq = sqrt(1/2), Rsk = 0, Rku = (1/2)/(1/4) = 2
  const auto s = roughness({-1.0, 0.0, 0.0, 1.0}, {0.5});
  EXPECT_DOUBLE_EQ(s.Ra, 0.5);
  EXPECT_DOUBLE_EQ(s.Rq, std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(s.Rsk, 0.0);
  EXPECT_DOUBLE_EQ(s.Rku, 2.0);
  EXPECT_DOUBLE_EQ(s.Rp, 1.0);
  EXPECT_DOUBLE_EQ(s.Rv, 1.0);
  EXPECT_DOUBLE_EQ(s.Rz, 2.0);
  EXPECT_DOUBLE_EQ(s.bearing[0], 0.25);
}

TEST(SurfaceStatistics, MergingHalvesEqualsAllAtOnce)
{
  HeightRange first, second, all;
  const std::size_t half = kHeights.size() / 2;
  for (std::size_t i = 0; i < kHeights.size(); ++i) {
    (i < half ? first : second).add(kHeights[i]);
    all.add(kHeights[i]);
  }
  first.merge(second);
  EXPECT_EQ(first.count, all.count);
  EXPECT_EQ(first.min, all.min);
  EXPECT_EQ(first.max, all.max);
  EXPECT_NEAR(first.sum, all.sum, 1e-15 * std::fabs(all.sum));

  HeightMoments a(first.mean(), first.max, kDepths), b(first.mean(), first.max, kDepths),
      whole(first.mean(), first.max, kDepths);
  for (std::size_t i = 0; i < kHeights.size(); ++i) {
    (i < half ? a : b).add(kHeights[i]);
    whole.add(kHeights[i]);
  }
  a.merge(b);
  const auto merged = roughness(first, a), once = roughness(all, whole);
  expect_rel(merged.Ra, once.Ra, 1e-13, "Ra");
  expect_rel(merged.Rq, once.Rq, 1e-13, "Rq");
  expect_rel(merged.Rsk, once.Rsk, 1e-12, "Rsk");
  expect_rel(merged.Rku, once.Rku, 1e-13, "Rku");
  expect_rel(merged.Rz, once.Rz, 1e-13, "Rz");
  EXPECT_EQ(merged.bearing, once.bearing);
  expect_matches(merged, direct(kHeights, kDepths), 1e-12);

  HeightMoments other_reference(first.mean() + 1e-9, first.max, kDepths);
  EXPECT_THROW(a.merge(other_reference), std::invalid_argument);
}

TEST(SurfaceStatistics, ReferenceOffTheMeanIsCorrected)
{
  // sums about a reference 0.3 um off the mean still give the central moments
  HeightRange range;
  for (double z : kHeights) range.add(z);
  HeightMoments moments(range.mean() + 0.3e-6, range.max, kDepths);
  for (double z : kHeights) moments.add(z);
  const auto s = roughness(range, moments);
  const auto d = direct(kHeights, kDepths);
  expect_rel(s.mean, d.mean, 1e-12, "mean");
  expect_rel(s.Rq, d.Rq, 1e-10, "Rq");
  expect_rel(s.Rsk, d.Rsk, 1e-9, "Rsk");
  expect_rel(s.Rku, d.Rku, 1e-9, "Rku");
  expect_rel(s.Rp, d.Rp, 1e-10, "Rp");
  expect_rel(s.Rv, d.Rv, 1e-10, "Rv");
}

TEST(SurfaceStatistics, SymmetricSetHasZeroSkewness)
{
  std::vector<double> z;
  for (double d : {0.1, 0.7, 1.3, 2.9, 0.05}) {
    z.push_back(5.0 + d);
    z.push_back(5.0 - d);
  }
  const auto s = roughness(z);
  EXPECT_NEAR(s.Rsk, 0.0, 1e-12);
  EXPECT_NEAR(s.Rp, s.Rv, 1e-14);
}

TEST(SurfaceStatistics, UniformSampleApproachesKurtosisOnePointEight)
{
  std::mt19937_64 rng(20260401);
  std::uniform_real_distribution<double> uniform(-1.0e-6, 1.0e-6);
  std::vector<double> z(200000);
  for (double &v : z) v = 2.0e-6 + uniform(rng);
  const auto s = roughness(z, {1.0e-6});
  EXPECT_NEAR(s.Rku, 1.8, 0.01);    // kurtosis of U(a, b) is 9/5
  EXPECT_NEAR(s.Rsk, 0.0, 0.01);
  EXPECT_NEAR(s.Rq, 1.0e-6 / std::sqrt(3.0), 0.005e-6);
  EXPECT_NEAR(s.Ra, 0.5e-6, 0.005e-6);
  EXPECT_NEAR(s.bearing[0], 0.5, 0.01);    // half the summits lie within half the range of the top
}

TEST(SurfaceStatistics, NoHeightsGiveInvalidZeros)
{
  const auto s = roughness(std::vector<double>{}, {0.1});
  EXPECT_FALSE(s.valid());
  EXPECT_EQ(s.Ra, 0.0);
  EXPECT_EQ(s.Rq, 0.0);
  EXPECT_EQ(s.Rsk, 0.0);
  EXPECT_EQ(s.Rku, 0.0);
  EXPECT_EQ(s.Rz, 0.0);
  ASSERT_EQ(s.bearing.size(), 1u);
  EXPECT_EQ(s.bearing[0], 0.0);
  EXPECT_TRUE(std::isfinite(s.mean));
}

TEST(SurfaceStatistics, FlatSurfaceHasZeroShapeFactors)
{
  const auto s = roughness({3.0, 3.0, 3.0}, {0.0});
  EXPECT_EQ(s.Rq, 0.0);
  EXPECT_EQ(s.Rsk, 0.0);
  EXPECT_EQ(s.Rku, 0.0);
  EXPECT_EQ(s.bearing[0], 1.0);
}

TEST(SurfaceStatistics, NegativeOrNonFiniteDepthThrows)
{
  EXPECT_THROW(HeightMoments(0.0, 1.0, {-1e-9}), std::invalid_argument);
  EXPECT_THROW(HeightMoments(0.0, 1.0, {std::nan("")}), std::invalid_argument);
}
