// Critical-timestep kernels against closed forms and against direct integration of the contact ODE.
#include "tribo/contact.h"
#include "tribo/stability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace runin::tribo;

namespace {
constexpr double kPi = 3.14159265358979323846;

// Root in (0, 1) of the Rayleigh equation for xi = (c_R / c_S)^2:
// xi^3 - 8 xi^2 + 8 (3 - 2 eta) xi - 16 (1 - eta) = 0, eta = (c_S / c_P)^2 = (1 - 2 nu) / (2 (1 - nu)).
double exact_rayleigh_ratio(double nu)
{
  const double eta = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
  auto f = [eta](double xi) { return ((xi - 8.0) * xi + 8.0 * (3.0 - 2.0 * eta)) * xi - 16.0 * (1.0 - eta); };
  double lo = 1e-9, hi = 1.0 - 1e-12;    // f(0) < 0 < f(1)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return std::sqrt(0.5 * (lo + hi));
}

// Velocity Verlet on m x'' = -k x^p (x > 0 = overlap), started at x = 0 with approach speed v.
struct Impact {
  double duration, max_overlap;
};
Impact integrate_impact(double m, double k, double p, double v, double dt)
{
  double x = 0.0, u = v, t = 0.0, peak = 0.0;
  double a = 0.0;
  while (true) {
    const double x_old = x;
    x += u * dt + 0.5 * a * dt * dt;
    const double a_new = x > 0.0 ? -k * std::pow(x, p) / m : 0.0;
    u += 0.5 * (a + a_new) * dt;
    a = a_new;
    t += dt;
    peak = std::max(peak, x);
    if (x <= 0.0) return {t - dt * x / (x - x_old), peak};    // interpolate the exit
  }
}

const Material kCu{110.0e9, 0.37, 0.87e9};
const Material kAl{69.0e9, 0.33, 0.245e9};
}    // namespace

TEST(Rayleigh, SpeedRatioFitWithinFourPerMilleOfTheRayleighEquation)
{
  for (double nu = 0.0; nu < 0.5; nu += 0.05)
    EXPECT_NEAR(rayleigh_speed_ratio(nu), exact_rayleigh_ratio(nu), 4e-3 * exact_rayleigh_ratio(nu)) << nu;
  // the classical value for nu = 1/4: c_R / c_S = sqrt(2 - 2/sqrt(3))
  EXPECT_NEAR(exact_rayleigh_ratio(0.25), std::sqrt(2.0 - 2.0 / std::sqrt(3.0)), 1e-12);
}

TEST(Rayleigh, TimeIsTheRayleighWaveCrossingHalfTheCircumference)
{
  const double radius = 1.0e-6, rho = 8960.0;
  const double shear_speed = std::sqrt(kCu.shear_modulus() / rho);
  const double expected = kPi * radius / (rayleigh_speed_ratio(kCu.poisson_ratio) * shear_speed);
  EXPECT_NEAR(rayleigh_time(radius, kCu, rho), expected, 1e-14 * expected);
  // Cu, R = 1 um: G = 40.146 GPa, pi 1e-6 sqrt(8960 / G) / 0.93695 = 1.5840 ns (by hand)
  EXPECT_NEAR(rayleigh_time(radius, kCu, rho), 1.5840e-9, 1e-13);
  EXPECT_DOUBLE_EQ(rayleigh_time(2.0 * radius, kCu, rho), 2.0 * rayleigh_time(radius, kCu, rho));
  EXPECT_THROW(rayleigh_time(-radius, kCu, rho), InvalidCoefficient);
  EXPECT_THROW(rayleigh_time(radius, kCu, 0.0), InvalidCoefficient);
}

TEST(Hertz, ContactTimeAndOverlapMatchDirectIntegration)
{
  const double e_eff = effective_modulus(kCu, kAl), r_eff = effective_radius(1e-6, 1e-6);
  const double m_eff = 0.5 * 2700.0 * 4.0 / 3.0 * kPi * 1e-18, v = 2.0;
  const double t_c = hertz_contact_time(e_eff, r_eff, m_eff, v);
  const Impact numeric = integrate_impact(m_eff, 4.0 / 3.0 * e_eff * std::sqrt(r_eff), 1.5, v, t_c * 1e-5);
  EXPECT_NEAR(numeric.duration, t_c, 1e-4 * t_c);
  const double peak = hertz_max_overlap(e_eff, r_eff, m_eff, v);
  EXPECT_NEAR(numeric.max_overlap, peak, 1e-6 * peak);
  // the textbook constant: t_c = 2.868 (m*^2 / (R* E*^2 v))^(1/5)
  EXPECT_NEAR(t_c, 2.868 * std::pow(m_eff * m_eff / (r_eff * e_eff * e_eff * v), 0.2), 1e-3 * t_c);
  // slower impacts last longer: t_c ~ v^(-1/5)
  EXPECT_NEAR(hertz_contact_time(e_eff, r_eff, m_eff, v / 32.0), 2.0 * t_c, 1e-12 * t_c);
}

