#include "coupling/friction_law.h"
#include "coupling/json_input.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <unsupported/Eigen/NonLinearOptimization>

namespace runin::coupling {

TabulatedLaw::TabulatedLaw(std::vector<double> distance, std::vector<double> mu)
    : distance_(std::move(distance)), mu_(std::move(mu)) {
  if (distance_.size() != mu_.size())
    throw std::invalid_argument("tabulated law: distance and mu differ in length");
  if (distance_.size() < 2) throw std::invalid_argument("tabulated law: needs at least 2 points");
  for (std::size_t i = 0; i < distance_.size(); ++i) {
    if (!std::isfinite(distance_[i]) || !std::isfinite(mu_[i]))
      throw std::invalid_argument("tabulated law: non-finite value at point " + std::to_string(i));
    if (i > 0 && !(distance_[i] > distance_[i - 1]))
      throw std::invalid_argument("tabulated law: distance does not strictly increase at point " +
                                  std::to_string(i));
  }
}

double TabulatedLaw::operator()(double s) const {
  if (s <= distance_.front()) return mu_.front();
  if (s >= distance_.back()) return mu_.back();
  const auto upper = std::upper_bound(distance_.begin(), distance_.end(), s);
  const std::size_t i = static_cast<std::size_t>(upper - distance_.begin());
  const double w = (s - distance_[i - 1]) / (distance_[i] - distance_[i - 1]);
  return (1.0 - w) * mu_[i - 1] + w * mu_[i];
}

std::size_t TabulatedLaw::peak_index() const {
  return static_cast<std::size_t>(std::max_element(mu_.begin(), mu_.end()) - mu_.begin());
}

double RunInFit::operator()(double s) const {
  return mu_ss + (mu_0 - mu_ss) * std::exp(-(s - s_peak) / s0);
}

const char *to_string(FitStatus status) {
  switch (status) {
    case FitStatus::Converged: return "converged";
    case FitStatus::TooFewPoints: return "too few points after the peak";
    case FitStatus::NoDecay: return "no decay after the peak";
    case FitStatus::NotConverged: return "not converged";
  }
  return "unknown";
}

namespace {

// Residuals r_i = mu_ss + (mu_0 - mu_ss) exp(-x_i / s0) - y_i with x_i the distance past
// the peak divided by the fitted span (keeps the problem well scaled for any unit).
// Parameters p = (mu_ss, mu_0, ln s0) so that s0 stays positive.
struct RunInResidual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const Eigen::VectorXd &x;
  const Eigen::VectorXd &y;

  int inputs() const { return 3; }
  int values() const { return static_cast<int>(x.size()); }

  int operator()(const Eigen::VectorXd &p, Eigen::VectorXd &r) const {
    const Eigen::ArrayXd decay = (-x.array() / std::exp(p[2])).exp();
    r = (p[0] + (p[1] - p[0]) * decay - y.array()).matrix();
    return 0;
  }
  int df(const Eigen::VectorXd &p, Eigen::MatrixXd &jac) const {
    const double s0 = std::exp(p[2]);
    const Eigen::ArrayXd decay = (-x.array() / s0).exp();
    jac.resize(x.size(), 3);
    jac.col(0) = (1.0 - decay).matrix();
    jac.col(1) = decay.matrix();
    jac.col(2) = ((p[1] - p[0]) * decay * x.array() / s0).matrix();  // d/d(ln s0)
    return 0;
  }
};

}  // namespace

