#include "tribo/elastic_plastic.h"

#include <cmath>
#include <sstream>
#include <string>

namespace runin::tribo {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string format(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

void require_finite(double value, const std::string &what)
{
  if (!std::isfinite(value)) throw InvalidCoefficient(what + " must be finite, got " + format(value));
}

void require_positive(double value, const std::string &what)
{
  require_finite(value, what);
  if (!(value > 0.0)) throw InvalidCoefficient(what + " must be > 0, got " + format(value));
}

}    // namespace

JacksonGreen::JacksonGreen(double effective_modulus, double effective_radius, double yield_strength,
                           double poisson_ratio, HertzToFitTransition transition)
    : JacksonGreen(ElasticPlasticCoefficients{effective_modulus, effective_radius, yield_strength, poisson_ratio},
                   transition)
{
}

JacksonGreen::JacksonGreen(const ElasticPlasticCoefficients &coefficients, HertzToFitTransition transition)
    : c_(coefficients), transition_(transition)
{
  require_positive(c_.effective_modulus, "E*: effective modulus");
  require_positive(c_.effective_radius, "R*: effective radius");
  require_positive(c_.yield_strength, "S_y: yield strength");
  require_finite(c_.poisson_ratio, "nu: Poisson ratio");
  if (!(c_.poisson_ratio >= 0.0 && c_.poisson_ratio < 0.5))
    throw InvalidCoefficient("nu: Poisson ratio must be in [0, 0.5), got " + format(c_.poisson_ratio));

  const double E = c_.effective_modulus, R = c_.effective_radius, S = c_.yield_strength;
  yield_factor_ = 1.295 * std::exp(0.736 * c_.poisson_ratio);
  area_exponent_ = 0.14 * std::exp(23.0 * S / E);
  const double strain = kPi * yield_factor_ * S / (2.0 * E);    // sqrt(omega_c / R)
  omega_c_ = strain * strain * R;
  inv_omega_c_ = 1.0 / omega_c_;
  const double load = yield_factor_ * kPi * S / 2.0;
  force_c_ = 4.0 / 3.0 * (R / E) * (R / E) * load * load * load;
  const double radius_c = yield_factor_ * S * R / (2.0 * E);
  area_c_ = kPi * kPi * kPi * radius_c * radius_c;
  hertz_factor_ = 4.0 / 3.0 * E;
  log_strain_c_ = std::log(omega_c_ / R);
  if (!std::isfinite(area_exponent_) || !(omega_c_ > 0.0) || !std::isfinite(omega_c_) || !(force_c_ > 0.0) ||
      !std::isfinite(force_c_))
    throw InvalidCoefficient("E*, R*, S_y: critical interference or load under- or overflows (S_y/E* = " +
                             format(S / E) + ", R* = " + format(R) + ")");

  // the jump of the published curve at omega* = 1.9, with the Hertz value computed as evaluate() does
  const double omega_t = kFitStart * omega_c_;
  const double hertz_t = hertz_factor_ * std::sqrt(R * omega_t) * omega_t;
  gap_ = fit(omega_t).force / hertz_t - 1.0;
}

double JacksonGreen::contact_radius(double omega) const
{
  return evaluate(omega).contact_radius;
}

double JacksonGreen::contact_area(double omega) const
{
  const double a = contact_radius(omega);
  return kPi * a * a;
}

double JacksonGreen::mean_pressure(double omega) const
{
  const ContactPoint p = evaluate(omega);
  if (!(p.contact_radius > 0.0)) return 0.0;
  return p.force / (kPi * p.contact_radius * p.contact_radius);
}

double JacksonGreen::hardness_geometric(double omega) const
{
  const double q = contact_radius(omega) / c_.effective_radius;
  if (!(q > 0.0)) return kHardnessLimit * c_.yield_strength;    // the limit a/R -> 0
  return kHardnessLimit * c_.yield_strength * (1.0 - std::exp(-0.82 * std::pow(q, -0.7)));
}

double ElasticPlasticUnloading::max_interference_of_residual(double d)
{
  if (!(d > 0.0)) return 1.0;
  if (!std::isfinite(d)) return d;
  // f(u) = ln(r(x) x) - ln d with u = ln x, r = (1 - x^-0.28)(1 - x^-0.69): increasing in u, concave for large
  // u; bracketed Newton (bisection where a step leaves the bracket).
  const double target = std::log(d);
  auto f = [&](double u, double &slope) {
    const double e1 = std::exp(-0.28 * u), e2 = std::exp(-0.69 * u);
    const double g1 = -std::expm1(-0.28 * u), g2 = -std::expm1(-0.69 * u);
    slope = 1.0 + 0.28 * e1 / g1 + 0.69 * e2 / g2;
    return std::log(g1) + std::log(g2) + u - target;
  };
  double lo = 0.0, hi = std::max(1.0, target + 2.0);
  double slope;
  while (f(hi, slope) < 0.0) hi *= 2.0;
  double u = std::max(target, 0.5 * hi);
  if (!(u > lo && u < hi)) u = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double value = f(u, slope);
    if (value == 0.0) break;
    (value < 0.0 ? lo : hi) = u;
    double next = u - value / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::fabs(next - u) <= 1e-15 * std::max(1.0, std::fabs(u)) || hi - lo <= 1e-16 * std::max(1.0, hi)) {
      u = next;
      break;
    }
    u = next;
  }
  return std::exp(u);
}

double ElasticPlasticUnloading::max_mean_pressure() const
{
  if (!(radius_max_ > 0.0)) return 0.0;
  return force_max_ / (kPi * radius_max_ * radius_max_);
}

double ElasticPlasticUnloading::ploughing_force() const
{
  return groove_ploughing_force(force_max_, radius_max_, radius_, omega_res_);
}

