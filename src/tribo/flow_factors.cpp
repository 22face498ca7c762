#include "tribo/flow_factors.h"

#include "tribo/contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace runin::tribo {

namespace {

constexpr std::array<double, 7> kGamma = {1.0 / 9.0, 1.0 / 6.0, 1.0 / 3.0, 1.0, 3.0, 6.0, 9.0};

// Patir & Cheng (1978): phi_x fit coefficients C, r.
constexpr std::array<double, 7> kPxC = {1.48, 1.38, 1.18, 0.90, 0.225, 0.520, 0.870};
constexpr std::array<double, 7> kPxR = {0.42, 0.42, 0.42, 0.56, 1.5, 1.5, 1.5};
// Patir & Cheng (1979): Phi_s fit coefficients A1, a1, a2, a3, A2.
constexpr std::array<double, 7> kSA1 = {2.046, 1.962, 1.858, 1.899, 1.560, 1.290, 1.011};
constexpr std::array<double, 7> kSa1 = {1.12, 1.08, 1.01, 0.98, 0.85, 0.62, 0.54};
constexpr std::array<double, 7> kSa2 = {0.78, 0.77, 0.76, 0.92, 1.13, 1.09, 1.07};
constexpr std::array<double, 7> kSa3 = {0.03, 0.03, 0.03, 0.05, 0.08, 0.08, 0.08};
constexpr std::array<double, 7> kSA2 = {1.856, 1.754, 1.561, 1.126, 0.556, 0.388, 0.295};
// Patir & Cheng (1979): phi_fp (D, s) and phi_fs (A3, a4, a5, a6).
constexpr std::array<double, 7> kFD = {1.51, 1.51, 1.47, 1.40, 0.98, 0.97, 0.73};
constexpr std::array<double, 7> kFs = {0.52, 0.54, 0.58, 0.66, 0.79, 0.91, 0.91};
constexpr std::array<double, 7> kFA3 = {14.1, 13.4, 12.3, 11.1, 9.8, 10.1, 8.7};
constexpr std::array<double, 7> kFa4 = {2.45, 2.42, 2.32, 2.31, 2.25, 2.25, 2.15};
constexpr std::array<double, 7> kFa5 = {2.30, 2.30, 2.30, 2.38, 2.80, 2.90, 2.97};
constexpr std::array<double, 7> kFa6 = {0.10, 0.10, 0.10, 0.11, 0.18, 0.18, 0.18};

void check_gamma(double gamma)
{
  if (!(gamma >= kGamma.front() * (1.0 - 1e-12) && gamma <= kGamma.back() * (1.0 + 1e-12)))
    throw InvalidCoefficient("gamma: surface pattern must be in [1/9, 9] (the range of Patir & Cheng's fits), got " +
                             std::to_string(gamma));
}

void check_h(double H)
{
  if (!std::isfinite(H)) throw InvalidCoefficient("h/sigma: film parameter must be finite");
}

// Bracketing table entries and the weight of the upper one (linear in ln gamma).
struct Bracket {
  std::size_t lo, hi;
  double w;
};

Bracket bracket(double gamma)
{
  check_gamma(gamma);
  gamma = std::clamp(gamma, kGamma.front(), kGamma.back());
  for (std::size_t k = 0; k + 1 < kGamma.size(); ++k)
    if (gamma <= kGamma[k + 1]) {
      const double w = std::log(gamma / kGamma[k]) / std::log(kGamma[k + 1] / kGamma[k]);
      return {k, k + 1, w};
    }
  return {kGamma.size() - 2, kGamma.size() - 1, 1.0};
}

template <class F> double interpolate(double gamma, F f)
{
  const Bracket b = bracket(gamma);
  if (b.w <= 0.0) return f(b.lo);
  if (b.w >= 1.0) return f(b.hi);
  return (1.0 - b.w) * f(b.lo) + b.w * f(b.hi);
}

}    // namespace

double pressure_flow_factor_x(double H, double gamma)
{
  check_h(H);
  H = std::max(H, kFlowFactorMinH);
  return interpolate(gamma, [H](std::size_t k) {
    return kGamma[k] <= 1.0 ? 1.0 - kPxC[k] * std::exp(-kPxR[k] * H) : 1.0 + kPxC[k] * std::pow(H, -kPxR[k]);
  });
}

