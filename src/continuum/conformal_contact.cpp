#include "continuum/conformal_contact.h"

#include "continuum/half_plane_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
}  // namespace

void BoreGeometry::validate() const {
  require(std::isfinite(shaft_radius) && shaft_radius > 0.0, "shaft_radius must be positive");
  require(std::isfinite(clearance) && clearance > 0.0, "clearance must be positive");
  require(std::isfinite(axial_width) && axial_width > 0.0, "axial_width must be positive");
  require(std::isfinite(youngs_modulus) && youngs_modulus > 0.0, "youngs_modulus must be positive");
  require(std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio < 0.5,
          "poisson_ratio must be in (-1, 0.5)");
  require(std::isfinite(arc_half_angle) && arc_half_angle > 0.0 && arc_half_angle < 0.5 * M_PI,
          "arc_half_angle must be in (0, pi/2)");
  require(nodes >= 3 && nodes <= 8192, "nodes must be in [3, 8192]");
}

double BoreGeometry::contact_modulus() const {
  return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

const char *to_string(ConformalStatus status) {
  switch (status) {
    case ConformalStatus::Converged: return "converged";
    case ConformalStatus::NoContact: return "no contact (load <= 0)";
    case ConformalStatus::ArcTooShort: return "contact reaches the end of the discretised arc";
    case ConformalStatus::NotConverged: return "active set did not converge";
  }
  return "unknown";
}

ConformalContact::ConformalContact(BoreGeometry geometry) : g_(geometry) {
  g_.validate();
  const int n = g_.nodes;
  dtheta_ = 2.0 * g_.arc_half_angle / n;
  theta_.resize(n);
  for (int i = 0; i < n; ++i) theta_[i] = -g_.arc_half_angle + (i + 0.5) * dtheta_;

  // Toeplitz: K_ij depends on |i - j| only (the half-plane kernel, half_plane_contact.h).
  compliance_ = symmetric_toeplitz(half_plane_influence_row(n, panel_length(), g_.contact_modulus(), g_.shaft_radius));
  const double lambda_min = smallest_eigenvalue_bound(compliance_);
  require(lambda_min > 0.0, "arc_half_angle: compliance matrix not positive definite (arc too long for R)");
  stiffness_per_area_ = 1.0 / lambda_min;
}

ConformalSolution ConformalContact::solve(double load_per_length, const std::vector<double> &wear,
                                        const std::vector<double> *warm_start) const {
  const int n = g_.nodes;
  require(wear.empty() || static_cast<int>(wear.size()) == n, "wear: one depth per node expected");
  require(std::isfinite(load_per_length), "load_per_length must be finite");
  ConformalSolution sol;
  sol.pressure.assign(n, 0.0);
  if (load_per_length <= 0.0) {
    sol.status = ConformalStatus::NoContact;
    return sol;
  }
  const double h = panel_length();
  Eigen::VectorXd rigid_gap(n), cosine(n);  // c + w_i, cos(theta_i)
  double max_wear = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w = wear.empty() ? 0.0 : wear[i];
    require(std::isfinite(w), "wear: depth must be finite");
    rigid_gap[i] = g_.clearance + w;
    cosine[i] = std::cos(theta_[i]);
    max_wear = std::max(max_wear, std::abs(w));
  }
  const double tolerance = 1e-10 * (g_.clearance + max_wear);

  std::vector<char> active(n, 0);
  if (warm_start && static_cast<int>(warm_start->size()) == n)
    for (int i = 0; i < n; ++i) active[i] = (*warm_start)[i] > 0.0;
  const LineContactResult r =
      solve_line_contact(compliance_, rigid_gap, cosine, h, load_per_length, tolerance, active, blocks_.get());
  sol.iterations = r.iterations;
  sol.status = r.converged ? ConformalStatus::Converged : ConformalStatus::NotConverged;
  const Eigen::VectorXd &p = r.pressure;
  const double e = r.approach;
  sol.approach = e;
  int first = n, last = -1;
  double force = 0.0, sum = 0.0;
  for (int i = 0; i < n; ++i) {
    sol.pressure[i] = p[i];
    if (p[i] > 0.0) {
      first = std::min(first, i);
      last = std::max(last, i);
      ++sol.active_nodes;
      sum += p[i];
      sol.peak_pressure = std::max(sol.peak_pressure, p[i]);
    }
    force += p[i] * h;
  }
  sol.normal_force_per_length = force;
  if (sol.active_nodes > 0) {
    sol.mean_pressure = sum / sol.active_nodes;
    sol.contact_half_angle = 0.5 * (last - first + 1) * dtheta_;
  }
  if (sol.ok() && (p[0] > 0.0 || p[n - 1] > 0.0)) sol.status = ConformalStatus::ArcTooShort;
  return sol;
}

double hertz_effective_radius(double shaft_radius, double bore_radius) {
  return shaft_radius * bore_radius / (bore_radius - shaft_radius);
}

double hertz_half_width(double load_per_length, double effective_radius, double contact_modulus) {
  return std::sqrt(4.0 * load_per_length * effective_radius / (M_PI * contact_modulus));
}

double hertz_peak_pressure(double load_per_length, double half_width) {
  return 2.0 * load_per_length / (M_PI * half_width);
}

}  // namespace runin::continuum
