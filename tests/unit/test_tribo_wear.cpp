// Archard wear kernel against V = k W s / H (and the thesis's eq. 1.4 with its factor 1/3).
#include "tribo/contact.h"
#include "tribo/wear.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

TEST(Archard, IncrementMatchesClosedForm)
{
  const double k = 3.2e-4, hardness = 0.245e9, load = 0.981, ds = 1.7e-3;
  const ArchardWear plain(k, hardness);
  EXPECT_NEAR(plain.volume(load, ds), k * load * ds / hardness, 1e-14 * k * load * ds / hardness);
  const ArchardWear thesis(k, hardness, ArchardForm::thesis);
  EXPECT_NEAR(thesis.volume(load, ds), k * load * ds / (3.0 * hardness), 1e-14 * k * load * ds / hardness);
  EXPECT_EQ(plain.volume(-load, -ds), plain.volume(load, ds));    // magnitudes only
}

TEST(Archard, SumOfIncrementsEqualsOneLongSlide)
{
  const ArchardWear wear(1e-3, 1e9);
  double total = 0.0;
  for (int i = 0; i < 1000; ++i) total += wear.volume(2.0, 1e-6);
  EXPECT_NEAR(total, wear.volume(2.0, 1e-3), 1e-12 * total);
}

TEST(Archard, ShareFollowsInverseHardness)
{
  EXPECT_DOUBLE_EQ(wear_share(1e9, 1e9), 0.5);
  EXPECT_NEAR(wear_share(1e9, 3e9), 0.75, 1e-15);    // the softer body takes 3/4
  EXPECT_NEAR(wear_share(1e9, 3e9) + wear_share(3e9, 1e9), 1.0, 1e-15);
}

TEST(Archard, RejectsImpossibleCoefficients)
{
  EXPECT_THROW(ArchardWear(-1e-4, 1e9), InvalidCoefficient);
  EXPECT_THROW(ArchardWear(1e-4, 0.0), InvalidCoefficient);
}

// The explicit wear update on a linear-elastic foundation, h += (k/H)(p0 - k_c h) ds, relaxes to
// h* = p0/k_c for any ds under the bound and grows without limit just above it.
TEST(Archard, StableSlipStepSeparatesDecayFromOscillation)
{
  const ArchardWear wear(1e-3, 1e9);
  const double k_c = 1e13, p0 = 1e8;
  const double bound = wear.stable_slip_step(k_c);
  EXPECT_DOUBLE_EQ(bound, 2.0 * 1e9 / (1e-3 * k_c));
  auto final_error = [&](double ds) {
    double h = 0.0;
    for (int n = 0; n < 400; n++) h += wear.depth_rate(p0 - k_c * h) * ds;
    return std::fabs(h - p0 / k_c) / (p0 / k_c);
  };
  EXPECT_LT(final_error(0.9 * bound), 1e-12);
  EXPECT_GT(final_error(1.1 * bound), 1.0);
  EXPECT_DOUBLE_EQ(ArchardWear(1e-3, 1e9, ArchardForm::thesis).stable_slip_step(k_c), 3.0 * bound);
  EXPECT_THROW(wear.stable_slip_step(0.0), InvalidCoefficient);
}

// removed = lost_a + lost_b = deposited + debris, each body loses its 1/H share and receives
// 'transfer' times what the other loses.
TEST(Archard, WearExchangeBookkeepingIsExact)
{
  const double removed = 3.7e-22, share = wear_share(0.245e9, 0.87e9);
  for (double transfer : {0.0, 0.3, 1.0}) {
    const WearExchange x = exchange_wear(removed, share, transfer);
    EXPECT_NEAR(x.lost_a + x.lost_b, removed, 1e-15 * removed);
    EXPECT_NEAR(x.lost_a, removed * 0.87 / (0.245 + 0.87), 1e-14 * removed);
    EXPECT_NEAR(x.gained_a, transfer * x.lost_b, 1e-16 * removed);
    EXPECT_NEAR(x.gained_b, transfer * x.lost_a, 1e-16 * removed);
    EXPECT_NEAR(x.gained_a + x.gained_b + x.debris, removed, 1e-15 * removed) << transfer;
  }
  EXPECT_EQ(exchange_wear(removed, share, 1.0).debris, 0.0);
  EXPECT_THROW(exchange_wear(removed, share, 1.5), InvalidCoefficient);
  EXPECT_THROW(exchange_wear(removed, share, -0.1), InvalidCoefficient);
}

// The per-type-pair rule of the force loops splits exactly as exchange_wear and checks the fraction once.
TEST(Archard, WearExchangeRuleSplitsAsExchangeWear)
{
  const double share = wear_share(0.245e9, 0.87e9);
  for (double transfer : {0.0, 0.3, 1.0}) {
    const WearExchangeRule rule(share, transfer);
    for (double removed : {0.0, 1e-30, 3.7e-22, 2e-18}) {
      const WearExchange a = rule.split(removed), b = exchange_wear(removed, share, transfer);
      EXPECT_EQ(a.lost_a, b.lost_a);
      EXPECT_EQ(a.lost_b, b.lost_b);
      EXPECT_EQ(a.gained_a, b.gained_a);
      EXPECT_EQ(a.gained_b, b.gained_b);
      EXPECT_EQ(a.debris, b.debris);
    }
  }
  EXPECT_THROW(WearExchangeRule(share, 1.5), InvalidCoefficient);
  EXPECT_THROW(WearExchangeRule(share, -0.1), InvalidCoefficient);
}
