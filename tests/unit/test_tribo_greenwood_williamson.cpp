// Greenwood-Williamson integrals against closed forms of the Gaussian tail moments.
#include "tribo/contact.h"
#include "tribo/greenwood_williamson.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

namespace {

const double kPi = std::acos(-1.0);
double standard_pdf(double h) { return std::exp(-0.5 * h * h) / std::sqrt(2.0 * kPi); }
double upper_tail(double h) { return 0.5 * std::erfc(h / std::sqrt(2.0)); }

}    // namespace

// Upper end 6 sigma: beyond it the closed form of F_2 itself loses digits to cancellation.
TEST(GaussianTailMoment, IntegerOrdersMatchClosedForms)
{
  const double sigma = 2.3e-7;
  for (double h = -50.0; h <= 6.0; h += 0.25) {
    const double d = h * sigma;
    const double f0 = upper_tail(h);
    const double f1 = sigma * standard_pdf(h) - d * upper_tail(h);
    const double f2 = (sigma * sigma + d * d) * upper_tail(h) - d * sigma * standard_pdf(h);
    EXPECT_NEAR(gaussian_tail_moment(0.0, d, sigma), f0, 1e-12 * f0) << "h=" << h;
    EXPECT_NEAR(gaussian_tail_moment(1.0, d, sigma), f1, 1e-11 * f1) << "h=" << h;
    EXPECT_NEAR(gaussian_tail_moment(2.0, d, sigma), f2, 1e-11 * f2) << "h=" << h;
  }
}

// At d = 0 every order is a half Gaussian moment: (2 sigma^2)^((nu+1)/2) Gamma((nu+1)/2) / (2 sigma sqrt(2 pi)).
TEST(GaussianTailMoment, HalfGaussianMomentAtZeroSeparation)
{
  const double sigma = 1.0e-6;
  for (const double nu : {0.5, 1.5, 2.5}) {
    const double exact = std::pow(2.0 * sigma * sigma, 0.5 * (nu + 1.0)) * std::tgamma(0.5 * (nu + 1.0)) /
                         (2.0 * sigma * std::sqrt(2.0 * kPi));
    EXPECT_NEAR(gaussian_tail_moment(nu, 0.0, sigma), exact, 1e-12 * exact) << "nu=" << nu;
  }
}

// Far below the summits every asperity touches: F_3/2 -> |d|^3/2 (1 + 3/8 s^2 + 9/128 s^4 + O(s^6)), s = sigma/|d|.
TEST(GaussianTailMoment, FullContactLimit)
{
  const double sigma = 1.0e-7, d = -20.0 * sigma, s = sigma / std::abs(d);
  const double series = std::pow(-d, 1.5) * (1.0 + 0.375 * s * s + 9.0 / 128.0 * std::pow(s, 4));
  EXPECT_NEAR(gaussian_tail_moment(1.5, d, sigma), series, 1e-8 * series);
}

// Integration by parts gives F_{nu+2} = -d F_{nu+1} + (nu+1) sigma^2 F_nu for any real nu and d.
TEST(GaussianTailMoment, RecurrenceHoldsForFractionalOrders)
{
  const double sigma = 3.0e-7;
  for (double h = -4.0; h <= 4.0; h += 0.5) {
    const double d = h * sigma;
    const double lhs = gaussian_tail_moment(3.5, d, sigma);
    const double rhs = -d * gaussian_tail_moment(2.5, d, sigma) + 2.5 * sigma * sigma * gaussian_tail_moment(1.5, d, sigma);
    EXPECT_NEAR(lhs, rhs, 1e-10 * lhs) << "h=" << h;
  }
}

TEST(GreenwoodWilliamson, IntegralsScaleTheTailMoments)
{
  const double eta = 2.5e11, radius = 1.0e-5, sigma = 1.0e-7, e_star = 1.0e11;
  const GreenwoodWilliamson gw(eta, radius, sigma, e_star);
  for (double h = -1.0; h <= 3.0; h += 0.5) {
    const double d = h * sigma;
    EXPECT_NEAR(gw.contact_density(d), eta * upper_tail(h), 1e-12 * eta * upper_tail(h));
    const double f1 = sigma * standard_pdf(h) - d * upper_tail(h);
    EXPECT_NEAR(gw.area_fraction(d), kPi * eta * radius * f1, 1e-11 * kPi * eta * radius * f1);
    // dP/dd = -(4/3) eta E* sqrt(R) (3/2) F_1/2: the load falls with separation at the GW rate
    const double step = 1e-4 * sigma;
    const double slope = (gw.pressure(d + step) - gw.pressure(d - step)) / (2.0 * step);
    const double expected = -2.0 * eta * e_star * std::sqrt(radius) * gaussian_tail_moment(0.5, d, sigma);
    EXPECT_NEAR(slope, expected, 1e-6 * std::abs(expected));
  }
}

TEST(GreenwoodWilliamson, RejectsImpossibleParameters)
{
  EXPECT_THROW(GreenwoodWilliamson(0.0, 1e-5, 1e-7, 1e11), InvalidCoefficient);
  EXPECT_THROW(GreenwoodWilliamson(1e11, -1e-5, 1e-7, 1e11), InvalidCoefficient);
  EXPECT_THROW(GreenwoodWilliamson(1e11, 1e-5, 0.0, 1e11), InvalidCoefficient);
  EXPECT_THROW(GreenwoodWilliamson(1e11, 1e-5, 1e-7, -1.0), InvalidCoefficient);
  EXPECT_THROW(gaussian_tail_moment(-0.5, 0.0, 1e-7), InvalidCoefficient);
}
