#include "tribo/friction_strength.h"

#include "tribo/contact.h"

#include <cmath>

namespace runin::tribo {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

AdhesionPloughing::AdhesionPloughing(double shear_strength, double ploughing_factor)
    : tau_s_(shear_strength), ploughing_factor_(ploughing_factor)
{
  if (!(shear_strength >= 0.0) || !std::isfinite(shear_strength))
    throw InvalidCoefficient("tau_s: interfacial shear strength must be >= 0");
  if (!(ploughing_factor >= 0.0) || !std::isfinite(ploughing_factor))
    throw InvalidCoefficient("plough: ploughing factor must be >= 0");
}

double AdhesionPloughing::ploughing_coefficient(double tan_attack_angle)
{
  return 2.0 / kPi * tan_attack_angle;
}

FrictionStrengthParts AdhesionPloughing::strength(double normal_force, double contact_radius,
                                                  double overlap) const
{
  FrictionStrengthParts parts;
  if (!(contact_radius > 0.0)) return parts;
  parts.adhesion = tau_s_ * kPi * contact_radius * contact_radius;
  if (overlap > 0.0 && normal_force > 0.0)
    parts.ploughing = ploughing_factor_ * ploughing_coefficient(overlap / contact_radius) * normal_force;
  return parts;
}

}    // namespace runin::tribo
