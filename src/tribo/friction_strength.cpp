#include "tribo/friction_strength.h"

#include "tribo/contact.h"

#include <cmath>

namespace runin::tribo {

AdhesionPloughing::AdhesionPloughing(double shear_strength, double ploughing_factor)
    : tau_s_(shear_strength), ploughing_factor_(ploughing_factor)
{
  if (!(shear_strength >= 0.0) || !std::isfinite(shear_strength))
    throw InvalidCoefficient("tau_s: interfacial shear strength must be >= 0");
  if (!(ploughing_factor >= 0.0) || !std::isfinite(ploughing_factor))
    throw InvalidCoefficient("plough: ploughing factor must be >= 0");
}

}    // namespace runin::tribo
