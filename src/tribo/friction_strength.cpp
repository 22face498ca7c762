#include "tribo/friction_strength.h"

#include "tribo/contact.h"

#include <cmath>
#include <cstdio>

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

namespace {
std::string format(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}
}    // namespace

std::string interface_state_list()
{
  std::string out;
  for (const char *name : kInterfaceStateNames) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

int find_interface_state(const std::string &name)
{
  for (int k = 0; k < kInterfaceStates; ++k)
    if (name == kInterfaceStateNames[k]) return k;
  throw InvalidCoefficient("interface: unknown interface state '" + name + "' (known: " + interface_state_list() + ")");
}

double shear_yield_strength(double yield_strength) { return yield_strength / std::sqrt(3.0); }

double interface_shear_strength(double friction_factor, double yield_strength_soft)
{
  if (!(friction_factor >= 0.0 && friction_factor <= 1.0))
    throw InvalidCoefficient("m: interface friction factor must be in [0, 1] (tau_s / (S_y / sqrt(3)) of the softer "
                             "body), got " + format(friction_factor));
  if (!(yield_strength_soft > 0.0) || !std::isfinite(yield_strength_soft))
    throw InvalidCoefficient("S_y: tau_s = m S_y / sqrt(3) needs the yield strength of the softer body, got " +
                             format(yield_strength_soft));
  return friction_factor * shear_yield_strength(yield_strength_soft);
}

void check_interface_strength(double shear_strength, double yield_strength_soft)
{
  const double k = shear_yield_strength(yield_strength_soft);
  if (shear_strength > k)
    throw InvalidCoefficient("tau_s: interfacial shear strength " + format(shear_strength) +
                             " Pa exceeds the shear yield strength of the softer body, S_y / sqrt(3) = " + format(k) +
                             " Pa (S_y = " + format(yield_strength_soft) +
                             " Pa): an interface cannot be stronger than the body under it; lower tau_s");
}

}    // namespace runin::tribo
