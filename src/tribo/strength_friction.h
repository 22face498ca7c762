// Coulomb limit of one contact whose kinetic level comes from its micro friction strength
// (adhesion + ploughing, friction_strength.h) instead of a fixed mu_k. Header-only; SI units.
#pragma once

#include "tribo/contact.h"
#include "tribo/friction_strength.h"

namespace runin::tribo {

// The kinetic coefficient is (F_adh + F_pl) / F_n of this contact; the static excess mu_s - mu_k of the
// coefficient set still weakens over d_c, so a fresh (or re-stuck) contact breaks away at
// mu_strength + (mu_s - mu_k). normal_force must be > 0.
inline StaticKineticFriction strength_friction(double mu_static, double mu_kinetic, double slip_weakening_distance,
                                               const FrictionStrengthParts &parts, double normal_force)
{
  const double mu_strength = parts.total() / normal_force;
  return StaticKineticFriction(mu_strength + (mu_static - mu_kinetic), mu_strength, slip_weakening_distance);
}

}    // namespace runin::tribo
