// Continuum integration of the two-mechanism roughness-feedback model (thesis ch. 3):
// state y = (R, W) with dR/dt = -A K1 R + B K2 / R and dW/dt = k(R) = K1 R + K2 / R,
// W the cumulative wear (integral of the wear rate). CVODE via CvodeIntegrator; the
// system (physics), the stepper (simulate) and the observer are separate, as in pin_on_disk.h.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "continuum/cvode_integrator.h"
#include "tribo/feedback.h"

namespace runin::continuum {

struct FeedbackSample {
  double t = 0.0;
  double roughness = 0.0;  // R
  double mu = 0.0;         // mu(R)
  double wear_rate = 0.0;  // k(R)
  double wear = 0.0;       // W = integral of k(R) dt from 0
};

class FeedbackSystem {
 public:
  explicit FeedbackSystem(tribo::FeedbackModel model) : model_(model) {}
  const tribo::FeedbackModel &model() const { return model_; }
  void rhs(double t, const double *y, double *dydt) const;
  FeedbackSample sample(double t, const double *y) const;

 private:
  tribo::FeedbackModel model_;
};

struct FeedbackRun {
  double initial_roughness = 0.0;  // R0 > 0
  double t_end = 0.0;
  double output_interval = 0.0;
  // Tighter than CvodeIntegrator's generic defaults (rtol 1e-8 gives a global error of up to
  // ~1e-7 relative in R here): with these, CVODE R(t) meets the closed form to 1e-8 relative.
  CvodeIntegrator::Settings integrator = default_settings();

  static CvodeIntegrator::Settings default_settings() {
    CvodeIntegrator::Settings s;
    s.rtol = 1e-10;
    s.atol = 1e-14;
    return s;
  }

  void validate() const;  // throws std::invalid_argument naming the field
};

enum class FeedbackStatus { Success, IntegratorFailure };
const char *to_string(FeedbackStatus status);

struct FeedbackReport {
  FeedbackStatus status = FeedbackStatus::Success;
  std::string message;  // empty on success
  double end_time = 0.0;
  long steps = 0;       // CVODE internal steps
  bool ok() const { return status == FeedbackStatus::Success; }
};

using FeedbackObserver = std::function<void(const FeedbackSample &)>;

// The stepper: one CVODE problem from t = 0, one output sample per output_interval (and t_end).
// Numerical failure is reported in the status, bad settings throw std::invalid_argument.
FeedbackReport simulate(const FeedbackSystem &system, const FeedbackRun &run, const FeedbackObserver &observer);

// First sample time after which |R - R*| <= tolerance R* at every later sample; -1 if the
// last sample is outside the band.
double settling_time(const std::vector<FeedbackSample> &samples, double stationary_roughness,
                     double tolerance = 0.01);

}  // namespace runin::continuum
