// Contact kernels against closed forms (Johnson, Contact Mechanics, 1985).
#include "tribo/contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace runin::tribo;

namespace {
constexpr double kRoundOff = 1e-13;    // tier 1: identities
const Material kCopper{110e9, 0.37, 0.87e9};
const Material kAluminium{69e9, 0.33, 0.245e9};
}    // namespace

TEST(Hertz, ForceMatchesJohnsonInversion)
{
  // Johnson eq. 4.22-4.23: a^3 = 3 F R* / (4 E*), delta = a^2 / R*. Independent route to F(delta).
  const double e_eff = effective_modulus(kCopper, kAluminium);
  const double r_eff = effective_radius(2e-6, 5e-6);
  const HertzNormal hertz(e_eff, r_eff);
  for (double delta : {1e-12, 3e-10, 1e-9, 2.5e-8}) {
    const double force = hertz.force(delta);
    const double a = std::cbrt(3.0 * force * r_eff / (4.0 * e_eff));
    EXPECT_NEAR(a * a / r_eff, delta, 1e-10 * delta);
    EXPECT_NEAR(hertz.contact_radius(delta), a, 1e-10 * a);
  }
}

TEST(Hertz, EffectiveModulusClosedForm)
{
  const double expected = 1.0 / ((1 - 0.37 * 0.37) / 110e9 + (1 - 0.33 * 0.33) / 69e9);
  EXPECT_NEAR(effective_modulus(kCopper, kAluminium), expected, kRoundOff * expected);
  EXPECT_NEAR(effective_radius(1.0, 1.0), 0.5, kRoundOff);
}

TEST(Hertz, StiffnessAndEnergyAreConsistentDerivatives)
{
  const HertzNormal hertz(5e10, 1e-6);
  const double delta = 1e-8, h = 1e-13;
  const double dforce = (hertz.force(delta + h) - hertz.force(delta - h)) / (2 * h);
  EXPECT_NEAR(hertz.stiffness(delta), dforce, 1e-7 * dforce);
  const double denergy = (hertz.elastic_energy(delta + h) - hertz.elastic_energy(delta - h)) / (2 * h);
  EXPECT_NEAR(hertz.force(delta), denergy, 1e-7 * denergy);
  EXPECT_EQ(hertz.force(-1e-9), 0.0);
}

TEST(Hertz, RejectsNonPositiveModulus)
{
  EXPECT_THROW(HertzNormal(-1.0, 1e-6), InvalidCoefficient);
  EXPECT_THROW(HertzNormal(1e9, 0.0), InvalidCoefficient);
  Material bad = kCopper;
  bad.hardness = -1.0;
  EXPECT_THROW(bad.validate("Cu"), InvalidCoefficient);
}

TEST(Damping, OffAtUnitRestitutionAndOpposesApproach)
{
  EXPECT_EQ(RestitutionDamping(1.0).force(1e6, 1e-9, -1.0), 0.0);
  const RestitutionDamping damping(0.5);
  EXPECT_GT(damping.force(1e6, 1e-9, -1.0), 0.0);    // approaching: repulsive
  EXPECT_LT(damping.force(1e6, 1e-9, +1.0), 0.0);
  const double beta = std::log(0.5) / std::sqrt(std::log(0.5) * std::log(0.5) + M_PI * M_PI);
  EXPECT_NEAR(damping.force(4.0, 1.0, -1.0), -2.0 * std::sqrt(5.0 / 6.0) * beta * 2.0, kRoundOff);
  EXPECT_THROW(RestitutionDamping(0.0), InvalidCoefficient);
  EXPECT_THROW(RestitutionDamping(1.2), InvalidCoefficient);
}

