#include "tribo/greenwood_tripp.h"

#include "tribo/contact.h"

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace runin::tribo {

namespace {

const double kPi = std::acos(-1.0);


// int_H^T (s - H)^n phi(s) ds = int_0^sqrt(T - H) 2 t^(2n+1) phi(H + t^2) dt (s - H = t^2 makes the integrand
// smooth at the lower end), composite 8-point Gauss-Legendre on `panels` panels.
double band_moment(double n, double H, double T, int panels)
{
  static constexpr double nodes[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                      0.9602898564975363};
  static constexpr double weights[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                        0.1012285362903763};
  const double w = std::sqrt(T - H) / panels;
  double sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const double centre = (p + 0.5) * w;
    for (int k = 0; k < 4; ++k)
      for (const double sign : {-1.0, 1.0}) {
        const double x = centre + sign * 0.5 * w * nodes[k];
        const double s = H + x * x;
        sum += weights[k] * 2.0 * std::pow(x, 2.0 * n + 1.0) * std::exp(-0.5 * s * s);
      }
  }
  return 0.5 * w * sum / std::sqrt(2.0 * kPi);
}

// F_n(H): the band up to s = max(H, 0) + 12 (phi(12) / phi(0) < 1e-31). Relative accuracy ~1e-13 against an
// independent exp-sinh quadrature for -3 <= H <= 8 (unit test); about 8x cheaper than gaussian_tail_moment,
// which matters for a pressure evaluated at every grid node.
double tail_moment(double n, double H) { return band_moment(n, H, std::max(H, 0.0) + 12.0, 24); }

double upper_tail(double x) { return 0.5 * std::erfc(x / std::sqrt(2.0)); }

}    // namespace

double greenwood_tripp_f_truncated(double n, double H, double T)
{
  if (!(n >= 0.0)) throw InvalidCoefficient("n: Greenwood-Tripp moment order must be >= 0");
  if (!std::isfinite(H)) throw InvalidCoefficient("h/sigma: film parameter must be finite");
  if (std::isnan(T)) throw InvalidCoefficient("top/sigma: the worn summits' top must not be NaN");
  if (H >= T) return 0.0;
  // beyond 12 sigma above both the cut changes nothing representable (phi(12) / phi(0) < 1e-31)
  if (T >= std::max(H, 0.0) + 12.0) return greenwood_tripp_f(n, H);
  // panels no wider in t than the tail's (sqrt(12) / 24): a narrow band of worn summits needs fewer
  const int panels = std::max(2, static_cast<int>(std::ceil(24.0 * std::sqrt((T - H) / 12.0))));
  return band_moment(n, H, T, panels) + std::pow(T - H, n) * upper_tail(T);
}

double truncated_rms_ratio(double T)
{
  if (std::isnan(T)) throw InvalidCoefficient("top/sigma: the worn summits' top must not be NaN");
  if (T >= 40.0) return 1.0;
  const double phi = std::exp(-0.5 * T * T) / std::sqrt(2.0 * kPi), q = upper_tail(T), below = 1.0 - q;
  const double mean = -phi + T * q;                     // E[min(x, T)]
  const double second = below - T * phi + T * T * q;    // E[min(x, T)^2]
  return std::sqrt(std::max(0.0, second - mean * mean));
}

double greenwood_tripp_f(double n, double H)
{
  if (!(n >= 0.0)) throw InvalidCoefficient("n: Greenwood-Tripp moment order must be >= 0");
  if (!std::isfinite(H)) throw InvalidCoefficient("h/sigma: film parameter must be finite");
  const double q = 0.5 * std::erfc(H / std::sqrt(2.0));
  const double phi = std::exp(-0.5 * H * H) / std::sqrt(2.0 * kPi);
  if (n == 0.0) return q;
  if (n == 1.0) return phi - H * q;
  // F_2 = (1 + H^2) Q - H phi cancels for large H; there the quadrature is the accurate one
  if (n == 2.0 && H < 3.0) return (1.0 + H * H) * q - H * phi;
  return tail_moment(n, H);
}

GreenwoodTripp::GreenwoodTripp(double summit_density, double summit_radius, double sigma,
                               double effective_modulus) :
    eta_(summit_density), beta_(summit_radius), sigma_(sigma), e_eff_(effective_modulus)
{
  require_positive_finite(eta_, "eta: summit density");
  require_positive_finite(beta_, "beta: summit radius");
  require_positive_finite(sigma_, "sigma: combined roughness");
  require_positive_finite(e_eff_, "E*: effective modulus");
  const double ebs = eta_ * beta_ * sigma_;
  k_ = 16.0 * std::sqrt(2.0) / 15.0 * kPi * ebs * ebs * std::sqrt(sigma_ / beta_);
}

double GreenwoodTripp::pressure(double h) const
{
  return k_ * e_eff_ * greenwood_tripp_f(2.5, h / sigma_);
}

