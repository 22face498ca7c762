// Load servo of fix runin/wall: monotone approach to the target force on Hertz and GW contacts.
#include "tribo/contact.h"
#include "tribo/greenwood_williamson.h"
#include "tribo/load_servo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace runin::tribo;

namespace {

// Runs the servo from approach u0 on F(u), K(u); returns the force history.
std::vector<double> servo_history(const LoadServo &servo, const std::function<double(double)> &force,
                                  const std::function<double(double)> &stiffness, double u0, double target, int steps)
{
  std::vector<double> history;
  double u = u0;
  for (int n = 0; n < steps; ++n) {
    history.push_back(force(u));
    u += servo.approach(force(u), stiffness(u), target);
  }
  history.push_back(force(u));
  return history;
}

void expect_monotone_convergence(const std::vector<double> &f, double target, double tolerance)
{
  const double direction = f.front() < target ? 1.0 : -1.0;
  for (std::size_t n = 1; n < f.size(); ++n) {
    EXPECT_GE(direction * (f[n] - f[n - 1]), -1e-12 * target) << "step " << n;    // no reversal
    EXPECT_LE(direction * (f[n] - target), 1e-12 * target) << "step " << n;       // no overshoot
  }
  EXPECT_NEAR(f.back(), target, tolerance * target);
}

}    // namespace

// Linear contact F = k u: the error contracts by exactly (1 - g) per step above the target.
TEST(LoadServo, LinearContactContractsByOneMinusGain)
{
  const double k = 3.0e6, target = 2.0, gain = 0.4;
  const LoadServo servo(gain, 1.0);
  double u = 2.0 * target / k;
  for (int n = 0; n < 5; ++n) {
    const double error = k * u - target;
    u += servo.approach(k * u, k, target);
    EXPECT_NEAR(k * u - target, (1.0 - gain) * error, 1e-12 * target);
  }
}

// One Hertz contact, from out of contact and from 50 x above the target: monotone, no overshoot.
TEST(LoadServo, HertzContactApproachesMonotonically)
{
  const HertzNormal hertz(1.0e11, 1.0e-6);
  auto force = [&](double u) { return u > 0.0 ? hertz.force(u) : 0.0; };
  auto stiffness = [&](double u) { return u > 0.0 ? hertz.stiffness(u) : 0.0; };
  const double target = hertz.force(2.0e-8);
  for (const double gain : {0.3, 1.0}) {
    const LoadServo servo(gain, 1.0e-9);
    expect_monotone_convergence(servo_history(servo, force, stiffness, -5.0e-9, target, 400), target, 1e-9);
    expect_monotone_convergence(servo_history(servo, force, stiffness, 2.0e-8 * std::pow(50.0, 2.0 / 3.0), target, 400),
                                target, 1e-9);
    // uncapped, from a force 2800 x below the target: a Newton step on F itself would overshoot
    const LoadServo uncapped(gain, 1.0);
    expect_monotone_convergence(servo_history(uncapped, force, stiffness, 1.0e-10, target, 400), target, 1e-9);
  }
}

// Greenwood-Williamson load (approach u = -d): monotone from both sides, converges onto P^-1(p).
TEST(LoadServo, GreenwoodWilliamsonLoadApproachesMonotonically)
{
  const double sigma = 1.0e-7;
  const GreenwoodWilliamson gw(2.5e11, 5.0e-6, sigma, 1.0e11);
  auto pressure = [&](double u) { return gw.pressure(-u); };
  // dP/du = 2 eta E* sqrt(R) F_1/2 (the GW load rate, cf. test_tribo_greenwood_williamson)
  auto stiffness = [&](double u) {
    return 2.0 * gw.summit_density() * gw.effective_modulus() * std::sqrt(gw.summit_radius()) *
           gaussian_tail_moment(0.5, -u, sigma);
  };
  const double target = gw.pressure(-1.0 * sigma);
  const LoadServo servo(0.5, 0.05 * sigma);
  expect_monotone_convergence(servo_history(servo, pressure, stiffness, -5.0 * sigma, target, 600), target, 1e-9);
  expect_monotone_convergence(servo_history(servo, pressure, stiffness, 3.0 * sigma, target, 600), target, 1e-9);
  const LoadServo uncapped(1.0, 1.0);
  expect_monotone_convergence(servo_history(uncapped, pressure, stiffness, -3.0 * sigma, target, 200), target, 1e-9);
}

TEST(LoadServo, NoContactAdvancesByTheCapAndRejectsBadSettings)
{
  const LoadServo servo(0.5, 2.0e-9);
  EXPECT_EQ(servo.approach(0.0, 0.0, 1.0), 2.0e-9);
  EXPECT_EQ(servo.approach(1e3, 1e3, 1.0), -2.0e-9);    // far above: capped retreat
  EXPECT_THROW(LoadServo(0.0, 1e-9), InvalidCoefficient);
  EXPECT_THROW(LoadServo(1.5, 1e-9), InvalidCoefficient);
  EXPECT_THROW(LoadServo(0.5, 0.0), InvalidCoefficient);
}