double pressure_flow_factor_y(double H, double gamma)
{
  check_gamma(gamma);
  return pressure_flow_factor_x(H, 1.0 / gamma);
}

double shear_flow_factor(double H, double gamma)
{
  check_h(H);
  H = std::max(H, kFlowFactorMinH);
  return interpolate(gamma, [H](std::size_t k) {
    return H <= 5.0 ? kSA1[k] * std::pow(H, kSa1[k]) * std::exp(-kSa2[k] * H + kSa3[k] * H * H)
                    : kSA2[k] * std::exp(-0.25 * H);
  });
}

double shear_flow_factor_pair(double H, double gamma, double sigma_moving, double sigma_fixed)
{
  if (!(sigma_moving >= 0.0) || !(sigma_fixed >= 0.0))
    throw InvalidCoefficient("sigma: surface roughnesses must be >= 0");
  const double s2 = sigma_moving * sigma_moving + sigma_fixed * sigma_fixed;
  if (s2 == 0.0) return 0.0;
  return (sigma_moving * sigma_moving - sigma_fixed * sigma_fixed) / s2 * shear_flow_factor(H, gamma);
}

double shear_stress_factor_f(double H)
{
  check_h(H);
  H = std::max(H, kFlowFactorMinH);
  const double z = H / 3.0;
  const double a = 1.0 - z * z;
  const double a3 = a * a * a;
  if (z <= 1.0) {
    // eps* = 1/300: the cut-off of the log singularity at contact (Patir & Cheng 1979)
    const double poly = -55.0 + z * (132.0 + z * (345.0 + z * (-160.0 + z * (-405.0 + z * (60.0 + 147.0 * z)))));
    return 35.0 / 32.0 * z * (a3 * std::log(300.0 * (z + 1.0)) + poly / 60.0);
  }
  // the closed form loses digits by cancellation for large z (1e-9 at z = 10, 2e-6 at z = 30); there
  // phi_f = E[h / (h - delta)] = 1 + <delta^2>/h^2 + <delta^4>/h^4 + ... with the moments 1, 27/11, 10935/1287
  // of the fit's height density 35/96 (1 - delta^2/9)^3 (series truncation < 1e-10 for H > 30)
  if (z > 10.0) {
    const double q = 1.0 / (H * H);
    return 1.0 + q * (1.0 + q * (27.0 / 11.0 + q * 10935.0 / 1287.0));
  }
  const double z2 = z * z;
  return 35.0 / 32.0 * z * (a3 * std::log((z + 1.0) / (z - 1.0)) + z / 15.0 * (66.0 + z2 * (30.0 * z2 - 80.0)));
}

double shear_stress_factor_fp(double H, double gamma)
{
  check_h(H);
  H = std::max(H, kFlowFactorMinH);
  return interpolate(gamma, [H](std::size_t k) { return 1.0 - kFD[k] * std::exp(-kFs[k] * H); });
}

double shear_stress_factor_fs(double H, double gamma)
{
  check_h(H);
  H = std::max(H, kFlowFactorMinH);
  if (H > 7.0) return 0.0;
  return interpolate(gamma, [H](std::size_t k) {
    return kFA3[k] * std::pow(H, kFa4[k]) * std::exp(-kFa5[k] * H + kFa6[k] * H * H);
  });
}

double mean_gap(double h, double sigma)
{
  if (!(sigma >= 0.0)) throw InvalidCoefficient("sigma: roughness must be >= 0");
  if (sigma == 0.0) return std::max(h, 0.0);
  const double H = h / sigma;
  const double pi = std::acos(-1.0);
  return 0.5 * h * (1.0 + std::erf(H / std::sqrt(2.0))) + sigma / std::sqrt(2.0 * pi) * std::exp(-0.5 * H * H);
}

double contact_factor(double H)
{
  check_h(H);
  return 0.5 * (1.0 + std::erf(H / std::sqrt(2.0)));
}

}    // namespace runin::tribo
