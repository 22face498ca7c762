// CvodeIntegrator: dense output between stops, exact landing on a stop (never stepping past it),
// roots before an output time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "continuum/cvode_integrator.h"

using runin::continuum::CvodeIntegrator;

namespace {
CvodeIntegrator::Settings tight() {
  CvodeIntegrator::Settings s;
  s.rtol = 1e-10;
  s.atol = 1e-14;
  return s;
}
}  // namespace

TEST(CvodeIntegrator, OutputsComeFromTheInterpolantAndCostNoSteps) {
  CvodeIntegrator integrator(1, tight());
  integrator.restart(
      0.0, {1.0}, [](double, const double *y, double *dy) { dy[0] = -y[0]; }, [](double, const double *, double *) {},
      {});
  const double t_end = 2.0, dt = 1e-3;
  double worst = 0.0;
  for (int i = 1; i <= 2000; ++i) {
    const double t = std::min(i * dt, t_end);
    const auto step = integrator.advance_to_output(t, t_end);
    ASSERT_EQ(step.outcome, CvodeIntegrator::Outcome::ReachedTarget) << step.message;
    EXPECT_DOUBLE_EQ(step.t, t);
    worst = std::max(worst, std::abs(integrator.state()[0] - std::exp(-t)) / std::exp(-t));
  }
  EXPECT_LT(worst, 1e-8);
  // 2000 outputs, far fewer steps: the steps follow the solution, not the output grid.
  EXPECT_LT(integrator.total_steps(), 400);
}

TEST(CvodeIntegrator, NeverStepsPastTheStopAndLandsOnIt) {
  CvodeIntegrator integrator(1, tight());
  double latest = 0.0;  // latest time the right-hand side was evaluated at
  // A jump of the right-hand side after t = 1: y = t before, 2 - t after.
  auto rhs = [&latest](double t, const double *, double *dy) {
    latest = std::max(latest, t);
    dy[0] = t <= 1.0 ? 1.0 : -1.0;  // left-continuous at the jump, as the drives' ramp ends
  };
  integrator.restart(0.0, {0.0}, rhs, [](double, const double *, double *) {}, {});
  for (double t : {0.3, 0.6, 0.9}) {
    const auto step = integrator.advance_to_output(t, 1.0);
    ASSERT_EQ(step.outcome, CvodeIntegrator::Outcome::ReachedTarget) << step.message;
    EXPECT_NEAR(integrator.state()[0], t, 1e-12);
  }
  const auto stop = integrator.advance_to_stop(1.0);
  ASSERT_EQ(stop.outcome, CvodeIntegrator::Outcome::ReachedTarget) << stop.message;
  EXPECT_EQ(stop.t, 1.0);
  EXPECT_NEAR(integrator.state()[0], 1.0, 1e-12);
  EXPECT_LE(latest, 1.0);  // the other side of the jump was never evaluated
  // restart at the stop (the kink), then on with dense output to the end
  integrator.restart(1.0, integrator.state(), rhs, [](double, const double *, double *) {}, {});
  for (double t : {1.25, 1.5, 1.75, 2.0}) {
    const auto step = integrator.advance_to_output(t, 2.0);
    ASSERT_EQ(step.outcome, CvodeIntegrator::Outcome::ReachedTarget) << step.message;
    EXPECT_NEAR(integrator.state()[0], 2.0 - t, 1e-12);
  }
  EXPECT_LE(latest, 2.0);
  EXPECT_THROW(integrator.advance_to_output(2.5, 2.0), std::invalid_argument);
}

TEST(CvodeIntegrator, RootBeforeTheOutputTimeStopsAtTheRoot) {
  CvodeIntegrator integrator(1, tight());
  integrator.restart(
      0.0, {0.0}, [](double, const double *, double *dy) { dy[0] = 1.0; },
      [](double, const double *y, double *g) { g[0] = y[0] - 0.5005; }, {+1});
  double t = 0.0;
  for (int i = 1; i <= 1000; ++i) {
    const auto step = integrator.advance_to_output(i * 1e-3, 1.0);
    ASSERT_NE(step.outcome, CvodeIntegrator::Outcome::Failed) << step.message;
    t = step.t;
    if (step.outcome == CvodeIntegrator::Outcome::FoundRoot) {
      EXPECT_EQ(i, 501);  // the output after 0.5 s waits for the root at 0.5005 s
      EXPECT_EQ(step.roots_found[0], 1);
      break;
    }
    EXPECT_DOUBLE_EQ(t, i * 1e-3);
  }
  EXPECT_NEAR(t, 0.5005, 1e-12);
  EXPECT_NEAR(integrator.state()[0], 0.5005, 1e-12);
}