double GreenwoodTripp::area_fraction(double h) const
{
  const double ebs = eta_ * beta_ * sigma_;
  return kPi * kPi * ebs * ebs * greenwood_tripp_f(2.0, h / sigma_);
}

double GreenwoodTripp::pressure(double h, double top) const
{
  return k_ * e_eff_ * greenwood_tripp_f_truncated(2.5, h / sigma_, top / sigma_);
}

double GreenwoodTripp::area_fraction(double h, double top) const
{
  const double ebs = eta_ * beta_ * sigma_;
  return kPi * kPi * ebs * ebs * greenwood_tripp_f_truncated(2.0, h / sigma_, top / sigma_);
}

double GreenwoodTripp::worn_volume(double top) const
{
  if (std::isnan(top)) throw InvalidCoefficient("top: the worn summits' top must not be NaN");
  if (top == HUGE_VAL) return 0.0;
  return kPi * eta_ * beta_ * sigma_ * sigma_ * greenwood_tripp_f(2.0, top / sigma_);
}

double GreenwoodTripp::top_after_wear(double worn) const
{
  if (!(worn >= 0.0) || !std::isfinite(worn))
    throw InvalidCoefficient("worn volume: must be >= 0 and finite, got " + std::to_string(worn));
  const double scale = kPi * eta_ * beta_ * sigma_ * sigma_;
  const double target = worn / scale;   // F_2(t) = target, F_2 falls monotonically in t
  constexpr double t_high = 12.0;
  if (target <= greenwood_tripp_f(2.0, t_high)) return HUGE_VAL;
  double t_low = -1.0;
  while (greenwood_tripp_f(2.0, t_low) < target) t_low *= 2.0;   // F_2(t) ~ t^2 for t -> -inf
  auto excess = [&](double t) { return greenwood_tripp_f(2.0, t) - target; };
  std::uintmax_t iterations = 200;
  const auto r = boost::math::tools::toms748_solve(
      excess, t_low, t_high, [](double a, double b) { return std::abs(b - a) <= 1e-14 * std::max(1.0, std::abs(b)); },
      iterations);
  return sigma_ * 0.5 * (r.first + r.second);
}

const char *to_string(LoadShareStatus status)
{
  switch (status) {
  case LoadShareStatus::Converged: return "converged";
  case LoadShareStatus::FilmCarriesAll: return "film carries all";
  case LoadShareStatus::NotBracketed: return "not bracketed";
  case LoadShareStatus::NotConverged: return "not converged";
  }
  return "?";
}

LoadShare solve_load_share(double load, const std::function<double(double)> &film_load,
                           const std::function<double(double)> &asperity_load, double sigma, double h_min,
                           double h_max, double rel_tol, int max_iterations)
{
  require_positive_finite(load, "load");
  require_positive_finite(sigma, "sigma");
  if (!(h_max > h_min) || !std::isfinite(h_min) || !std::isfinite(h_max))
    throw InvalidCoefficient("h_min, h_max: the film bracket needs h_min < h_max");
  LoadShare out;
  auto excess = [&](double h) { return film_load(h) + asperity_load(h) - load; };
  auto fill = [&](double h) {
    out.h = h;
    out.film_parameter = h / sigma;
    out.film_load = film_load(h);
    out.asperity_load = asperity_load(h);
    out.asperity_fraction = out.asperity_load / load;
  };
  const double f_lo = excess(h_min), f_hi = excess(h_max);
  if (f_hi >= 0.0) {
    fill(h_max);
    out.status = LoadShareStatus::FilmCarriesAll;
    return out;
  }
  if (f_lo < 0.0) {
    fill(h_min);
    out.status = LoadShareStatus::NotBracketed;
    return out;
  }
  std::uintmax_t iterations = static_cast<std::uintmax_t>(max_iterations);
  const double abs_tol = rel_tol * load;
  auto tol = [&](double a, double b) {
    return std::abs(excess(0.5 * (a + b))) <= abs_tol || std::abs(b - a) <= 1e-15 * std::abs(b);
  };
  const auto r = boost::math::tools::toms748_solve(excess, h_min, h_max, f_lo, f_hi, tol, iterations);
  fill(0.5 * (r.first + r.second));
  out.iterations = static_cast<int>(iterations);
  out.status = std::abs(excess(out.h)) <= abs_tol ? LoadShareStatus::Converged : LoadShareStatus::NotConverged;
  return out;
}

LoadShare solve_load_share(double load, const std::function<double(double)> &film_load,
                           const GreenwoodTripp &contact, double nominal_area, double h_min, double h_max,
                           double rel_tol, int max_iterations)
{
  require_positive_finite(nominal_area, "nominal_area");
  return solve_load_share(
      load, film_load, [&](double h) { return contact.load(h, nominal_area); }, contact.sigma(), h_min, h_max,
      rel_tol, max_iterations);
}

}    // namespace runin::tribo
