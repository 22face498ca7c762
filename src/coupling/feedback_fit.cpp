#include "coupling/feedback_fit.h"

#include "tribo/number_format.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>

namespace runin::coupling {

const char *to_string(FeedbackFitStatus status) {
  switch (status) {
    case FeedbackFitStatus::Converged: return "converged";
    case FeedbackFitStatus::TooFewPoints: return "too few points";
    case FeedbackFitStatus::NonFinite: return "non-finite value";
    case FeedbackFitStatus::TimeNotIncreasing: return "time not increasing";
    case FeedbackFitStatus::NonPositive: return "non-positive value";
    case FeedbackFitStatus::ConstantRoughness: return "degenerate data (R constant)";
    case FeedbackFitStatus::NoEquilibrium: return "no equilibrium roughness";
    case FeedbackFitStatus::NoRunIn: return "no run-in";
    case FeedbackFitStatus::NoFrictionMinimum: return "no friction minimum";
    case FeedbackFitStatus::PoorFit: return "poor fit";
    case FeedbackFitStatus::NotConverged: return "not converged";
  }
  return "unknown";
}

namespace {

using tribo::format_g;

// Relative residuals of R^2: r_i = w_i (v_inf + (v_0 - v_inf) E_i) - 1 with E_i = exp(-2 b x_i),
// x_i = (t_i - t_0) / span in [0, 1], w_i = scale / R_i^2, u = scale v. p = (v_inf, v_0, ln b): b > 0.
struct SquaredRoughnessResidual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const Eigen::ArrayXd &x;
  const Eigen::ArrayXd &w;

  int inputs() const { return 3; }
  int values() const { return static_cast<int>(x.size()); }

  int operator()(const Eigen::VectorXd &p, Eigen::VectorXd &r) const {
    const Eigen::ArrayXd e = (-2.0 * std::exp(p[2]) * x).exp();
    r = (w * (p[0] + (p[1] - p[0]) * e) - 1.0).matrix();
    return 0;
  }
  int df(const Eigen::VectorXd &p, Eigen::MatrixXd &jac) const {
    const double b = std::exp(p[2]);
    const Eigen::ArrayXd e = (-2.0 * b * x).exp();
    jac.resize(x.size(), 3);
    jac.col(0) = (w * (1.0 - e)).matrix();
    jac.col(1) = (w * e).matrix();
    jac.col(2) = (w * (p[1] - p[0]) * e * (-2.0 * b * x)).matrix();  // d/d(ln b)
    return 0;
  }
};

// Best (v_inf, v_0) for a fixed b (the problem is linear in them) and its sum of squares.
double linear_part(const Eigen::ArrayXd &x, const Eigen::ArrayXd &w, double b, double &v_inf, double &v_0) {
  const Eigen::ArrayXd e = (-2.0 * b * x).exp();
  Eigen::MatrixXd m(x.size(), 2);
  m.col(0) = (w * (1.0 - e)).matrix();
  m.col(1) = (w * e).matrix();
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(x.size());
  const Eigen::VectorXd c = m.colPivHouseholderQr().solve(ones);
  v_inf = c[0];
  v_0 = c[1];
  return (m * c - ones).squaredNorm();
}

FeedbackFitResult fail(FeedbackFitResult r, FeedbackFitStatus status, const std::string &message) {
  r.status = status;
  r.message = message;
  r.model.reset();
  return r;
}

}  // namespace

