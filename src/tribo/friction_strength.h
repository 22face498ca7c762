// Micro origin of the sliding friction of one asperity contact: adhesion + ploughing.
// Pure functions and a small validating class; SI units. See doc/worn_asperity_geometry.md.
#pragma once

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

}    // namespace runin::tribo
