// Adhesion + ploughing friction strength of one asperity contact.
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"
#include "tribo/friction_strength.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST(AdhesionPloughing, PartsMatchClosedForms)
{
  const double tau = 1.5e8, fn = 2e-3, a = 4e-8, delta = 3e-9;
  const AdhesionPloughing model(tau);
  const FrictionStrengthParts parts = model.strength(fn, a, delta);
  EXPECT_NEAR(parts.adhesion, tau * kPi * a * a, 1e-15 * tau * kPi * a * a);
  const double mu_p = 2.0 / kPi * delta / a;
  EXPECT_NEAR(parts.ploughing, mu_p * fn, 1e-15 * mu_p * fn);
  EXPECT_DOUBLE_EQ(parts.total(), parts.adhesion + parts.ploughing);
  EXPECT_NEAR(AdhesionPloughing::ploughing_coefficient(1.0), 2.0 / kPi, 1e-16);
  const FrictionStrengthParts adhesion_only = AdhesionPloughing(tau, 0.0).strength(fn, a, delta);
  EXPECT_EQ(adhesion_only.ploughing, 0.0);
  EXPECT_EQ(model.strength(fn, 0.0, delta).total(), 0.0);
}

// On an unworn Hertz contact tan(theta) = delta / a = a / R; wear (a flat) lowers the ploughing term.
TEST(AdhesionPloughing, HertzAttackAngleAndWornFlat)
{
  const double E = 4.8e10, R = 5e-7, delta = 4e-9;
  const HertzNormal hertz(E, R);
  const AdhesionPloughing model(0.0);
  const double a = hertz.contact_radius(delta);
  const double fn = hertz.force(delta);
  EXPECT_NEAR(model.strength(fn, a, delta).ploughing, 2.0 / kPi * (a / R) * fn, 1e-14 * fn);

  const FlatHertzNormal worn(E, R, 2.0 * a);
  // same load on the worn asperity: find its overlap by bisection, then compare mu_p
  double lo = 0.0, hi = delta;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (worn.force(mid) < fn ? lo : hi) = mid;
  }
  const double worn_a = worn.contact_radius(lo);
  const double mu_worn = model.strength(fn, worn_a, lo).ploughing / fn;
  EXPECT_NEAR(mu_worn, 2.0 / kPi * worn.curved_radius(lo) / R, 1e-12 * mu_worn);
  EXPECT_LT(mu_worn, 0.5 * 2.0 / kPi * a / R);
}

// mu = tau pi a^2 / F_n + (2/pi) a / R on a Hertz contact at fixed load: the adhesion part falls and the
// ploughing part rises as R shrinks (a^2 ~ R^(2/3), a / R ~ R^(-2/3)): the two mechanisms of mu(R).
TEST(AdhesionPloughing, TwoMechanismsScaleOppositelyWithRadius)
{
  const double E = 4.8e10, fn = 1e-3, tau = 1e8;
  const AdhesionPloughing model(tau);
  auto parts_at = [&](double R) {
    const double a = std::cbrt(3.0 * fn * R / (4.0 * E));
    return model.strength(fn, a, a * a / R);
  };
  const FrictionStrengthParts coarse = parts_at(2e-6), fine = parts_at(2e-6 / 8.0);
  EXPECT_NEAR(fine.adhesion / coarse.adhesion, std::pow(8.0, -2.0 / 3.0), 1e-12);
  EXPECT_NEAR(fine.ploughing / coarse.ploughing, std::pow(8.0, 2.0 / 3.0), 1e-12);
}

TEST(AdhesionPloughing, RejectsBadCoefficients)
{
  EXPECT_THROW(AdhesionPloughing(-1.0), InvalidCoefficient);
  EXPECT_THROW(AdhesionPloughing(1e8, -0.5), InvalidCoefficient);
  EXPECT_THROW(AdhesionPloughing(NAN), InvalidCoefficient);
}
