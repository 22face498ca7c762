// The state-law splitting driver (src/continuum/state_law_splitting.h) on a toy element with a closed-form coupled
// solution, and its statuses on failure.
//
// Toy: a block slides at constant speed V (s = V t) and its state y decays by the held friction,
// dy/dt = -mu y; the friction follows the worn state, dmu/ds = c. Coupled (exact): mu = mu0 + c V t,
// y(T) = exp(-(mu0 T + c V T^2 / 2)). Split at interval dt (mu held over each interval, advanced at its end):
// y_split(T) = exp(-dt sum_k mu_k) = exp(-(mu0 T + c V T (T - dt) / 2)), so ln(y_split / y) = c V T dt / 2: first
// order in dt, exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "continuum/state_law_splitting.h"

namespace {

using runin::continuum::FastStepper;
using runin::continuum::SlowStepError;
using runin::continuum::SlowSystem;
using runin::continuum::SolveReport;
using runin::continuum::SolveStatus;
using runin::continuum::SplitStatus;

constexpr double kV = 2.0, kC = 0.5, kMu0 = 0.3, kT = 1.0;

struct ToySample {
  double t = 0.0, s = 0.0, y = 1.0;
};

// The fast stepper: exact integration over each output interval with the held mu; the restarts it is asked for
// are counted (an exact integrator needs none).
struct ToyFast {
  const double &mu;
  double dt;
  int restarts = 0;
  SolveStatus fail_with = SolveStatus::Success;
  double fail_at = 1e300;
  SolveReport operator()(const std::function<void(const ToySample &)> &on_sample, const std::function<bool()> &refresh) {
    SolveReport report;
    ToySample x;
    on_sample(x);
    const int n = static_cast<int>(std::lround(kT / dt));
    for (int k = 1; k <= n; ++k) {
      if (x.t + dt > fail_at) {
        report.status = fail_with;
        report.message = "toy failure";
        break;
      }
      x.y *= std::exp(-mu * dt);
      x.t = k * dt;
      x.s = kV * x.t;
      on_sample(x);
      if (refresh()) ++restarts;
    }
    report.end_time = x.t;
    return report;
  }
};

// The slow system: mu advanced exactly by c over the distance slid since the last step.
struct ToySlow : SlowSystem<ToySample> {
  double mu = 0.0, slid = 0.0;
  double throw_at = 1e300;
  int what = 0;  // 0: std::out_of_range, 1: SlowStepError, 2: std::invalid_argument
  void start() override { mu = kMu0; }
  bool step(const ToySample &x) override {
    if (x.t >= throw_at) {
      if (what == 0) throw std::out_of_range("p = 9e9 Pa is above the law's grid");
      if (what == 1) throw SlowStepError(SplitStatus::SlowFailure, "contact did not converge");
      throw std::invalid_argument("negative slid distance");
    }
    const double ds = x.s - slid;
    if (!(ds > 0.0)) return false;
    mu += kC * ds;
    slid = x.s;
    return true;
  }
};

double split_y(double dt, int *restarts = nullptr) {
  ToySlow slow;
  ToyFast fast{slow.mu, dt};
  double y = 0.0;
  const auto report = runin::continuum::split_run<ToySample>(
      slow, FastStepper<ToySample>(std::ref(fast)), [&](const ToySample &x) { y = x.y; });
  EXPECT_TRUE(report.ok()) << report.message;
  EXPECT_DOUBLE_EQ(report.time, kT);
  EXPECT_EQ(report.slow_steps, std::lround(kT / dt));
  if (restarts) *restarts = fast.restarts;
  return y;
}

}  // namespace

TEST(StateLawSplitting, ConvergesAtFirstOrderToTheExactCoupledSolution) {
  const double exact = std::exp(-(kMu0 * kT + 0.5 * kC * kV * kT * kT));
  std::vector<double> error;
  for (double dt : {0.1, 0.05, 0.025, 0.0125}) {
    const double y = split_y(dt);
    error.push_back(std::log(y / exact));
    EXPECT_NEAR(error.back(), 0.5 * kC * kV * kT * dt, 1e-12) << dt;  // the closed-form splitting error
  }
  for (std::size_t i = 0; i + 1 < error.size(); ++i) EXPECT_NEAR(error[i] / error[i + 1], 2.0, 1e-9);
}

