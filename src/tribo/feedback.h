// Two-mechanism roughness-feedback model (thesis ch. 3, after Mortazavi & Nosonovsky).
// One mechanism smooths the surface (friction C1 R, wear rate K1 R, feedback dR = -A k1),
// the other roughens it (friction C2 / R, wear rate K2 / R, feedback dR = +B k2):
//   mu(R)   = C1 R + C2 / R
//   k(R)    = K1 R + K2 / R
//   dR/dt   = -A K1 R + B K2 / R                                   (eq. 3.6)
// Lubricated: viscous erosion (C_vis, K_vis) + capillarity (C_cap, K_cap).
// Dry:        deformation (C_def, K_def)     + adhesion (C_adh, K_adh).
// Pure kernel: no I/O. Units are the caller's (R in a length unit, t in a time unit).
#pragma once

#include <string>

#include "tribo/contact.h"  // InvalidCoefficient

namespace runin::tribo {

enum class FeedbackKind { lubricated, dry };
const char *to_string(FeedbackKind kind);  // "lubricated" / "dry"

struct FeedbackCoefficients {
  double C1 = 0.0;  // smoothing-mechanism friction coefficient per unit R  (C_vis / C_def)
  double C2 = 0.0;  // roughening-mechanism friction coefficient times R    (C_cap / C_adh)
  double K1 = 0.0;  // smoothing wear-rate coefficient                       (K_vis / K_def)
  double K2 = 0.0;  // roughening wear-rate coefficient                      (K_cap / K_adh)
  double A = 0.0;   // feedback gain of the smoothing mechanism
  double B = 0.0;   // feedback gain of the roughening mechanism
};

class FeedbackModel {
 public:
  // Throws InvalidCoefficient naming the coefficient: every coefficient finite and >= 0,
  // C1 > 0, K1 > 0 and A > 0 (the smoothing mechanism is active, so R* is stable and a
  // friction minimum exists), and B K2 > 0 (the roughening mechanism is active, so R* > 0).
  explicit FeedbackModel(FeedbackCoefficients c, FeedbackKind kind = FeedbackKind::lubricated);

  const FeedbackCoefficients &coefficients() const { return c_; }
  FeedbackKind kind() const { return kind_; }
  // Thesis name of coefficient "C1".."K2" for this kind, e.g. "C_vis" (lubricated), "K_adh" (dry).
  std::string thesis_name(const std::string &generic) const;

  // R > 0 throughout.
  double mu(double R) const { return c_.C1 * R + c_.C2 / R; }
  double k(double R) const { return c_.K1 * R + c_.K2 / R; }
  double dRdt(double R) const { return -c_.A * c_.K1 * R + c_.B * c_.K2 / R; }

  double stationary_roughness() const;    // R* = sqrt(B K2 / (A K1))   (eq. 3.7)
  double min_wear_roughness() const;      // sqrt(K2 / K1)              (eq. 3.9)
  double min_friction_roughness() const;  // sqrt(C2 / C1)              (eq. 3.10)
  double min_mu() const;                  // mu at sqrt(C2/C1) = 2 sqrt(C1 C2)
  double min_k() const;                   // k at sqrt(K2/K1) = 2 sqrt(K1 K2)
  // R* equals the minimiser (A == B, resp. additionally K2/K1 == C2/C1), to relative 1e-12.
  bool stationary_minimises_wear() const;
  bool stationary_minimises_friction() const;

  double relaxation_rate() const { return 2.0 * c_.A * c_.K1; }  // u = R^2 relaxes as exp(-rate t)
  // Closed form: R(t)^2 = R*^2 + (R0^2 - R*^2) exp(-2 A K1 t).
  double exact_roughness(double R0, double t) const;
  // Closed-form time after which |R - R*| <= tolerance R* for ever (0 if already so at t = 0).
  double exact_settling_time(double R0, double tolerance) const;

 private:
  FeedbackCoefficients c_;
  FeedbackKind kind_;
};

}  // namespace runin::tribo