FitResult fit_run_in(const TabulatedLaw &data) {
  FitResult result;
  const std::size_t peak = data.peak_index();
  const std::size_t n = data.distance().size() - peak;
  if (n < 4) {
    result.status = FitStatus::TooFewPoints;
    result.message = std::to_string(n) + " points from the peak on, need at least 4";
    return result;
  }
  const double s_peak = data.distance()[peak];
  const double span = data.distance().back() - s_peak;
  Eigen::VectorXd x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = (data.distance()[peak + i] - s_peak) / span;
    y[i] = data.mu()[peak + i];
  }

  // Initial guess: peak value, mean of the last quarter, distance of the 1/e drop.
  const std::size_t tail = std::max<std::size_t>(1, n / 4);
  const double mu_ss_guess = y.tail(tail).mean();
  const double mu_0_guess = y[0];
  const double drop = mu_0_guess - mu_ss_guess;
  if (!(drop > 1e-12 * std::max(1.0, std::abs(mu_0_guess)))) {
    result.status = FitStatus::NoDecay;
    result.message = "mu after the peak does not fall towards a lower steady value";
    return result;
  }
  double s0_guess = 1.0 / 3.0;
  for (std::size_t i = 1; i < n; ++i)
    if (y[i] - mu_ss_guess <= drop / std::exp(1.0)) {
      s0_guess = std::max(x[i], 1e-6);
      break;
    }

  RunInResidual residual{x, y};
  Eigen::LevenbergMarquardt<RunInResidual> solver(residual);
  solver.parameters.ftol = 1e-15;
  solver.parameters.xtol = 1e-15;
  solver.parameters.maxfev = 5000;
  Eigen::VectorXd p(3);
  p << mu_ss_guess, mu_0_guess, std::log(s0_guess);
  const auto status = solver.minimize(p);
  using namespace Eigen::LevenbergMarquardtSpace;
  const bool converged = status == RelativeReductionTooSmall || status == RelativeErrorTooSmall ||
                         status == RelativeErrorAndReductionTooSmall || status == CosinusTooSmall ||
                         status == FtolTooSmall || status == XtolTooSmall || status == GtolTooSmall;
  if (!converged || !p.allFinite()) {
    result.status = FitStatus::NotConverged;
    result.message = "Levenberg-Marquardt status " + std::to_string(static_cast<int>(status));
    return result;
  }
  Eigen::VectorXd r;
  residual(p, r);
  result.status = FitStatus::Converged;
  result.fit.mu_ss = p[0];
  result.fit.mu_0 = p[1];
  result.fit.s0 = std::exp(p[2]) * span;
  result.fit.s_peak = s_peak;
  result.fit.rms_residual = std::sqrt(r.squaredNorm() / static_cast<double>(n));
  result.fit.points = n;
  return result;
}

double FrictionLaw::evaluate(double s, Branch branch) const {
  if (branch == Branch::Fit && fit && s >= fit->s_peak) return (*fit)(s);
  return table(s);
}

double metres_per_unit(const std::string &unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um") return 1e-6;
  if (unit == "nm") return 1e-9;
  if (unit == "angstrom") return 1e-10;
  throw std::invalid_argument("unknown distance unit '" + unit + "' (m, mm, um, nm, angstrom)");
}

FrictionLaw build_law(const AveTimeTable &table, const std::string &distance_column,
                      const std::string &mu_column, const std::string &distance_unit,
                      FitResult *fit_report) {
  std::optional<TabulatedLaw> tabulated;
  try {
    tabulated.emplace(table.column(distance_column), table.column(mu_column));
  } catch (const std::invalid_argument &e) {
    throw InputFormatError(table.source() + ": columns '" + distance_column + "', '" + mu_column +
                           "': " + e.what());
  }
  FrictionLaw law{table.source(), distance_column, mu_column, distance_unit,
                  metres_per_unit(distance_unit), *tabulated, std::nullopt};
  const FitResult fit = fit_run_in(law.table);
  if (fit.status == FitStatus::Converged) law.fit = fit.fit;
  if (fit_report) *fit_report = fit;
  return law;
}

std::string law_to_json_text(const FrictionLaw &law) {
  using nlohmann::json;
  json doc;
  doc["format"] = "runin-friction-law";
  doc["version"] = 1;
  doc["source"] = {{"file", law.source_file},
                   {"distance_column", law.distance_column},
                   {"mu_column", law.mu_column}};
  doc["units"] = {{"distance", law.distance_unit},
                  {"distance_in_m", law.distance_unit_in_m},
                  {"mu", "1"}};
  doc["peak"] = {{"distance", law.peak_distance()}, {"mu", law.table.mu()[law.table.peak_index()]}};
  if (law.fit) {
    const RunInFit &f = *law.fit;
    doc["fit"] = {{"form", "mu(s) = mu_ss + (mu_0 - mu_ss) * exp(-(s - s_peak) / s0), s >= s_peak"},
                  {"method", "Levenberg-Marquardt least squares (Eigen)"},
                  {"mu_0", f.mu_0},
                  {"mu_ss", f.mu_ss},
                  {"s0", f.s0},
                  {"s_peak", f.s_peak},
                  {"rms_residual", f.rms_residual},
                  {"points", f.points}};
  } else {
    doc["fit"] = nullptr;
  }
  doc["table"] = {{"distance", law.table.distance()}, {"mu", law.table.mu()}};
  return doc.dump(2) + "\n";
}