TEST(StateLawSplitting, TheFastStepperRestartsOnlyWhereTheCoefficientsChanged) {
  int restarts = 0;
  split_y(0.1, &restarts);
  EXPECT_EQ(restarts, 10);
  // no sliding: no change, no restart
  ToySlow slow;
  ToyFast fast{slow.mu, 0.1};
  const auto still = [&](const std::function<void(const ToySample &)> &on_sample, const std::function<bool()> &refresh) {
    SolveReport r;
    for (int k = 0; k <= 10; ++k) {
      on_sample({0.1 * k, 0.0, 1.0});
      if (refresh()) ++fast.restarts;
    }
    return r;
  };
  const auto report = runin::continuum::split_run<ToySample>(slow, still, nullptr);
  EXPECT_TRUE(report.ok());
  EXPECT_EQ(report.slow_steps, 0);
  EXPECT_EQ(fast.restarts, 0);
}

TEST(StateLawSplitting, SlowFailuresAreStatusesWithTimeAndMessage) {
  struct Case {
    int what;
    SplitStatus status;
    const char *message;
  };
  for (const Case &c : {Case{0, SplitStatus::LawOutOfRange, "p = 9e9 Pa is above the law's grid"},
                        Case{1, SplitStatus::SlowFailure, "contact did not converge"},
                        Case{2, SplitStatus::InvalidState, "negative slid distance"}}) {
    ToySlow slow;
    slow.throw_at = 0.5;
    slow.what = c.what;
    ToyFast fast{slow.mu, 0.1};
    double last_observed = -1.0;
    const auto report = runin::continuum::split_run<ToySample>(slow, FastStepper<ToySample>(std::ref(fast)),
                                                               [&](const ToySample &x) { last_observed = x.t; });
    EXPECT_EQ(report.status, c.status) << c.what;
    EXPECT_EQ(report.message, c.message);
    EXPECT_NEAR(report.time, 0.5, 1e-12);
    EXPECT_NEAR(last_observed, 0.4, 1e-12);  // the failing sample is not observed
    EXPECT_FALSE(report.ok());
  }
}

TEST(StateLawSplitting, AFailingStartIsAStatusAtTimeZero) {
  ToySlow slow;
  slow.throw_at = -1.0;  // ToySlow::start does not throw: fail the first step instead, at t = 0
  ToyFast fast{slow.mu, 0.1};
  const auto report = runin::continuum::split_run<ToySample>(slow, FastStepper<ToySample>(std::ref(fast)), nullptr);
  EXPECT_EQ(report.status, SplitStatus::LawOutOfRange);
  EXPECT_EQ(report.time, 0.0);

  struct BadStart : ToySlow {
    void start() override { throw std::out_of_range("p = 1 Pa is below the law's grid"); }
  } bad;
  bool ran = false;
  const auto stopped = runin::continuum::split_run<ToySample>(
      bad, [&](const auto &, const auto &) { ran = true; return SolveReport{}; }, nullptr);
  EXPECT_EQ(stopped.status, SplitStatus::LawOutOfRange);
  EXPECT_EQ(stopped.message, "p = 1 Pa is below the law's grid");
  EXPECT_FALSE(ran);
}

TEST(StateLawSplitting, AFastFailureIsReportedWithTheFastStatus) {
  ToySlow slow;
  ToyFast fast{slow.mu, 0.1};
  fast.fail_with = SolveStatus::TooManyEvents;
  fast.fail_at = 0.55;
  const auto report = runin::continuum::split_run<ToySample>(slow, FastStepper<ToySample>(std::ref(fast)), nullptr);
  EXPECT_EQ(report.status, SplitStatus::FastFailure);
  EXPECT_EQ(report.fast.status, SolveStatus::TooManyEvents);
  EXPECT_EQ(report.message, "toy failure");
  EXPECT_NEAR(report.time, 0.5, 1e-12);
}

TEST(StateLawSplitting, TheObserversOwnExceptionsPassThrough) {
  ToySlow slow;
  ToyFast fast{slow.mu, 0.1};
  EXPECT_THROW(runin::continuum::split_run<ToySample>(slow, FastStepper<ToySample>(std::ref(fast)),
                                                      [](const ToySample &x) {
                                                        if (x.t > 0.25) throw std::out_of_range("observer");
                                                      }),
               std::out_of_range);
}
