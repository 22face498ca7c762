// Micro origin of the sliding friction of one asperity contact: adhesion + ploughing.
// Pure functions and a small validating class; SI units. See doc/worn_asperity_geometry.md.
#pragma once

#include <array>
#include <limits>
#include <string>

namespace runin::tribo {

struct FrictionStrengthParts {
  double adhesion = 0.0;     // tau_s pi a^2 [N]
  double ploughing = 0.0;    // mu_p F_n [N]
  double total() const { return adhesion + ploughing; }
};

// F_t = tau_s A_r + mu_p F_n (Bowden & Tabor's two-term model).
//  - adhesion: interfacial shear strength tau_s times the real contact area pi a^2;
//  - ploughing: Rabinowicz's cone, mu_p = (2/pi) tan(theta) (Friction and Wear of Materials, 2nd ed.,
//    1995, sec. 4.5), with the attack angle of the cone that has the contact's penetration depth and
//    contact radius: tan(theta) = delta / a (Hokkirigawa & Kato's degree of penetration, Tribol. Int. 21,
//    1988). For the Sneddon contact delta / a = c / R (c the curved ring, R the curvature radius), so
//    tan(theta) = a / R for an unworn sphere and falls as wear widens the flat.
// A smooth asperity field (small R) ploughs more; a large one has more contact area to shear. This is the
// micro origin of the thesis's dry law mu = C_def R + C_adh / R (ch. 3, Mortazavi & Nosonovsky).
class AdhesionPloughing {
 public:
  // shear_strength tau_s [Pa] >= 0; ploughing_factor scales mu_p (1 = Rabinowicz's cone, 0 = off), >= 0.
  AdhesionPloughing(double shear_strength, double ploughing_factor = 1.0);

  static double ploughing_coefficient(double tan_attack_angle)    // (2/pi) tan(theta)
  {
    return 2.0 / 3.14159265358979323846 * tan_attack_angle;
  }
  // Inline: pair runin/asperity evaluates it for every contact and step.
  FrictionStrengthParts strength(double normal_force, double contact_radius, double overlap) const
  {
    FrictionStrengthParts parts;
    if (!(contact_radius > 0.0)) return parts;
    parts.adhesion = tau_s_ * 3.14159265358979323846 * contact_radius * contact_radius;
    if (overlap > 0.0 && normal_force > 0.0)
      parts.ploughing = ploughing_factor_ * ploughing_coefficient(overlap / contact_radius) * normal_force;
    return parts;
  }
  double shear_strength() const { return tau_s_; }
  double ploughing_factor() const { return ploughing_factor_; }

 private:
  double tau_s_, ploughing_factor_;
};

// Interfacial shear strength from the state of the interface (doc/interface_strength.md): tau_s = m k_soft, with
// k_soft = S_y / sqrt(3) the von Mises shear yield strength of the softer body and m in [0, 1] the friction factor
// of the metal-forming literature (m = 1: the interface as strong as the softer body, sticking). The coefficient
// files give m per material pair and state ('interface A B STATE m').
constexpr int kInterfaceStates = 3;
constexpr std::array<const char *, kInterfaceStates> kInterfaceStateNames{"clean", "oxidised", "boundary"};
using InterfaceFactors = std::array<double, kInterfaceStates>;    // m per state; NaN: no line for it
inline InterfaceFactors no_interface_factors()
{
  InterfaceFactors none;
  none.fill(std::numeric_limits<double>::quiet_NaN());
  return none;
}
// Index of a state; throws InvalidCoefficient "unknown interface state 'x' (known: clean, oxidised, boundary)".
int find_interface_state(const std::string &name);
// "clean, oxidised, boundary"
std::string interface_state_list();
// S_y / sqrt(3) [Pa]
double shear_yield_strength(double yield_strength);
// m S_y / sqrt(3); throws InvalidCoefficient naming m (outside [0, 1]) or S_y (not > 0 and finite).
double interface_shear_strength(double friction_factor, double yield_strength_soft);
// An interface cannot shear harder than the softer body under it: throws InvalidCoefficient naming tau_s when
// tau_s > S_y / sqrt(3).
void check_interface_strength(double shear_strength, double yield_strength_soft);

}    // namespace runin::tribo