TEST(Mindlin, StickIsLinearSpringThenSlipsAtStaticThenKineticLimit)
{
  const StaticKineticFriction friction(0.6, 0.4, 0.0);
  const double n[3] = {0, 0, 1}, vt[3] = {1e-3, 0, 0};
  const double kt = 2e5, fn = 1e-3, dt = 1e-9;
  double spring[3] = {0, 0, 0}, slip = 0.0;

  // Stick: F_t = -k_t * u, with u the accumulated tangential displacement.
  auto step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
  EXPECT_FALSE(step.slipping);
  EXPECT_NEAR(step.force[0], -kt * 1e-12, kRoundOff * kt * 1e-12);

  // Load until the first slip: the force at slip is exactly mu_s F_n.
  int steps = 1;
  while (!(step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true)).slipping) ++steps;
  EXPECT_NEAR(std::fabs(step.force[0]), 0.6 * fn, kRoundOff);
  EXPECT_NEAR(steps * vt[0] * dt, 0.6 * fn / kt, vt[0] * dt);    // stick distance = mu_s F_n / k_t

  // First kinetic step: the spring relaxes from mu_s F_n / k_t to mu_k F_n / k_t.
  double slip_before = slip;
  step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
  EXPECT_TRUE(step.slipping);
  EXPECT_NEAR(std::fabs(step.force[0]), 0.4 * fn, kRoundOff);
  EXPECT_NEAR(slip - slip_before, (0.6 - 0.4) * fn / kt + vt[0] * dt, 1e-12 * fn / kt);

  // Steady sliding: slip accumulates at exactly the imposed rate.
  slip_before = slip;
  step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
  EXPECT_NEAR(std::fabs(step.force[0]), 0.4 * fn, kRoundOff);
  EXPECT_NEAR(slip - slip_before, vt[0] * dt, 1e-9 * vt[0] * dt);
}

TEST(Mindlin, SetupCallLeavesHistoryUntouched)
{
  const StaticKineticFriction friction(0.5, 0.5, 0.0);
  const double n[3] = {0, 0, 1}, vt[3] = {1.0, 0, 0};
  double spring[3] = {1e-9, 0, 0}, slip = 0.25;
  auto out = mindlin_coulomb(1e5, 1.0, friction, n, vt, 1e-6, spring, slip, false);
  EXPECT_EQ(spring[0], 1e-9);
  EXPECT_EQ(slip, 0.25);
  EXPECT_NEAR(out.force[0], -1e-4, kRoundOff);
}

TEST(StaticKinetic, SlipWeakeningIsLinearOverDc)
{
  const StaticKineticFriction friction(0.8, 0.2, 1e-6);
  EXPECT_DOUBLE_EQ(friction.coefficient(0.0), 0.8);
  EXPECT_NEAR(friction.coefficient(0.5e-6), 0.5, kRoundOff);
  EXPECT_DOUBLE_EQ(friction.coefficient(2e-6), 0.2);
  EXPECT_THROW(StaticKineticFriction(0.2, 0.3, 0.0), InvalidCoefficient);
}

// Slide past d_c (limit mu_k F_n), stop, then push again: with re-stick the contact breaks away at
// mu_s F_n a second time; without it the second peak stays at mu_k F_n.
TEST(Mindlin, RestickHealsToStaticLimitAfterAStop)
{
  const double kt = 7.6e3, fn = 1.6e-5, dt = 1e-10, speed = 1.0;
  const StaticKineticFriction friction(0.6, 0.4, 5e-9);
  const double n[3] = {0.0, 0.0, 1.0};
  for (double restick_speed : {0.0, 0.1}) {
    double spring[3] = {0.0, 0.0, 0.0}, slip = 0.0, second_peak = 0.0;
    auto push = [&](double v, int steps, double *peak) {
      const double vt[3] = {v, 0.0, 0.0};
      for (int k = 0; k < steps; ++k) {
        const TangentialUpdate update = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
        if (resticks(update, std::fabs(v), restick_speed)) slip = 0.0;
        if (peak) *peak = std::max(*peak, std::fabs(update.force[0]));
      }
    };
    push(speed, 200, nullptr);
    EXPECT_NEAR(kt * std::fabs(spring[0]), 0.4 * fn, 1e-12 * fn);    // sliding at mu_k
    push(0.0, 3, nullptr);
    push(speed, 200, &second_peak);
    const double expected = restick_speed > 0.0 ? 0.6 * fn : 0.4 * fn;
    EXPECT_NEAR(second_peak, expected, 1e-12 * fn) << "restick speed " << restick_speed;
  }
  TangentialUpdate slipping;
  slipping.slipping = true;
  EXPECT_FALSE(resticks(slipping, 0.0, 0.1));    // a slipping contact never re-sticks
  EXPECT_FALSE(resticks(TangentialUpdate(), 0.2, 0.1));
  EXPECT_TRUE(resticks(TangentialUpdate(), 0.05, 0.1));
}