FrictionLaw law_from_json_text(const std::string &text, const std::string &source_name) {
  using json = nlohmann::json;
  const json doc = parse_json_input(text, source_name);
  if (!doc.is_object()) throw InputFormatError(source_name + ": the law must be a JSON object { ... }");
  // Every value by its JSON pointer; errors name the key as a dotted path.
  const auto fail = [&](const std::string &pointer, const std::string &problem) {
    std::string key = pointer.substr(1);
    std::replace(key.begin(), key.end(), '/', '.');
    return InputFormatError(source_name + ": key '" + key + "': " + problem);
  };
  const auto node = [&](const std::string &pointer) -> const json & {
    const json::json_pointer where(pointer);
    if (!doc.contains(where)) throw fail(pointer, "missing (required)");
    return doc.at(where);
  };
  const auto text_at = [&](const std::string &pointer) {
    const json &v = node(pointer);
    if (!v.is_string()) throw fail(pointer, std::string("expected a string, got ") + v.type_name());
    return v.get<std::string>();
  };
  const auto number_at = [&](const std::string &pointer) {
    const json &v = node(pointer);
    if (!v.is_number()) throw fail(pointer, std::string("expected a number, got ") + v.type_name());
    const double x = v.get<double>();
    if (!std::isfinite(x)) throw fail(pointer, "must be finite");
    return x;
  };
  const auto numbers_at = [&](const std::string &pointer) {
    const json &v = node(pointer);
    if (!v.is_array()) throw fail(pointer, std::string("expected an array of numbers, got ") + v.type_name());
    std::vector<double> out;
    for (const auto &element : v) {
      if (!element.is_number() || !std::isfinite(element.get<double>()))
        throw fail(pointer, "element " + std::to_string(out.size()) + ": expected a finite number");
      out.push_back(element.get<double>());
    }
    return out;
  };
  if (text_at("/format") != "runin-friction-law")
    throw fail("/format", "not a runin-friction-law file (expected \"runin-friction-law\")");
  if (!node("/version").is_number_integer() || node("/version").get<long>() != 1)
    throw fail("/version", "expected the integer 1, got " + node("/version").dump());
  try {
    FrictionLaw law{text_at("/source/file"), text_at("/source/distance_column"), text_at("/source/mu_column"),
                    text_at("/units/distance"), number_at("/units/distance_in_m"),
                    TabulatedLaw(numbers_at("/table/distance"), numbers_at("/table/mu")), std::nullopt};
    if (!(law.distance_unit_in_m > 0.0)) throw fail("/units/distance_in_m", "must be positive");
    if (!node("/fit").is_null()) {
      RunInFit f;
      f.mu_0 = number_at("/fit/mu_0");
      f.mu_ss = number_at("/fit/mu_ss");
      f.s0 = number_at("/fit/s0");
      f.s_peak = number_at("/fit/s_peak");
      f.rms_residual = number_at("/fit/rms_residual");
      const json &points = node("/fit/points");
      if (!points.is_number_unsigned()) throw fail("/fit/points", "expected a non-negative integer");
      f.points = points.get<std::size_t>();
      if (!(f.s0 > 0.0)) throw fail("/fit/s0", "must be positive");
      law.fit = f;
    }
    return law;
  } catch (const std::invalid_argument &e) {  // the table's own checks
    throw InputFormatError(source_name + ": key 'table': " + e.what());
  }
}

FrictionLaw read_law_file(const std::string &path) {
  std::ifstream file = open_input(path, "law file");
  std::ostringstream text;
  text << file.rdbuf();
  return law_from_json_text(text.str(), path);
}

}  // namespace runin::coupling
