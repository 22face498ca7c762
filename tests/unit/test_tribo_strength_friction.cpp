// Coulomb limit from the micro friction strength (adhesion + ploughing) with a static excess.
#include "tribo/friction_strength.h"
#include "tribo/strength_friction.h"

#include <gtest/gtest.h>

using namespace runin::tribo;

// mu(slip) = mu_p + mu_adh + (mu_s - mu_k) max(0, 1 - slip / d_c): the kinetic level is the strength
// over the normal force, the static excess and its slip weakening are those of the coefficient set.
TEST(StrengthFriction, KineticLevelIsStrengthOverLoadWithStaticExcess)
{
  const double mu_s = 0.7, mu_k = 0.5, d_c = 2e-8, fn = 3e-3;
  FrictionStrengthParts parts;
  parts.adhesion = 4e-4;
  parts.ploughing = 2e-4;
  const double mu_strength = (4e-4 + 2e-4) / fn;    // 0.2
  const StaticKineticFriction limit = strength_friction(mu_s, mu_k, d_c, parts, fn);
  EXPECT_NEAR(limit.mu_kinetic(), mu_strength, 1e-15);
  EXPECT_NEAR(limit.mu_static(), mu_strength + 0.2, 1e-15);
  EXPECT_NEAR(limit.coefficient(0.0), mu_strength + 0.2, 1e-15);
  EXPECT_NEAR(limit.coefficient(0.5 * d_c), mu_strength + 0.1, 1e-15);
  EXPECT_NEAR(limit.coefficient(3.0 * d_c), mu_strength, 1e-15);
}

// Without a static excess the limit is the strength alone at every slip distance (the pure
// Bowden-Tabor contact); with no adhesion and no ploughing it is frictionless.
TEST(StrengthFriction, NoExcessIsPureStrength)
{
  FrictionStrengthParts parts;
  parts.ploughing = 1e-3;
  const StaticKineticFriction limit = strength_friction(0.4, 0.4, 1e-8, parts, 1e-2);
  EXPECT_NEAR(limit.coefficient(0.0), 0.1, 1e-15);
  EXPECT_NEAR(limit.coefficient(1.0), 0.1, 1e-15);
  EXPECT_EQ(strength_friction(0.4, 0.4, 0.0, FrictionStrengthParts{}, 1e-2).coefficient(0.0), 0.0);
}
