// Greenwood-Tripp asperity contact: F_n against an independent quadrature (Boost exp-sinh on the
// untransformed integral) and closed forms, and the load-sharing solve.
#include "tribo/contact.h"
#include "tribo/greenwood_tripp.h"

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

namespace {

const double kPi = std::acos(-1.0);

// F_n(H) = (2 pi)^-1/2 int_H^inf (s - H)^n exp(-s^2/2) ds, integrated in s directly (no substitution).
double reference_f(double n, double H)
{
  boost::math::quadrature::exp_sinh<double> integrator;
  auto f = [&](double t) { return std::pow(t, n) * std::exp(-0.5 * (H + t) * (H + t)); };
  return integrator.integrate(f, 0.0, std::numeric_limits<double>::infinity()) / std::sqrt(2.0 * kPi);
}

// Worn summits cut at T: int_H^T (s - H)^n phi ds (tanh-sinh on the untransformed band) + (T - H)^n Q(T).
double reference_truncated(double n, double H, double T)
{
  if (H >= T) return 0.0;
  boost::math::quadrature::tanh_sinh<double> integrator;
  auto f = [&](double s) { return std::pow(s - H, n) * std::exp(-0.5 * s * s); };
  const double band = integrator.integrate(f, H, T) / std::sqrt(2.0 * kPi);
  return band + std::pow(T - H, n) * 0.5 * std::erfc(T / std::sqrt(2.0));
}

}    // namespace

