// Elastic-plastic contact of one sphere (the equivalent sphere R*) against a flat: loading (Jackson & Green
// 2005), unloading and elastic reloading (Etsion, Kligerman & Kadin 2005), the ploughing force of the
// plastic groove and the full-stick static friction limit (Brizmer, Kligerman & Etsion 2007).
// Pure functions and small value classes: no LAMMPS, no I/O. SI units. Equations, references, ranges of
// validity and what was checked against what: doc/elastic_plastic_contact.md.
//
// Notation: omega = interference (overlap), omega* = omega / omega_c, E* effective modulus, R = R*,
// S_y yield strength and nu Poisson ratio of the body that yields (the softer one).
//
// Loading, Jackson & Green (2005), J. Tribol. 127:343-354, doi:10.1115/1.1866166:
//   C       = 1.295 exp(0.736 nu)                                    (yield onset factor)
//   omega_c = (pi C S_y / (2 E*))^2 R
//   P_c     = 4/3 (R / E*)^2 (C pi S_y / 2)^3                        (= Hertz at omega_c)
//   A_c     = pi^3 (C S_y R / (2 E*))^2                              (= pi R omega_c)
//   omega* <= 1.9: Hertz, P = 4/3 E* sqrt(R) omega^(3/2), A = pi R omega
//   omega* >= 1.9: P / P_c = exp(-1/4 omega*^(5/12)) omega*^(3/2)
//                            + 4 H_G / (C S_y) [1 - exp(-1/25 omega*^(5/9))] omega*
//                  A / A_c = omega* (omega* / 1.9)^B,  B = 0.14 exp(23 S_y / E*)
//   H_G / S_y = 2.84 [1 - exp(-0.82 (a / R)^(-0.7))],  a = sqrt(A / pi)   (geometric hardness)
// The published curve jumps at omega* = 1.9: the fit there is (1 + g) times Hertz, g between about +7.5 %
// (nu = 0) and -3 % (nu = 0.5), +0.5 % at nu = 0.3. HertzToFitTransition::kSmooth (the default) closes
// the gap on 1 < omega* < 1.9 by Hertz * (1 + g s(t)), s = t^2 (3 - 2t), t = (omega* - 1) / 0.9, so the
// force is continuous (a force loop must not see a jump); kPublished keeps the jump. Both are Hertz up to
// omega_c and the JG fit from 1.9 omega_c on. The area is continuous at 1.9 in both.
//
// Unloading from omega_max and elastic reloading below omega_max, Etsion, Kligerman & Kadin (2005),
// Int. J. Solids Struct. 42:3716-3729 (also Kadin, Kligerman & Etsion 2006, J. Mech. Phys. Solids
// 54:2652-2674), with omega*_max = omega_max / omega_c, for 1 < omega*_max <= 110:
//   omega_res / omega_max = [1 - omega*_max^(-0.28)] [1 - omega*_max^(-0.69)]
//   P / P_max = [(omega - omega_res) / (omega_max - omega_res)]^n,  n = 1.5 omega*_max^(-0.0331)
// and Hertz (omega_res = 0, n = 3/2) for omega*_max <= 1. P_max = P(omega_max) of the JG loading curve.
// Contact radius on unloading: a = a_max [(omega - omega_res) / (omega_max - omega_res)]^(n - 1), from the
// elastic-unloading relation dP/domega = 2 E* a (Pharr, Oliver & Brotzen 1992) scaled to a_max at omega_max
// (unscaled, it gives 0.74-1.19 a_max there); exact Hertz for omega*_max <= 1.
//
// The JG constants were checked against public implementations; the EKK and Brizmer et al. constants are
// from our reading of the papers and not verified against their text (doc/elastic_plastic_contact.md).
#pragma once