FeedbackFitResult fit_feedback(const FeedbackSeries &d, const FeedbackFitOptions &options) {
  FeedbackFitResult r;
  const std::size_t n = d.t.size();
  r.points = n;
  if (d.mu.size() != n || d.R.size() != n)
    return fail(r, FeedbackFitStatus::TooFewPoints,
                "columns of different length: " + d.t_name + " " + std::to_string(n) + ", " + d.mu_name + " " +
                    std::to_string(d.mu.size()) + ", " + d.R_name + " " + std::to_string(d.R.size()));
  if (n < FeedbackFitResult::kMinPoints)
    return fail(r, FeedbackFitStatus::TooFewPoints,
                std::to_string(n) + " rows; the fit needs at least " +
                    std::to_string(FeedbackFitResult::kMinPoints));
  for (std::size_t i = 0; i < n; ++i) {
    r.bad_row = i;
    const std::pair<const std::string *, double> values[] = {{&d.t_name, d.t[i]}, {&d.mu_name, d.mu[i]},
                                                             {&d.R_name, d.R[i]}};
    for (const auto &[name, value] : values)
      if (!std::isfinite(value))
        return fail(r, FeedbackFitStatus::NonFinite,
                    "column '" + *name + "', row " + std::to_string(i + 1) + ": non-finite value " + format_g(value));
    if (i > 0 && !(d.t[i] > d.t[i - 1]))
      return fail(r, FeedbackFitStatus::TimeNotIncreasing,
                  "column '" + d.t_name + "', row " + std::to_string(i + 1) + ": " + format_g(d.t[i]) +
                      " does not increase (previous " + format_g(d.t[i - 1]) + ")");
    if (!(d.R[i] > 0.0))
      return fail(r, FeedbackFitStatus::NonPositive,
                  "column '" + d.R_name + "', row " + std::to_string(i + 1) + ": roughness " + format_g(d.R[i]) +
                      " must be > 0");
    if (!(d.mu[i] > 0.0))
      return fail(r, FeedbackFitStatus::NonPositive,
                  "column '" + d.mu_name + "', row " + std::to_string(i + 1) + ": friction coefficient " +
                      format_g(d.mu[i]) + " must be > 0");
  }
  r.bad_row = FeedbackFitResult::kNoRow;
  const auto [r_min, r_max] = std::minmax_element(d.R.begin(), d.R.end());
  if (*r_max - *r_min <= 1e-9 * *r_max)
    return fail(r, FeedbackFitStatus::ConstantRoughness,
                "column '" + d.R_name + "' is constant (" + format_g(*r_max) +
                    "): the run-in rate and C1, C2 apart are not determined");

  // R(t): scaled so that every parameter is O(1) whatever the units.
  r.t0 = d.t.front();
  const double span = d.t.back() - r.t0;
  const double scale = *r_max * *r_max;
  Eigen::ArrayXd x(n), w(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (d.t[i] - r.t0) / span;
    w[i] = scale / (d.R[i] * d.R[i]);
  }
  // Start: the best b = a span on a log grid 1e-3 .. 1e4, the linear part solved exactly for each.
  double best = std::numeric_limits<double>::infinity(), best_b = 1.0, v_inf = 0.0, v_0 = 1.0;
  for (int k = 0; k <= 140; ++k) {
    const double b = std::pow(10.0, -3.0 + 7.0 * k / 140.0);
    double vi = 0.0, v0 = 0.0;
    const double ss = linear_part(x, w, b, vi, v0);
    if (std::isfinite(ss) && ss < best) best = ss, best_b = b, v_inf = vi, v_0 = v0;
  }
  SquaredRoughnessResidual residual{x, w};
  Eigen::LevenbergMarquardt<SquaredRoughnessResidual> solver(residual);
  solver.parameters.ftol = 1e-15;
  solver.parameters.xtol = 1e-15;
  solver.parameters.maxfev = 5000;
  Eigen::VectorXd p(3);
  p << v_inf, v_0, std::log(best_b);
  const auto lm = solver.minimize(p);
  r.lm_status = static_cast<int>(lm);
  r.lm_evaluations = static_cast<long>(solver.nfev);
  using namespace Eigen::LevenbergMarquardtSpace;
  const bool converged = lm == RelativeReductionTooSmall || lm == RelativeErrorTooSmall ||
                         lm == RelativeErrorAndReductionTooSmall || lm == CosinusTooSmall || lm == FtolTooSmall ||
                         lm == XtolTooSmall || lm == GtolTooSmall;
  if (!converged || !p.allFinite())
    return fail(r, FeedbackFitStatus::NotConverged,
                "Levenberg-Marquardt on R(t)^2 stopped with status " + std::to_string(r.lm_status) + " after " +
                    std::to_string(r.lm_evaluations) + " evaluations");

  const double b = std::exp(p[2]);
  const double u_inf = scale * p[0], u_0 = scale * p[1];
  if (!(u_0 > 0.0))
    return fail(r, FeedbackFitStatus::NotConverged, "fitted R0^2 = " + format_g(u_0) + " is not positive");
  r.rate = b / span;
  r.R0 = std::sqrt(u_0);
  r.R_star = u_inf > 0.0 ? std::sqrt(u_inf) : 0.0;
  r.B_K2 = r.rate * std::max(u_inf, 0.0);

  // Standard errors: covariance s^2 (J^T J)^-1 with s^2 = SSR / (n - 3), through the SVD of J; a J of
  // (numerically) lower rank leaves a parameter undetermined.
  Eigen::VectorXd res;
  Eigen::MatrixXd jac;
  residual(p, res);
  residual.df(p, jac);
  const double s2 = res.squaredNorm() / static_cast<double>(n - 3);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(jac, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  bool determined = sv.allFinite() && sv[2] > 1e-10 * sv[0];
  if (determined) {
    const Eigen::MatrixXd v = svd.matrixV();
    const Eigen::MatrixXd cov = s2 * v * sv.cwiseAbs2().cwiseInverse().asDiagonal() * v.transpose();
    r.R_star_squared_error = scale * std::sqrt(cov(0, 0));
    r.R0_squared_error = scale * std::sqrt(cov(1, 1));
    r.rate_error = r.rate * std::sqrt(cov(2, 2));  // d a = a d(ln b)
    determined = std::isfinite(r.R_star_squared_error) && std::isfinite(r.rate_error);
  }

  // mu(R): rows weighted by 1/mu_i, so the fit minimises the relative error.
  Eigen::MatrixXd m(n, 2);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
  for (std::size_t i = 0; i < n; ++i) {
    m(i, 0) = d.R[i] / d.mu[i];
    m(i, 1) = 1.0 / (d.R[i] * d.mu[i]);
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
  if (qr.rank() < 2)
    return fail(r, FeedbackFitStatus::ConstantRoughness,
                "R and 1/R are collinear over the data: C1 and C2 are not determined apart");
  Eigen::VectorXd c = qr.solve(ones);
  if (c[1] < 0.0) {  // best with C2 = 0 (the constraint is active)
    c[1] = 0.0;
    c[0] = m.col(0).dot(ones) / m.col(0).squaredNorm();
    r.C2_clamped = true;
  }
  r.C1 = c[0];
  r.C2 = c[1];
  {
    const double dof = static_cast<double>(n) - (r.C2_clamped ? 1.0 : 2.0);
    const double s2_mu = (m * c - ones).squaredNorm() / dof;
    if (r.C2_clamped) {
      r.C1_error = std::sqrt(s2_mu / m.col(0).squaredNorm());
    } else {
      const Eigen::Matrix2d inverse = (m.transpose() * m).inverse();
      r.C1_error = std::sqrt(std::max(s2_mu * inverse(0, 0), 0.0));
      r.C2_error = std::sqrt(std::max(s2_mu * inverse(1, 1), 0.0));
    }
  }

  // Residuals of the fitted closed form (an R(t) that reaches 0 misses by 100 %, and mu there by more).
  double sr = 0.0, sm = 0.0, sml = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = u_inf + (u_0 - u_inf) * std::exp(-2.0 * r.rate * (d.t[i] - r.t0));
    const double R = std::sqrt(std::max(u, 0.0));
    const double mu = R > 0.0 ? r.C1 * R + r.C2 / R : std::numeric_limits<double>::max();
    const double er = std::abs(R - d.R[i]) / d.R[i];
    const double em = std::min(std::abs(mu - d.mu[i]) / d.mu[i], 1e300);
    const double eml = std::abs(r.C1 * d.R[i] + r.C2 / d.R[i] - d.mu[i]) / d.mu[i];
    r.R_max_rel_error = std::max(r.R_max_rel_error, er);
    r.mu_max_rel_error = std::max(r.mu_max_rel_error, em);
    r.mu_of_R_max_rel_error = std::max(r.mu_of_R_max_rel_error, eml);
    sr += er * er;
    sm += std::min(em * em, 1e300);
    sml += eml * eml;
  }
  r.R_rms_rel_error = std::sqrt(sr / static_cast<double>(n));
  r.mu_rms_rel_error = std::sqrt(sm / static_cast<double>(n));
  r.mu_of_R_rms_rel_error = std::sqrt(sml / static_cast<double>(n));

  // What the data do not support, the most telling first.
  const double limit = options.max_rms_relative_error;
  if (r.R_rms_rel_error > limit || r.mu_rms_rel_error > limit) {
    const bool by_R = r.R_rms_rel_error > limit;
    return fail(r, FeedbackFitStatus::PoorFit,
                std::string("the fitted model misses ") + (by_R ? d.R_name + "(t)" : d.mu_name + "(t)") +
                    " by an RMS relative error of " + format_g(by_R ? r.R_rms_rel_error : r.mu_rms_rel_error) + " (> " +
                    format_g(limit) + "; max " + format_g(by_R ? r.R_max_rel_error : r.mu_max_rel_error) +
                    "): the data do not follow the feedback model (R monotone towards R* > 0)");
  }
  // R* > 0 must be carried by the data: well above rounding and three standard errors from 0.
  if (!determined || !(u_inf > 1e-9 * scale) || !(u_inf > 3.0 * r.R_star_squared_error))
    return fail(r, FeedbackFitStatus::NoEquilibrium,
                "R(t) runs towards no positive equilibrium roughness: fitted R*^2 = " + format_g(u_inf) +
                    (determined ? " +- " + format_g(r.R_star_squared_error) : std::string(" (not determined)")) +
                    ", rate A K1 = " + format_g(r.rate) + " per unit of " + d.t_name +
                    "; the model needs R to settle at an R* > 0 within the data");
  if (!(r.rate > 3.0 * r.rate_error))
    return fail(r, FeedbackFitStatus::NoRunIn,
                "the run-in rate A K1 = " + format_g(r.rate) + " +- " + format_g(r.rate_error) + " per unit of " + d.t_name +
                    " is not determined: " + d.R_name + " hardly changes over the data (R0 = " + format_g(r.R0) +
                    ", R* = " + format_g(r.R_star) + ")");
  if (!(r.C1 > 3.0 * r.C1_error))
    return fail(r, FeedbackFitStatus::NoFrictionMinimum,
                "fitted C1 = " + format_g(r.C1) + " +- " + format_g(r.C1_error) + " is not > 0: " + d.mu_name +
                    " does not grow with R as C1 R + C2/R needs for a friction minimum");

  tribo::FeedbackCoefficients k;
  k.C1 = r.C1;
  k.C2 = r.C2;
  k.A = 1.0;
  k.B = 1.0;
  k.K1 = r.rate;
  k.K2 = r.B_K2;
  try {
    r.model.emplace(k, options.kind);
  } catch (const tribo::InvalidCoefficient &e) {
    return fail(r, FeedbackFitStatus::NotConverged, std::string("fitted constants rejected: ") + e.what());
  }
  r.status = FeedbackFitStatus::Converged;
  return r;
}

double fitted_roughness(const FeedbackFitResult &fit, double t) {
  const double rs2 = fit.R_star * fit.R_star;
  return std::sqrt(std::max(rs2 + (fit.R0 * fit.R0 - rs2) * std::exp(-2.0 * fit.rate * (t - fit.t0)), 0.0));
}

double fitted_mu(const FeedbackFitResult &fit, double t) {
  const double R = fitted_roughness(fit, t);
  return fit.C1 * R + fit.C2 / R;
}

}  // namespace runin::coupling
