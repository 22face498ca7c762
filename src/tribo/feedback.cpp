#include "tribo/feedback.h"

#include <cmath>
#include <sstream>

namespace runin::tribo {
namespace {
std::string format(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}
bool close(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }
}  // namespace

const char *to_string(FeedbackKind kind) { return kind == FeedbackKind::dry ? "dry" : "lubricated"; }

FeedbackModel::FeedbackModel(FeedbackCoefficients c, FeedbackKind kind) : c_(c), kind_(kind) {
  const std::pair<const char *, double> all[] = {{"C1", c.C1}, {"C2", c.C2}, {"K1", c.K1},
                                                 {"K2", c.K2}, {"A", c.A},   {"B", c.B}};
  for (const auto &[name, value] : all) {
    if (!std::isfinite(value)) throw InvalidCoefficient(std::string("feedback coefficient ") + name + " must be finite");
    if (value < 0.0)
      throw InvalidCoefficient(std::string("feedback coefficient ") + name + " must be >= 0, got " + format(value));
  }
  if (!(c.C1 > 0.0)) throw InvalidCoefficient("feedback coefficient C1 must be > 0 (no friction minimum otherwise)");
  if (!(c.K1 > 0.0)) throw InvalidCoefficient("feedback coefficient K1 must be > 0 (K1 A > 0: no stable R* otherwise)");
  if (!(c.A > 0.0)) throw InvalidCoefficient("feedback coefficient A must be > 0 (K1 A > 0: no stable R* otherwise)");
  if (!(c.K2 > 0.0)) throw InvalidCoefficient("feedback coefficient K2 must be > 0 (B K2 > 0: R* = 0 otherwise)");
  if (!(c.B > 0.0)) throw InvalidCoefficient("feedback coefficient B must be > 0 (B K2 > 0: R* = 0 otherwise)");
  if (!std::isfinite(stationary_roughness()) || !(stationary_roughness() > 0.0) ||
      !std::isfinite(min_wear_roughness()) || !std::isfinite(min_friction_roughness()))
    throw InvalidCoefficient("feedback coefficients A, B, K1, K2, C1, C2: ratios overflow or underflow");
}

std::string FeedbackModel::thesis_name(const std::string &generic) const {
  const bool dry = kind_ == FeedbackKind::dry;
  if (generic == "C1") return dry ? "C_def" : "C_vis";
  if (generic == "C2") return dry ? "C_adh" : "C_cap";
  if (generic == "K1") return dry ? "K_def" : "K_vis";
  if (generic == "K2") return dry ? "K_adh" : "K_cap";
  return generic;
}

double FeedbackModel::stationary_roughness() const { return std::sqrt(c_.B * c_.K2 / (c_.A * c_.K1)); }
double FeedbackModel::min_wear_roughness() const { return std::sqrt(c_.K2 / c_.K1); }
double FeedbackModel::min_friction_roughness() const { return std::sqrt(c_.C2 / c_.C1); }
double FeedbackModel::min_mu() const { return 2.0 * std::sqrt(c_.C1 * c_.C2); }
double FeedbackModel::min_k() const { return 2.0 * std::sqrt(c_.K1 * c_.K2); }

bool FeedbackModel::stationary_minimises_wear() const { return close(c_.A, c_.B); }
bool FeedbackModel::stationary_minimises_friction() const {
  return close(stationary_roughness(), min_friction_roughness());
}

double FeedbackModel::exact_roughness(double R0, double t) const {
  const double rs2 = c_.B * c_.K2 / (c_.A * c_.K1);
  return std::sqrt(rs2 + (R0 * R0 - rs2) * std::exp(-relaxation_rate() * t));
}

double FeedbackModel::exact_settling_time(double R0, double tolerance) const {
  const double rs = stationary_roughness();
  if (std::abs(R0 - rs) <= tolerance * rs) return 0.0;
  // R^2 - R*^2 decays monotonically; the band edge on R0's side is R*(1 +- tol).
  const double edge = R0 > rs ? rs * (1.0 + tolerance) : rs * (1.0 - tolerance);
  return std::log((R0 * R0 - rs * rs) / (edge * edge - rs * rs)) / relaxation_rate();
}

}  // namespace runin::tribo