TEST(GreenwoodTripp, F52MatchesIndependentQuadrature)
{
  double worst = 0.0;
  for (double H = -3.0; H <= 8.0; H += 0.25) {
    const double ref = reference_f(2.5, H);
    const double got = greenwood_tripp_f(2.5, H);
    worst = std::max(worst, std::abs(got - ref) / ref);
    EXPECT_NEAR(got, ref, 1e-6 * ref) << "H=" << H;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("F_5/2 worst relative error vs exp-sinh quadrature on H in [-3, 8]: %.3e\n", worst);
}

// F_n(0) = 2^((n-1)/2) Gamma((n+1)/2) / sqrt(2 pi); F_2 in closed form.
TEST(GreenwoodTripp, ClosedFormsOfTheMoments)
{
  for (const double n : {1.5, 2.0, 2.5}) {
    const double exact = std::pow(2.0, 0.5 * (n - 1.0)) * std::tgamma(0.5 * (n + 1.0)) / std::sqrt(2.0 * kPi);
    EXPECT_NEAR(greenwood_tripp_f(n, 0.0), exact, 1e-10 * exact) << "n=" << n;
  }
  EXPECT_NEAR(greenwood_tripp_f(2.5, 0.0), 0.616634, 1e-6);   // 2^(3/4) Gamma(7/4) / sqrt(2 pi)
  for (double H = 0.0; H <= 4.0; H += 0.5) {
    const double q = 0.5 * std::erfc(H / std::sqrt(2.0)), phi = std::exp(-0.5 * H * H) / std::sqrt(2.0 * kPi);
    EXPECT_NEAR(greenwood_tripp_f(2.0, H), (1.0 + H * H) * q - H * phi, 1e-10 * reference_f(2.0, H)) << "H=" << H;
    EXPECT_NEAR(greenwood_tripp_f(0.0, H), q, 1e-14);
  }
}

TEST(GreenwoodTripp, PressureAndAreaMatchIndependentQuadrature)
{
  const double eta = 5.0e10, beta = 2.0e-5, sigma = 4.0e-7, e_star = 1.1e11;
  const GreenwoodTripp gt(eta, beta, sigma, e_star);
  const double ebs = eta * beta * sigma;
  const double k = 16.0 * std::sqrt(2.0) / 15.0 * kPi * ebs * ebs * std::sqrt(sigma / beta);
  EXPECT_NEAR(gt.coefficient(), k, 1e-14 * k);
  for (const double H : {0.5, 1.0, 2.0, 3.0, 4.0}) {
    const double p_ref = k * e_star * reference_f(2.5, H);
    EXPECT_NEAR(gt.pressure(H * sigma), p_ref, 1e-6 * p_ref) << "H=" << H;
    const double a_ref = kPi * kPi * ebs * ebs * reference_f(2.0, H);
    EXPECT_NEAR(gt.area_fraction(H * sigma), a_ref, 1e-6 * a_ref) << "H=" << H;
    EXPECT_NEAR(gt.load(H * sigma, 2.0e-4), p_ref * 2.0e-4, 1e-6 * p_ref * 2.0e-4);
  }
  // decreasing in the gap
  EXPECT_GT(gt.pressure(1.0 * sigma), gt.pressure(1.1 * sigma));
}

TEST(GreenwoodTripp, BadInputNamesTheField)
{
  auto message = [](auto f) {
    try {
      f();
    } catch (const InvalidCoefficient &e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_NE(message([] { GreenwoodTripp(5e10, 2e-5, -1e-7, 1e11); }).find("sigma"), std::string::npos);
  EXPECT_NE(message([] { GreenwoodTripp(0.0, 2e-5, 1e-7, 1e11); }).find("eta"), std::string::npos);
  EXPECT_NE(message([] { GreenwoodTripp(5e10, 0.0, 1e-7, 1e11); }).find("beta"), std::string::npos);
  EXPECT_NE(message([] { GreenwoodTripp(5e10, 2e-5, 1e-7, 0.0); }).find("E*"), std::string::npos);
}

// Inclined-pad film (closed form, per width B): W_f = 6 mu U B l^2 / (h^2 (K-1)^2) [ln K - 2 (K-1)/(K+1)]
// plus Greenwood-Tripp asperities on the pad area; the solve returns the gap at which both carry the load.
TEST(GreenwoodTripp, LoadShareCarriesTheNominalLoad)
{
  const double sigma = 5.0e-7;
  const GreenwoodTripp gt(5.0e10, 2.0e-5, sigma, 1.1e11);
  const double mu = 0.01, u = 0.5, l = 5e-3, width = 1e-2, kk = 2.0, area = l * width;
  auto film = [&](double h) {
    return 6.0 * mu * u * width * l * l / (h * h * (kk - 1.0) * (kk - 1.0)) *
           (std::log(kk) - 2.0 * (kk - 1.0) / (kk + 1.0));
  };
  for (const double H_target : {1.0, 2.0, 3.0}) {
    const double h = H_target * sigma;
    const double load = film(h) + gt.load(h, area);
    const LoadShare s = solve_load_share(load, film, gt, area, 0.05 * sigma, 20.0 * sigma);
    ASSERT_TRUE(s.ok()) << to_string(s.status);
    EXPECT_NEAR(s.film_parameter, H_target, 1e-8) << "H=" << H_target;
    EXPECT_NEAR(s.film_load + s.asperity_load, load, 1e-9 * load);
    EXPECT_NEAR(s.asperity_fraction, gt.load(h, area) / load, 1e-8);
  }
  // a load the film alone carries at the top of the bracket
  const LoadShare light = solve_load_share(0.5 * film(20.0 * sigma), film, gt, area, 0.05 * sigma, 20.0 * sigma);
  EXPECT_EQ(light.status, LoadShareStatus::FilmCarriesAll);
  EXPECT_THROW(solve_load_share(-1.0, film, gt, area, 0.05 * sigma, 20.0 * sigma), InvalidCoefficient);
}

// A run-in surface: summits above the top T flattened to T (plateau). Checked against an independent quadrature
// and the limits that define it: no contact beyond the top, the Gaussian F_n when the top is far, the count of
// summits in contact (F_0) unchanged below the top.
TEST(GreenwoodTripp, WornSummitMomentsMatchIndependentQuadrature)
{
  double worst = 0.0;
  for (const double n : {1.5, 2.0, 2.5})
    for (const double T : {-0.5, 0.5, 1.0, 2.0, 3.0})
      for (double H = -2.0; H < T; H += 0.25) {
        const double ref = reference_truncated(n, H, T), got = greenwood_tripp_f_truncated(n, H, T);
        worst = std::max(worst, std::abs(got - ref) / ref);
        EXPECT_NEAR(got, ref, 1e-10 * ref) << "n=" << n << " H=" << H << " T=" << T;
      }
  std::printf("worn-summit F_n worst relative error vs tanh-sinh quadrature: %.3e\n", worst);
  for (const double H : {-1.0, 0.0, 1.5, 2.9}) {
    EXPECT_EQ(greenwood_tripp_f_truncated(2.5, 3.0, 3.0), 0.0);
    EXPECT_EQ(greenwood_tripp_f_truncated(2.5, H + 0.1, H), 0.0);
    EXPECT_EQ(greenwood_tripp_f_truncated(2.5, H, HUGE_VAL), greenwood_tripp_f(2.5, H));
    EXPECT_NEAR(greenwood_tripp_f_truncated(0.0, H, 3.0), greenwood_tripp_f(0.0, H), 1e-12);
  }
  // the cut only lowers the load, and the load falls to 0 continuously at the top
  for (double H = 0.0; H < 2.0; H += 0.2)
    EXPECT_LT(greenwood_tripp_f_truncated(2.5, H, 2.0), greenwood_tripp_f(2.5, H));
  EXPECT_LT(greenwood_tripp_f_truncated(2.5, 2.0 - 1e-6, 2.0), 1e-14);
}

// The worn volume of a cut is pi eta beta sigma^2 F_2(T / sigma) (each summit of height z > T loses a cap of
// pi beta (z - T)^2); the top after a volume inverts it; the RMS of min(x, T) against its moments by quadrature.
TEST(GreenwoodTripp, WornVolumeAndRoughnessOfTheCut)
{
  const double eta = 2.5e9, beta = 1e-4, sigma = 2.83e-7, e_star = 1.15e11;
  const GreenwoodTripp gt(eta, beta, sigma, e_star);
  for (const double t : {-2.0, -0.5, 0.0, 1.0, 2.5, 4.0}) {
    const double ref = kPi * eta * beta * sigma * sigma * reference_f(2.0, t);
    EXPECT_NEAR(gt.worn_volume(t * sigma), ref, 1e-9 * ref) << "t=" << t;
    EXPECT_NEAR(gt.top_after_wear(gt.worn_volume(t * sigma)), t * sigma, 1e-9 * sigma) << "t=" << t;
  }
  EXPECT_EQ(gt.worn_volume(HUGE_VAL), 0.0);
  EXPECT_EQ(gt.top_after_wear(0.0), HUGE_VAL);
  EXPECT_GT(gt.top_after_wear(1e-12), gt.top_after_wear(1e-10));   // more wear, lower top
  // pressure and area with the top: the dimensionless moments times the uncut prefactors
  const double H = 1.2, T = 2.0;
  EXPECT_NEAR(gt.pressure(H * sigma, T * sigma) / gt.pressure(H * sigma),
              reference_truncated(2.5, H, T) / reference_f(2.5, H), 1e-9);
  EXPECT_NEAR(gt.area_fraction(H * sigma, T * sigma) / gt.area_fraction(H * sigma),
              reference_truncated(2.0, H, T) / reference_f(2.0, H), 1e-9);
  // RMS of min(x, T): closed form at T = 0 (sqrt(1/2 - 1/(2 pi))), quadrature elsewhere, 1 uncut
  EXPECT_NEAR(truncated_rms_ratio(0.0), std::sqrt(0.5 - 0.5 / kPi), 1e-14);
  EXPECT_EQ(truncated_rms_ratio(HUGE_VAL), 1.0);
  boost::math::quadrature::tanh_sinh<double> integrator;
  for (const double T : {-1.0, 0.7, 1.5, 3.0}) {
    auto moment = [&](int k) {
      auto f = [&](double x) { return std::pow(x, k) * std::exp(-0.5 * x * x); };
      return integrator.integrate(f, -40.0, T) / std::sqrt(2.0 * kPi) +
             std::pow(T, k) * 0.5 * std::erfc(T / std::sqrt(2.0));
    };
    const double m1 = moment(1), m2 = moment(2);
    EXPECT_NEAR(truncated_rms_ratio(T), std::sqrt(m2 - m1 * m1), 1e-10) << "T=" << T;
  }
}
