// Coulomb limit from the micro friction strength (adhesion + ploughing) with a static excess:
// StaticKineticFriction::limit_force, used by pair runin/asperity and fix runin/wall with 'friction strength'.
#include "tribo/contact.h"
#include "tribo/friction_strength.h"

#include <gtest/gtest.h>

using namespace runin::tribo;

// F_lim = F_adh + F_pl + (mu_s - mu_k) max(0, 1 - slip / d_c) F_n: the kinetic level is the strength,
// the static excess and its slip weakening are those of the coefficient set.
TEST(StrengthFriction, KineticLevelIsStrengthWithStaticExcess)
{
  const double mu_s = 0.7, mu_k = 0.5, d_c = 2e-8, fn = 3e-3;
  FrictionStrengthParts parts;
  parts.adhesion = 4e-4;
  parts.ploughing = 2e-4;
  const double strength = 6e-4;    // mu_strength = 0.2
  const StaticKineticFriction friction(mu_s, mu_k, d_c);
  EXPECT_NEAR(friction.limit_force(0.0, fn, parts.total()), strength + 0.2 * fn, 1e-18);
  EXPECT_NEAR(friction.limit_force(0.5 * d_c, fn, parts.total()), strength + 0.1 * fn, 1e-18);
  EXPECT_NEAR(friction.limit_force(3.0 * d_c, fn, parts.total()), strength, 1e-18);
}

// Without a static excess the limit is the strength alone at every slip distance (the pure
// Bowden-Tabor contact); with no adhesion and no ploughing it is frictionless.
TEST(StrengthFriction, NoExcessIsPureStrength)
{
  FrictionStrengthParts parts;
  parts.ploughing = 1e-3;
  const StaticKineticFriction friction(0.4, 0.4, 1e-8);
  EXPECT_NEAR(friction.limit_force(0.0, 1e-2, parts.total()), 1e-3, 1e-18);
  EXPECT_NEAR(friction.limit_force(1.0, 1e-2, parts.total()), 1e-3, 1e-18);
  EXPECT_EQ(StaticKineticFriction(0.4, 0.4, 0.0).limit_force(0.0, 1e-2, FrictionStrengthParts{}.total()), 0.0);
}
