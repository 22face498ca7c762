#include "continuum/feedback_system.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
}  // namespace

void FeedbackSystem::rhs(double, const double *y, double *dydt) const {
  dydt[0] = model_.dRdt(y[0]);
  dydt[1] = model_.k(y[0]);
}

FeedbackSample FeedbackSystem::sample(double t, const double *y) const {
  FeedbackSample s;
  s.t = t;
  s.roughness = y[0];
  s.mu = model_.mu(y[0]);
  s.wear_rate = model_.k(y[0]);
  s.wear = y[1];
  return s;
}

void FeedbackRun::validate() const {
  require(std::isfinite(initial_roughness) && initial_roughness > 0.0, "initial_roughness must be positive");
  require(std::isfinite(t_end) && t_end > 0.0, "t_end must be positive");
  require(std::isfinite(output_interval) && output_interval > 0.0, "output_interval must be positive");
  require(t_end / output_interval <= 1e7, "output_interval gives more than 1e7 samples");
}

const char *to_string(FeedbackStatus status) {
  return status == FeedbackStatus::Success ? "success" : "integrator failure";
}

FeedbackReport simulate(const FeedbackSystem &system, const FeedbackRun &run, const FeedbackObserver &observer) {
  run.validate();
  const double round_off = 64.0 * std::numeric_limits<double>::epsilon() * run.t_end;
  FeedbackReport report;
  CvodeIntegrator integrator(2, run.integrator);
  std::vector<double> y = {run.initial_roughness, 0.0};
  double t = 0.0;
  integrator.restart(
      t, y, [&](double tt, const double *yy, double *dy) { system.rhs(tt, yy, dy); },
      [](double, const double *, double *) {}, {});
  observer(system.sample(t, y.data()));

  long next_grid = 1;
  while (t < run.t_end - round_off) {
    const double target = std::min(static_cast<double>(next_grid) * run.output_interval, run.t_end);
    const auto step = integrator.advance_to_output(target, run.t_end);  // dense output, one stop at t_end
    y = integrator.state();
    t = step.t;
    if (step.outcome != CvodeIntegrator::Outcome::ReachedTarget) {
      report.status = FeedbackStatus::IntegratorFailure;
      report.message = "CVODE failed at t = " + std::to_string(t) + ": " + step.message;
      break;
    }
    if (!(y[0] > 0.0) || !std::isfinite(y[0])) {
      report.status = FeedbackStatus::IntegratorFailure;
      report.message = "roughness left (0, inf) at t = " + std::to_string(t);
      break;
    }
    observer(system.sample(t, y.data()));
    ++next_grid;
  }
  report.end_time = t;
  report.steps = integrator.total_steps();
  return report;
}

double settling_time(const std::vector<FeedbackSample> &samples, double stationary_roughness, double tolerance) {
  const double band = tolerance * stationary_roughness;
  double settled = -1.0;
  for (auto it = samples.rbegin(); it != samples.rend(); ++it) {
    if (std::abs(it->roughness - stationary_roughness) > band) break;
    settled = it->t;
  }
  return settled;
}

}  // namespace runin::continuum
