#include "tribo/friction_strength.h"

#include "tribo/contact.h"

#include <cmath>

namespace runin::tribo {

AdhesionPloughing::AdhesionPloughing(double shear_strength, double ploughing_factor)
    : tau_s_(shear_strength), ploughing_factor_(ploughing_factor)
{
  if (!(shear_strength >= 0.0) || !std::isfinite(shear_strength))
    throw InvalidCoefficient("tau_s: interfacial shear strength must be >= 0");
  // 1 is the groove of the plastic interference itself; a factor beyond 10 describes no groove (1e308 gave a
  // ploughing friction coefficient of 1e305)
  if (!(ploughing_factor >= 0.0 && ploughing_factor <= 10.0))
    throw InvalidCoefficient("plough: ploughing factor must lie in [0, 10]");
}

}    // namespace runin::tribo