TEST(Verlet, LinearSpringIsBoundedBelowTheLimitAndGrowsAbove)
{
  const double k = 3.0e4, m = 2.0e-12;
  const double limit = verlet_limit(k, m);
  EXPECT_NEAR(limit, 2.0 / std::sqrt(k / m), 1e-15 * limit);
  auto amplitude_after = [&](double dt) {
    double x = 1.0, u = 0.0, a = -k * x / m, peak = 0.0;
    for (int i = 0; i < 2000; ++i) {
      x += u * dt + 0.5 * a * dt * dt;
      const double a_new = -k * x / m;
      u += 0.5 * (a + a_new) * dt;
      a = a_new;
      peak = std::max(peak, std::abs(x));
    }
    return peak;
  };
  EXPECT_LT(amplitude_after(0.99 * limit), 10.0);    // bounded (amplitude grows only as 1/sqrt(1 - (w dt/2)^2))
  EXPECT_GT(amplitude_after(1.01 * limit), 1e10);
  // Hertz: the tangent stiffness at the overlap, 2 E* sqrt(R* delta)
  const double e_eff = 5.0e10, r_eff = 0.5e-6, delta = 1e-8;
  EXPECT_NEAR(hertz_verlet_limit(e_eff, r_eff, m, delta), verlet_limit(2.0 * e_eff * std::sqrt(r_eff * delta), m),
              1e-15);
}

TEST(Cfl, ThesisEquation21)
{
  const double h = 2e-6, rho = 7870.0, e = 200e9;
  EXPECT_NEAR(cfl_time_step(h, e, rho), h / std::sqrt(e / rho), 1e-24);
  EXPECT_NEAR(cfl_time_step(h, e, rho, 0.5), 0.5 * h / std::sqrt(e / rho), 1e-24);
  EXPECT_THROW(cfl_time_step(h, e, rho, 1.5), InvalidCoefficient);
  EXPECT_THROW(cfl_time_step(h, e, rho, 0.0), InvalidCoefficient);
}

TEST(EquivalentMaterial, RecoversALikePairExactly)
{
  for (const Material &m : {kCu, kAl, Material{200e9, 0.29, 1e9}, Material{66e9, 0.27, 1e9}}) {
    const Material back = equivalent_material(effective_modulus(m, m), effective_shear_modulus(m, m));
    EXPECT_NEAR(back.poisson_ratio, m.poisson_ratio, 1e-12);
    EXPECT_NEAR(back.youngs_modulus, m.youngs_modulus, 1e-12 * m.youngs_modulus);
  }
  EXPECT_THROW(equivalent_material(1e9, 1e9), InvalidCoefficient);    // G*/E* outside (1/6, 1/3)
  // the fallback keeps E* and the given nu when G*/E* is not isotropic, else recovers the pair
  const Material fallback = equivalent_material(4.8e10, 1.9e10, 0.3);
  EXPECT_DOUBLE_EQ(fallback.poisson_ratio, 0.3);
  EXPECT_NEAR(effective_modulus(fallback, fallback), 4.8e10, 1e-12 * 4.8e10);
  const Material like = equivalent_material(effective_modulus(kAl, kAl), effective_shear_modulus(kAl, kAl), 0.3);
  EXPECT_NEAR(like.poisson_ratio, kAl.poisson_ratio, 1e-12);
}

TEST(Policy, WarnAboveAFifthOfTheRayleighTimeFailAboveFourTimes)
{
  const double t_r = 1e-9;
  EXPECT_EQ(judge_time_step(0.1e-9, t_r), TimeStepVerdict::ok);
  EXPECT_EQ(judge_time_step(0.2e-9, t_r), TimeStepVerdict::ok);
  EXPECT_EQ(judge_time_step(0.21e-9, t_r), TimeStepVerdict::warn);
  EXPECT_EQ(judge_time_step(4.0e-9, t_r), TimeStepVerdict::warn);
  EXPECT_EQ(judge_time_step(4.1e-9, t_r), TimeStepVerdict::fail);
}
