// Fit of the two-mechanism roughness-feedback model (thesis ch. 3, tribo/feedback.h) to a run-in series
// (t_i, mu_i, R_i); t is time or sliding distance, R a roughness, in any units.
//
// What the data determine: R(t)^2 = R*^2 + (R0^2 - R*^2) exp(-2 a t) gives R0, R* and the rate a = A K1
// (nonlinear least squares, Eigen's Levenberg-Marquardt, on the relative error of R^2); then B K2 = a R*^2.
// A and K1 enter R(t) only as the product A K1, B and K2 only as B K2, and the wear rate k(R) is not in the
// data, so the fitted model is written with A = B = 1, K1 = a, K2 = a R*^2 (wear in units where the
// feedback gains are 1). mu(R) = C1 R + C2 / R gives C1, C2 by linear least squares (Eigen QR) on the
// measured (R, 1/R), rows weighted by 1/mu_i (relative error), with C2 >= 0 enforced.
// t is taken from the first point: the fitted R0 is the model's R at t_0 and the model's time is t - t_0.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tribo/feedback.h"

namespace runin::coupling {

struct FeedbackSeries {
  std::vector<double> t, mu, R;
  // Names used in messages (the CSV column names, say).
  std::string t_name = "t", mu_name = "mu", R_name = "R";
};

enum class FeedbackFitStatus {
  Converged,
  TooFewPoints,       // fewer than kMinPoints rows, or columns of different length
  NonFinite,          // a nan / inf value
  TimeNotIncreasing,  // t_i <= t_{i-1}
  NonPositive,        // R <= 0 or mu <= 0
  ConstantRoughness,  // R (nearly) constant: neither the rate nor C1, C2 apart are determined
  NoEquilibrium,      // R*^2 not significantly > 0 (R runs towards 0) or not determined by the data
  NoRunIn,            // the rate A K1 not significantly > 0: R hardly changes (noise about a level)
  NoFrictionMinimum,  // fitted C1 not significantly > 0: mu does not grow with R
  PoorFit,            // the fitted model misses the data by more than the allowed RMS relative error
  NotConverged,       // Levenberg-Marquardt failed
};
const char *to_string(FeedbackFitStatus status);

struct FeedbackFitOptions {
  tribo::FeedbackKind kind = tribo::FeedbackKind::lubricated;  // only names the mechanisms
  // PoorFit when the RMS relative error of R(t) or of mu(t) exceeds this.
  double max_rms_relative_error = 0.05;
};

struct FeedbackFitResult {
  static constexpr std::size_t kMinPoints = 5;

  FeedbackFitStatus status = FeedbackFitStatus::NotConverged;
  std::string message;  // one line; why not, when status != Converged
  static constexpr std::size_t kNoRow = static_cast<std::size_t>(-1);
  std::size_t bad_row = kNoRow;  // 0-based row of a NonFinite / TimeNotIncreasing / NonPositive value
  bool ok() const { return status == FeedbackFitStatus::Converged; }

  // Fitted constants (meaningful once the R fit has run; R_star may be 0 for NoEquilibrium).
  double t0 = 0.0;          // the first data time; model time = t - t0
  double R0 = 0.0;          // model R at t0
  double R_star = 0.0;      // stationary roughness
  double rate = 0.0;        // a = A K1
  double B_K2 = 0.0;        // a R*^2
  double C1 = 0.0, C2 = 0.0;
  // One standard error (from the Gauss-Newton covariance at the optimum) of R*^2, R0^2 and a.
  double R_star_squared_error = 0.0, R0_squared_error = 0.0, rate_error = 0.0;
  double C1_error = 0.0, C2_error = 0.0;  // of the linear fit (covariance s^2 (M^T M)^-1)
  bool C2_clamped = false;  // the unconstrained C2 was < 0; refitted with C2 = 0

  // Residuals of the fitted model (R(t) from the exact solution, mu = mu(R(t))) against the data:
  // max_i |model_i - data_i| / |data_i| and sqrt(mean of its squares).
  double R_max_rel_error = 0.0, R_rms_rel_error = 0.0;
  double mu_max_rel_error = 0.0, mu_rms_rel_error = 0.0;
  // The same for mu(R) of the fitted C1, C2 at the measured R (the linear fit alone).
  double mu_of_R_max_rel_error = 0.0, mu_of_R_rms_rel_error = 0.0;
  std::size_t points = 0;
  int lm_status = 0;        // Eigen's LevenbergMarquardtSpace::Status
  long lm_evaluations = 0;  // residual evaluations

  // A = B = 1, K1 = a, K2 = a R*^2; only when ok().
  std::optional<tribo::FeedbackModel> model;
};

FeedbackFitResult fit_feedback(const FeedbackSeries &data, const FeedbackFitOptions &options = {});

// The fitted model's R and mu at data time t (t0 subtracted here).
double fitted_roughness(const FeedbackFitResult &fit, double t);
double fitted_mu(const FeedbackFitResult &fit, double t);

}  // namespace runin::coupling