#include "tribo/contact.h"    // InvalidCoefficient

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace runin::tribo {

// Coefficients of one elastic-plastic sphere-on-flat contact (the sphere is the equivalent sphere R*).
struct ElasticPlasticCoefficients {
  double effective_modulus = 0.0;    // E* [Pa]
  double effective_radius = 0.0;     // R* [m]
  double yield_strength = 0.0;       // S_y of the yielding (softer) body [Pa]
  double poisson_ratio = 0.0;        // nu of the yielding body [-]
};

// How the Hertz branch meets the JG fit at omega* = 1.9 (see the header comment).
enum class HertzToFitTransition { kSmooth, kPublished };

// Force, contact radius and stiffness at one interference.
struct ContactPoint {
  double force = 0.0;             // P [N]
  double contact_radius = 0.0;    // a [m]
  double stiffness = 0.0;         // dP/domega [N/m]
};

// Jackson-Green loading curve. The constructor validates (E* > 0, R* > 0, S_y > 0, 0 <= nu < 0.5, all
// finite) and throws InvalidCoefficient naming the coefficient; evaluate() and the members take any omega
// (<= 0: no contact) and do not throw.
class JacksonGreen {
 public:
  JacksonGreen(double effective_modulus, double effective_radius, double yield_strength, double poisson_ratio,
               HertzToFitTransition transition = HertzToFitTransition::kSmooth);
  explicit JacksonGreen(const ElasticPlasticCoefficients &coefficients,
                        HertzToFitTransition transition = HertzToFitTransition::kSmooth);

  static constexpr double kFitStart = 1.9;    // omega* from which JG use their fit
  // omega* up to which the curve is tested (monotone, positive stiffness); the JG and EKK fits reach 110,
  // beyond that they are extrapolated. Hosts warn above it (NormalContact::range_ratio).
  static constexpr double kCheckedRange = 1000.0;
  // H_G / S_y as a / R -> 0: the flow pressure of a small fully plastic contact
  static constexpr double kHardnessLimit = 2.84;

  const ElasticPlasticCoefficients &coefficients() const { return c_; }
  HertzToFitTransition transition() const { return transition_; }
  double yield_factor() const { return yield_factor_; }              // C(nu)
  double area_exponent() const { return area_exponent_; }            // B
  double critical_interference() const { return omega_c_; }          // omega_c
  double critical_force() const { return force_c_; }                 // P_c
  double critical_area() const { return area_c_; }                   // A_c
  double critical_contact_radius() const { return std::sqrt(area_c_ / kPi); }
  // g: the JG fit at omega* = 1.9 over Hertz there, minus 1 (the jump kSmooth bridges).
  double transition_gap() const { return gap_; }

  // All three in one pass (header-inline: the force loops call it per contact and step).
  ContactPoint evaluate(double omega) const;
  // The same, and ln(omega*) for omega* > 1 (0 otherwise): the fit takes it anyway, and the EKK unloading
  // curve of a loading contact is a function of it (one logarithm for both).
  ContactPoint evaluate(double omega, double &log_x) const;
  double force(double omega) const { return evaluate(omega).force; }
  double contact_radius(double omega) const;                   // sqrt(A / pi)
  double contact_area(double omega) const;                     // A
  double stiffness(double omega) const { return evaluate(omega).stiffness; }
  double mean_pressure(double omega) const;                    // P / A (0 without contact)
  double hardness_geometric(double omega) const;               // H_G at the contact radius of omega

 private:
  friend class PlasticLoadingTable;    // samples the fit branch itself on both sides of 1.9
  static constexpr double kPi = 3.14159265358979323846;
  ContactPoint fit(double omega) const { double log_x; return fit(omega, log_x); }
  ContactPoint fit(double omega, double &log_x) const;    // the JG fit branch (omega* >= 1.9)

  ElasticPlasticCoefficients c_;
  HertzToFitTransition transition_;
  double yield_factor_, area_exponent_, omega_c_, inv_omega_c_, force_c_, area_c_;
  double hertz_factor_;    // 4/3 E*
  double log_strain_c_;    // ln(omega_c / R)
  double gap_ = 0.0;
};

// Unloading and elastic reloading below a maximum interference omega_max (EKK 2005, header comment). Built
// from a validated JacksonGreen; takes any omega_max (<= 0: the contact never formed) and does not throw.
// force() etc. describe the curve for omega_res < omega <= omega_max (0 below omega_res); above omega_max
// the contact loads plastically again: elastic_plastic_contact() switches to the JG curve there.
class ElasticPlasticUnloading {
 public:
  ElasticPlasticUnloading(const JacksonGreen &loading, double max_interference);

  // omega_res / omega_max of EKK as a function of omega*_max (0 for omega*_max <= 1).
  static double residual_ratio(double normalised_max_interference)
  {
    const double x = normalised_max_interference;
    if (!(x > 1.0)) return 0.0;
    return residual_ratio_of_log(std::log(x));
  }
  // The unloading exponent n = 1.5 omega*_max^(-0.0331) of EKK (3/2 for omega*_max <= 1).
  static double unloading_exponent(double normalised_max_interference)
  {
    const double x = normalised_max_interference;
    if (!(x > 1.0)) return 1.5;
    return unloading_exponent_of_log(std::log(x));
  }
  // The same from ln(omega*_max) > 0 (one logarithm serves both, and exp is cheaper than pow).
  static double residual_ratio_of_log(double log_x)
  {
    return (-std::expm1(-0.28 * log_x)) * (-std::expm1(-0.69 * log_x));
  }
  static double unloading_exponent_of_log(double log_x) { return 1.5 * std::exp(-0.0331 * log_x); }
  // The inverse of x -> residual_ratio(x) x: the omega*_max whose residual interference is
  // omega_res / omega_c = normalised_residual (> 0; 1 for <= 0). Newton on ln x, to round-off.
  static double max_interference_of_residual(double normalised_residual);

  ContactPoint evaluate(double omega) const;    // header-inline
  double force(double omega) const { return evaluate(omega).force; }
  double contact_radius(double omega) const { return evaluate(omega).contact_radius; }
  double stiffness(double omega) const { return evaluate(omega).stiffness; }

  double max_interference() const { return omega_max_; }
  double max_force() const { return force_max_; }
  double max_contact_radius() const { return radius_max_; }
  double residual_interference() const { return omega_res_; }
  double exponent() const { return exponent_; }
  bool plastic() const { return omega_res_ > 0.0; }
  // Mean pressure P_max / A_max at omega_max: the flow pressure of the groove (ploughing_force()).
  double max_mean_pressure() const;
  // Ploughing force of the permanent groove (residual depth omega_res, see sphere_groove_area) pushed at
  // the flow pressure P_max / A_max: zero below yield (omega_max <= omega_c).
  double ploughing_force() const;

 private:
  double radius_;    // R*
  double omega_max_ = 0.0, force_max_ = 0.0, radius_max_ = 0.0, omega_res_ = 0.0, exponent_ = 1.5;
  double inv_span_ = 0.0;    // 1 / (omega_max - omega_res)
};

// One evaluation with history. omega >= omega_max (or no plastic history) loads on the JG curve and raises
// omega_max to omega; omega < omega_max follows the EKK unloading/reloading curve of omega_max (force 0 at
// or below omega_res: the contact has opened). The caller stores omega_max per contact.
struct ElasticPlasticContact {
  double force = 0.0;                    // P [N]
  double contact_radius = 0.0;           // a [m]
  double stiffness = 0.0;                // dP/domega [N/m]
  double omega_max = 0.0;                // updated maximum interference [m]
  double residual_interference = 0.0;    // omega_res(omega_max) [m]
  bool plastic = false;                  // omega_max > omega_c: a permanent groove/flat exists
};
ElasticPlasticContact elastic_plastic_contact(const JacksonGreen &loading, double omega, double omega_max);

// Cross-section of the groove a sphere of radius R leaves at depth d <= 2R: the circular segment
// A_g = R^2 (theta - sin(theta) cos(theta)), cos(theta) = 1 - d/R, written as R^2 (phi - sin phi) / 2 with
// phi = 2 theta = 4 asin(sqrt(d / 2R)) and a series for small phi (no cancellation for d << R).
inline double sphere_groove_area(double radius, double depth)
{
  if (!(depth > 0.0) || !(radius > 0.0)) return 0.0;
  const double d = depth < 2.0 * radius ? depth : 2.0 * radius;
  const double half_depth = 0.5 * d / radius;    // sin^2(theta), theta = phi / 4
  const double phi = 4.0 * std::asin(std::sqrt(half_depth));
  double phi_minus_sin;
  if (phi < 1e-2) {
    const double p2 = phi * phi;    // phi - sin(phi) = phi^3/6 - phi^5/120 + phi^7/5040 - ...
    phi_minus_sin = phi * p2 * (1.0 / 6.0 - p2 * (1.0 / 120.0 - p2 * (1.0 / 5040.0)));
  } else {
    // sin(4 theta) = 4 sin(theta) cos(theta) cos(2 theta) = 4 sqrt(h (1 - h)) (1 - 2h), h = sin^2(theta):
    // exact, and one square root instead of the sine
    phi_minus_sin = phi - 4.0 * std::sqrt(half_depth * (1.0 - half_depth)) * (1.0 - 2.0 * half_depth);
  }
  return 0.5 * radius * radius * phi_minus_sin;
}

// Ploughing force of the permanent groove of residual depth `residual` that a sphere of radius R leaves,
// pushed at the mean pressure P / (pi a^2) of the contact that made it (0 for a = 0): F_p = p_m A_g.
inline double groove_ploughing_force(double force, double contact_radius, double radius, double residual)
{
  if (!(contact_radius > 0.0)) return 0.0;
  return force / (3.14159265358979323846 * contact_radius * contact_radius) * sphere_groove_area(radius, residual);
}

// Ploughing coefficient of a sphere that leaves a groove of half-width b (b <= R), Bowden & Tabor's
// two-term model with the load carried by the front half of the contact, pi b^2 / 2 (Goddard & Wilman
// 1962, Wear 5:114): mu_p = A_g / (pi b^2 / 2) = (2/pi) [(R/b)^2 asin(b/R) - sqrt((R/b)^2 - 1)];
// 4/(3 pi) b/R for b << R (the series is used there), 1 at b = R.
double sphere_ploughing_coefficient(double half_width_over_radius);

// The ploughing force of the permanent groove after loading to omega_max (ElasticPlasticUnloading::
// ploughing_force): F_p = p_m(omega_max) A_g(omega_res(omega_max)). Zero for omega_max <= omega_c.
double ploughing_force(const JacksonGreen &loading, double omega_max);
// The same with a given flow pressure (e.g. the indentation hardness H of the softer body) [Pa].
double ploughing_force(const JacksonGreen &loading, double omega_max, double flow_pressure);

// Static friction of the elastic-plastic sphere under full stick (sliding inception as loss of tangential
// stiffness), Brizmer, Kligerman & Etsion (2007), Tribol. Lett. 25:61-70:
//   mu_s = 0.27 coth(0.27 (P / L_c)^0.35)
// with L_c the critical (yield-inception) load under full stick, Brizmer, Kligerman & Etsion (2006),
// Int. J. Solids Struct. 43:5736-5749: L_c / P_c = 8.88 nu - 10.13 (nu^2 + 0.089), P_c the frictionless
// critical load (JG's, equal to Kogut & Etsion's to 0.3 % at nu = 0.3). The stick/slip ratio is fitted for
// 0.2 <= nu <= 0.5 (it is 1.0 at nu = 0.5 and turns negative below nu ~ 0.12), so the constructor requires
// nu in [0.2, 0.5). mu_s falls from ~1 at P = L_c towards 0.27 at large loads.
class BrizmerStaticFriction {
 public:
  explicit BrizmerStaticFriction(const JacksonGreen &loading);

  static double critical_load_ratio(double poisson_ratio)    // L_c(stick) / P_c(slip)
  {
    return 8.88 * poisson_ratio - 10.13 * (poisson_ratio * poisson_ratio + 0.089);
  }
  double critical_load() const { return critical_load_; }    // L_c [N]
  // mu_s at normal load P > 0 (+inf at P <= 0, where limit_force is 0).
  double coefficient(double normal_force) const { return coefficient_at(normal_force * inv_critical_load_); }
  // mu_s at the normalised load P / L_c (the fit itself; +inf at P <= 0).
  static double coefficient_at(double load_ratio)
  {
    if (!(load_ratio > 0.0)) return HUGE_VAL;
    return 0.27 / std::tanh(0.27 * std::pow(load_ratio, 0.35));
  }
  // mu_s P: the tangential force at sliding inception [N]; P^0.65 L_c^0.35 for P << L_c, 0 at P <= 0.
  double limit_force(double normal_force) const
  {
    if (!(normal_force > 0.0)) return 0.0;
    return normal_force * coefficient(normal_force);
  }

 private:
  double critical_load_, inv_critical_load_;
};

// The fully plastic branch (omega* >= 1.9) of a JacksonGreen curve, with what a loading contact derives from
// it (the EKK residual ratio and unloading exponent at omega_max = omega, the groove's ploughing force), as
// piecewise polynomials in omega*: a force loop evaluates it with a few dozen multiply-adds instead of about
// ten libm calls (one log, six exponentials, asin). Pieces are 1/16 of an octave of omega* (indexed by the
// bits of the double, no logarithm), each a degree-7 polynomial interpolating the exact curve at its 8
// Chebyshev nodes; relative error below 1e-13 (the groove 1e-10, its own closed form's cancellation) for
// omega* in [1.9, upper()) (unit test against the equations). Outside that range callers evaluate the
// equations.
struct PlasticLoadingPoint {
  double force = 0.0;               // P [N]
  double stiffness = 0.0;           // dP/domega [N/m]
  double contact_radius = 0.0;      // a [m]
  double residual_ratio = 0.0;      // omega_res / omega of EKK, omega_max = omega
  double exponent = 0.0;            // EKK unloading exponent n
  double groove_ploughing = 0.0;    // P / (pi a^2) A_g(omega_res) [N]
};
class PlasticLoadingTable {
 public:
  explicit PlasticLoadingTable(const JacksonGreen &curve);
  static constexpr double kUpper = 524288.0;    // 2^19: the pieces end there at the latest
  // Where the pieces end: kUpper, or before the piece in which the residual depth reaches the sphere's
  // radius (the groove area has a square-root singularity at the diameter, too close beyond that for the
  // polynomials; such a summit is used up anyway).
  double upper() const { return upper_; }
  bool covers(double normalised_interference) const
  {
    return normalised_interference >= JacksonGreen::kFitStart && normalised_interference < upper_;
  }
  // x = omega / omega_c with covers(x); header-inline for the force loops.
  PlasticLoadingPoint evaluate(double normalised_interference) const;
  // The exact values the table interpolates (the equations; for any x > 0).
  static PlasticLoadingPoint exact(const JacksonGreen &curve, double normalised_interference);

 private:
  static constexpr int kMantissaBits = 4, kPiecesPerOctave = 1 << kMantissaBits;
  static constexpr int kCoefficients = 8, kQuantities = 6;
  // piece index = the double's exponent and top mantissa bits, minus that of the piece holding 1.9
  static constexpr int kFirstPiece = (1023 << kMantissaBits) + 14;    // [1.875, 2)
  static constexpr int kPieces = 19 * kPiecesPerOctave - 14;
  struct Piece {
    double centre, inv_half_width;
    double coefficient[kCoefficients][kQuantities];    // monomials in t = (x - centre) / half width
  };
  void end_before(int piece);    // the table ends where this piece starts
  std::vector<Piece> pieces_;
  double upper_ = kUpper;
};

// ---- inline definitions -------------------------------------------------------------------------------

inline ContactPoint JacksonGreen::evaluate(double omega) const
{
  double log_x;
  return evaluate(omega, log_x);
}

inline ContactPoint JacksonGreen::evaluate(double omega, double &log_x) const
{
  ContactPoint out;
  log_x = 0.0;
  if (!(omega > 0.0)) return out;
  const double x = omega * inv_omega_c_;
  if (!(x < kFitStart)) return fit(omega, log_x);
  if (x > 1.0) log_x = std::log(x);
  // Hertz: a = sqrt(R omega), P = 4/3 E* a omega, dP/domega = 2 E* a
  const double a = std::sqrt(c_.effective_radius * omega);
  out.contact_radius = a;
  out.force = hertz_factor_ * a * omega;
  out.stiffness = 2.0 * c_.effective_modulus * a;
  if (x > 1.0 && transition_ == HertzToFitTransition::kSmooth) {
    // P = P_H (1 + g s(t)): continuous value at 1.9 and value and slope at 1
    const double t = (x - 1.0) * (1.0 / (kFitStart - 1.0));
    const double s = t * t * (3.0 - 2.0 * t);
    const double ds_domega = 6.0 * t * (1.0 - t) * (1.0 / (kFitStart - 1.0)) * inv_omega_c_;
    out.stiffness = out.stiffness * (1.0 + gap_ * s) + out.force * gap_ * ds_domega;
    out.force *= 1.0 + gap_ * s;
  }
  return out;
}

// The published fit with its libm calls shared (one log and five exponentials): every power of omega* is
// an exponential of ln omega*, x^(5/12) and x^(5/9) are y^3 and y^4 of y = x^(5/36), and (a/R)^(-0.7) is
// an exponential of ln(a/R) = (ln(omega/R) + B (ln x - ln 1.9)) / 2 with ln(omega/R) = ln x + ln(omega_c/R).
// The same equations as written in the header comment, to round-off.
inline ContactPoint JacksonGreen::fit(double omega, double &log_x_out) const
{
  constexpr double kLogFitStart = 0.64185388617239469;    // ln 1.9
  ContactPoint out;
  const double x = omega * inv_omega_c_;
  const double log_x = std::log(x);
  log_x_out = log_x;
  const double B = area_exponent_;
  // a = sqrt(A / pi) = sqrt(R omega) (x / 1.9)^(B/2); q = a / R
  const double log_growth = 0.5 * B * (log_x - kLogFitStart);
  const double growth = std::exp(log_growth);
  const double a = std::sqrt(c_.effective_radius * omega) * growth;
  // q^(-0.7) = exp(-0.7 ln q), ln q = (ln x + ln(omega_c / R)) / 2 + ln growth
  const double q_pow = std::exp(-0.7 * (0.5 * (log_x + log_strain_c_) + log_growth));
  const double e_h = std::exp(-0.82 * q_pow);
  const double h = kHardnessLimit * (1.0 - e_h);    // H_G / S_y
  // x^(5/12) = y^3 and x^(5/9) = y^4 with y = x^(5/36)
  const double y = std::exp(5.0 / 36.0 * log_x);
  const double x_512 = y * y * y;
  const double x_59 = x_512 * y;
  // first term: exp(-x^(5/12) / 4) x^(3/2), one exponential
  const double t1 = std::exp(1.5 * log_x - 0.25 * x_512);
  // second term: 4 h / C (1 - exp(-x^(5/9) / 25)) x
  const double g_2 = -std::expm1(-0.04 * x_59);
  const double e_2 = 1.0 - g_2;    // exp(-x^(5/9) / 25), in (0, 1]: no cancellation
  const double four_over_c = 4.0 / yield_factor_;
  const double t2 = four_over_c * h * g_2 * x;
  // derivatives in x: dq/dx = q (1 + B) / (2x) and dh/dq = -2.84 * 0.574 q^(-1.7) e_h
  const double inv_x = 1.0 / x;
  const double dt1 = t1 * (1.5 - 0.25 * 5.0 / 12.0 * x_512) * inv_x;
  const double dh = -kHardnessLimit * 0.82 * 0.7 * q_pow * e_h * 0.5 * (1.0 + B) * inv_x;
  const double dg_2 = 0.04 * 5.0 / 9.0 * x_59 * e_2 * inv_x;
  const double dt2 = four_over_c * (dh * g_2 * x + h * dg_2 * x + h * g_2);
  out.contact_radius = a;
  out.force = force_c_ * (t1 + t2);
  out.stiffness = force_c_ * inv_omega_c_ * (dt1 + dt2);
  return out;
}

inline ElasticPlasticUnloading::ElasticPlasticUnloading(const JacksonGreen &loading, double max_interference)
    : radius_(loading.coefficients().effective_radius)
{
  if (!(max_interference > 0.0)) return;
  omega_max_ = max_interference;
  const ContactPoint peak = loading.evaluate(max_interference);
  force_max_ = peak.force;
  radius_max_ = peak.contact_radius;
  const double x = max_interference / loading.critical_interference();
  omega_res_ = residual_ratio(x) * max_interference;
  exponent_ = unloading_exponent(x);
  inv_span_ = 1.0 / (omega_max_ - omega_res_);
}

inline ContactPoint ElasticPlasticUnloading::evaluate(double omega) const
{
  ContactPoint out;
  if (!(omega > omega_res_) || !(omega_max_ > 0.0)) return out;
  const double gap = omega - omega_res_;
  const double s = gap * inv_span_;    // 1 at omega_max
  const double s_n = std::exp(exponent_ * std::log(s));
  out.force = force_max_ * s_n;
  out.stiffness = exponent_ * out.force / gap;
  out.contact_radius = radius_max_ * s_n / s;    // a_max s^(n-1)
  return out;
}

inline ElasticPlasticContact elastic_plastic_contact(const JacksonGreen &loading, double omega,
                                                     double omega_max)
{
  ElasticPlasticContact out;
  out.omega_max = omega_max > 0.0 ? omega_max : 0.0;
  const double inv_omega_c = 1.0 / loading.critical_interference();
  if (omega >= out.omega_max) {
    // loading (or first contact): the JG curve, and the history follows
    if (omega > 0.0) out.omega_max = omega;
    const ContactPoint p = loading.evaluate(omega);
    out.force = p.force;
    out.contact_radius = p.contact_radius;
    out.stiffness = p.stiffness;
  } else if (out.omega_max * inv_omega_c <= 1.0) {
    // elastic history: unloading is the Hertz loading curve itself
    const ContactPoint p = loading.evaluate(omega);
    out.force = p.force;
    out.contact_radius = p.contact_radius;
    out.stiffness = p.stiffness;
  } else {
    const ContactPoint p = ElasticPlasticUnloading(loading, out.omega_max).evaluate(omega);
    out.force = p.force;
    out.contact_radius = p.contact_radius;
    out.stiffness = p.stiffness;
  }
  out.residual_interference = ElasticPlasticUnloading::residual_ratio(out.omega_max * inv_omega_c) * out.omega_max;
  out.plastic = out.omega_max * inv_omega_c > 1.0;
  return out;
}

inline PlasticLoadingPoint PlasticLoadingTable::evaluate(double x) const
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const Piece &piece = pieces_[static_cast<int>(bits >> (52 - kMantissaBits)) - kFirstPiece];
  const double t = (x - piece.centre) * piece.inv_half_width;
  double v[kQuantities];
  for (int q = 0; q < kQuantities; ++q) v[q] = piece.coefficient[kCoefficients - 1][q];
  for (int k = kCoefficients - 2; k >= 0; --k)
    for (int q = 0; q < kQuantities; ++q) v[q] = v[q] * t + piece.coefficient[k][q];
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

}    // namespace runin::tribo
