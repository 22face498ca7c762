#include "continuum/conformal_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
// Antiderivative of ln|t|, continuous at 0.
double log_integral(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }
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

  // Toeplitz: K_ij depends on |i - j| only.
  const double r = g_.shaft_radius, h = panel_length();
  const double scale = -2.0 / (M_PI * g_.contact_modulus());
  std::vector<double> row(n);
  for (int m = 0; m < n; ++m) {
    const double d = m * h / r;  // in units of R
    row[m] = scale * r * (log_integral(d + 0.5 * h / r) - log_integral(d - 0.5 * h / r));
  }
  compliance_.resize(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) compliance_(i, j) = row[std::abs(i - j)];

  // lambda_min(K) by inverse power iteration, started on the alternating (stiffest) mode.
  Eigen::LLT<Eigen::MatrixXd> llt(compliance_);
  double lambda_min = 0.0;
  if (llt.info() == Eigen::Success) {
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v[i] = (i % 2 ? -1.0 : 1.0);
    v.normalize();
    for (int it = 0; it < 60; ++it) {
      Eigen::VectorXd next = llt.solve(v);
      v = next.normalized();
    }
    // Rayleigh quotient minus the residual norm: a lower bound on the nearest eigenvalue, so
    // k_c errs on the stiff (safe) side.
    const Eigen::VectorXd kv = compliance_ * v;
    const double rayleigh = v.dot(kv);
    lambda_min = rayleigh - (kv - rayleigh * v).norm();
  } else {
    lambda_min = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(compliance_, Eigen::EigenvaluesOnly).eigenvalues()[0];
  }
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
  int count = 0;
  if (warm_start && static_cast<int>(warm_start->size()) == n)
    for (int i = 0; i < n; ++i) count += active[i] = (*warm_start)[i] > 0.0;
  if (count == 0) {  // first touch of the rigid shaft
    int first = 0;
    for (int i = 1; i < n; ++i)
      if (rigid_gap[i] / cosine[i] < rigid_gap[first] / cosine[first]) first = i;
    active[first] = 1;
  }

  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  double e = 0.0;
  const int max_iterations = 4 * n + 20;
  sol.status = ConformalStatus::NotConverged;
  for (int it = 1; it <= max_iterations; ++it) {
    sol.iterations = it;
    std::vector<int> index;
    for (int i = 0; i < n; ++i)
      if (active[i]) index.push_back(i);
    const int m = static_cast<int>(index.size());
    Eigen::MatrixXd kaa(m, m);
    Eigen::VectorXd b(m), c(m);
    for (int a = 0; a < m; ++a) {
      for (int bb = 0; bb < m; ++bb) kaa(a, bb) = compliance_(index[a], index[bb]);
      b[a] = -rigid_gap[index[a]];
      c[a] = cosine[index[a]];
    }
    // K p = b + e c with the load balance h c.p = load: p = u + e v.
    Eigen::VectorXd u, v;
    Eigen::LLT<Eigen::MatrixXd> llt(kaa);
    if (llt.info() == Eigen::Success) {
      u = llt.solve(b);
      v = llt.solve(c);
    } else {
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(kaa);
      u = lu.solve(b);
      v = lu.solve(c);
    }
    e = (load_per_length / h - c.dot(u)) / c.dot(v);
    const Eigen::VectorXd pa = u + e * v;
    p.setZero();
    bool removed = false;
    for (int a = 0; a < m; ++a) {
      if (pa[a] < 0.0 && m > 1) {
        active[index[a]] = 0;
        removed = true;
      } else {
        p[index[a]] = std::max(pa[a], 0.0);
      }
    }
    if (removed) continue;
    const Eigen::VectorXd gap = rigid_gap - e * cosine + compliance_ * p;
    bool added = false;
    for (int i = 0; i < n; ++i)
      if (!active[i] && gap[i] < -tolerance) {
        active[i] = 1;
        added = true;
      }
    if (!added) {
      sol.status = ConformalStatus::Converged;
      break;
    }
  }

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
