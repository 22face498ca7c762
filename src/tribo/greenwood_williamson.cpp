#include "tribo/greenwood_williamson.h"

#include "tribo/contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace runin::tribo {

namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun table 25.4).
constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                          0.9602898564975363};
constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                            0.1012285362903763};
constexpr int kPanels = 200;
constexpr double kTailSigmas = 14.0;    // phi beyond 14 sigma is below 1e-42 of its peak

void require_positive(double value, const char *name)
{
  if (!(value > 0.0) || !std::isfinite(value))
    throw InvalidCoefficient(std::string(name) + " must be > 0, got " + std::to_string(value));
}

}    // namespace

double gaussian_tail_moment(double nu, double separation, double sigma)
{
  if (!(nu >= 0.0)) throw InvalidCoefficient("nu: tail moment order must be >= 0");
  require_positive(sigma, "sigma");
  const double pi = std::acos(-1.0);
  const double norm = 1.0 / (sigma * std::sqrt(2.0 * pi));
  // z - d = t^2: F_nu = int_0^T 2 t^(2 nu + 1) phi(d + t^2) dt
  const double z_max = std::max(separation, 0.0) + kTailSigmas * sigma;
  if (z_max <= separation) return 0.0;
  const double t_max = std::sqrt(z_max - separation);
  const double h = t_max / kPanels;
  double sum = 0.0;
  for (int p = 0; p < kPanels; ++p) {
    const double centre = (p + 0.5) * h;
    for (std::size_t k = 0; k < kNodes.size(); ++k)
      for (const double sign : {-1.0, 1.0}) {
        const double t = centre + sign * 0.5 * h * kNodes[k];
        const double z = separation + t * t;
        sum += kWeights[k] * 2.0 * std::pow(t, 2.0 * nu + 1.0) * std::exp(-0.5 * z * z / (sigma * sigma));
      }
  }
  return 0.5 * h * norm * sum;
}

GreenwoodWilliamson::GreenwoodWilliamson(double summit_density, double summit_radius, double summit_sigma,
                                         double effective_modulus) :
    eta_(summit_density), radius_(summit_radius), sigma_(summit_sigma), e_eff_(effective_modulus)
{
  require_positive(eta_, "eta: summit density");
  require_positive(radius_, "R: summit radius");
  require_positive(sigma_, "sigma: summit height std");
  require_positive(e_eff_, "E*: effective modulus");
}

double GreenwoodWilliamson::contact_density(double separation) const
{
  return eta_ * gaussian_tail_moment(0.0, separation, sigma_);
}

double GreenwoodWilliamson::area_fraction(double separation) const
{
  return std::acos(-1.0) * eta_ * radius_ * gaussian_tail_moment(1.0, separation, sigma_);
}

double GreenwoodWilliamson::pressure(double separation) const
{
  return 4.0 / 3.0 * eta_ * e_eff_ * std::sqrt(radius_) * gaussian_tail_moment(1.5, separation, sigma_);
}

}    // namespace runin::tribo