double sphere_ploughing_coefficient(double half_width_over_radius)
{
  const double r = half_width_over_radius;
  if (!(r > 0.0)) return 0.0;
  if (r >= 1.0) return 1.0;    // a hemisphere: A_g = pi R^2 / 2 = pi b^2 / 2
  if (r < 1e-3) {
    // (2/pi) [r/6 + r/2 + (3/40 + 1/8) r^3 + ...] = (2/pi) (2r/3 + r^3/5 + ...)
    return 2.0 / kPi * r * (2.0 / 3.0 + r * r / 5.0);
  }
  const double inv = 1.0 / r;
  return 2.0 / kPi * (inv * inv * std::asin(r) - std::sqrt(inv * inv - 1.0));
}

double ploughing_force(const JacksonGreen &loading, double omega_max)
{
  return ElasticPlasticUnloading(loading, omega_max).ploughing_force();
}

double ploughing_force(const JacksonGreen &loading, double omega_max, double flow_pressure)
{
  if (!(flow_pressure > 0.0)) return 0.0;
  const double residual =
      ElasticPlasticUnloading::residual_ratio(omega_max / loading.critical_interference()) * omega_max;
  return flow_pressure * sphere_groove_area(loading.coefficients().effective_radius, residual);
}

BrizmerStaticFriction::BrizmerStaticFriction(const JacksonGreen &loading)
{
  const double nu = loading.coefficients().poisson_ratio;
  if (!(nu >= 0.2 && nu < 0.5))
    throw InvalidCoefficient("nu: Poisson ratio must be in [0.2, 0.5) for the full-stick critical load of "
                             "Brizmer et al. (2006), got " + format(nu));
  critical_load_ = critical_load_ratio(nu) * loading.critical_force();
  inv_critical_load_ = 1.0 / critical_load_;
}

PlasticLoadingPoint PlasticLoadingTable::exact(const JacksonGreen &curve, double x)
{
  const double omega = x * curve.critical_interference();
  double log_x;
  const ContactPoint p = curve.fit(omega, log_x);
  PlasticLoadingPoint out;
  out.force = p.force;
  out.stiffness = p.stiffness;
  out.contact_radius = p.contact_radius;
  out.residual_ratio = ElasticPlasticUnloading::residual_ratio_of_log(log_x);
  out.exponent = ElasticPlasticUnloading::unloading_exponent_of_log(log_x);
  out.groove_ploughing = groove_ploughing_force(p.force, p.contact_radius, curve.coefficients().effective_radius,
                                                out.residual_ratio * omega);
  return out;
}

PlasticLoadingTable::PlasticLoadingTable(const JacksonGreen &curve) : pieces_(kPieces)
{
  // T_k(t) as monomial coefficients, for the conversion of each piece's Chebyshev series
  long double chebyshev[kCoefficients][kCoefficients] = {};
  chebyshev[0][0] = 1.0L;
  chebyshev[1][1] = 1.0L;
  for (int k = 2; k < kCoefficients; ++k)
    for (int m = 0; m < kCoefficients; ++m)
      chebyshev[k][m] = (m > 0 ? 2.0L * chebyshev[k - 1][m - 1] : 0.0L) - chebyshev[k - 2][m];
  const long double pi = 3.141592653589793238462643383279502884L;

  for (int p = 0; p < kPieces; ++p) {
    const int index = kFirstPiece + p;
    const double octave = std::ldexp(1.0, (index >> kMantissaBits) - 1023);
    const double half_width = octave / (2 * kPiecesPerOctave);    // a power of two: t is exact to rounding
    Piece &piece = pieces_[p];
    piece.centre = octave * (1.0 + static_cast<double>(index & (kPiecesPerOctave - 1)) / kPiecesPerOctave) +
                   half_width;
    piece.inv_half_width = 1.0 / half_width;

    long double series[kCoefficients][kQuantities] = {};
    bool finite = true;
    for (int j = 0; j < kCoefficients; ++j) {
      const long double angle = pi * (j + 0.5L) / kCoefficients;
      const double t = static_cast<double>(std::cos(angle));
      const PlasticLoadingPoint v = exact(curve, piece.centre + t * half_width);
      const double values[kQuantities] = {v.force,    v.stiffness, v.contact_radius, v.residual_ratio,
                                          v.exponent, v.groove_ploughing};
      for (double value : values) finite = finite && std::isfinite(value);
      for (int k = 0; k < kCoefficients; ++k) {
        const long double weight = (k == 0 ? 1.0L : 2.0L) / kCoefficients * std::cos(k * angle);
        for (int q = 0; q < kQuantities; ++q) series[k][q] += weight * values[q];
      }
    }
    if (!finite) {
      // the fit overflows from here on (extreme S_y/E*: B = 0.14 exp(23 S_y/E*) reaches hundreds): the
      // equations take over, and a non-finite force is caught by the hosts' finite-force check as before
      end_before(p);
      break;
    }
    for (int m = 0; m < kCoefficients; ++m)
      for (int q = 0; q < kQuantities; ++q) {
        long double monomial = 0.0L;
        for (int k = m; k < kCoefficients; ++k) monomial += series[k][q] * chebyshev[k][m];
        piece.coefficient[m][q] = static_cast<double>(monomial);
      }
    const double end = piece.centre + half_width;
    const double omega_end = end * curve.critical_interference();
    if (exact(curve, end).residual_ratio * omega_end >= curve.coefficients().effective_radius) {
      end_before(p);
      break;
    }
  }
}

void PlasticLoadingTable::end_before(int piece)
{
  upper_ = pieces_[piece].centre - 1.0 / pieces_[piece].inv_half_width;
  pieces_.resize(piece);    // only the pieces below upper_ are ever read
}

}    // namespace runin::tribo
