#include "continuum/half_plane_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace runin::continuum {
namespace {
// Antiderivative of ln|t|, continuous at 0.
double log_integral(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }
}  // namespace

std::vector<double> half_plane_influence_row(int panels, double panel_length, double contact_modulus,
                                             double reference_length) {
  if (panels < 1 || !(panel_length > 0.0) || !(contact_modulus > 0.0) || !(reference_length > 0.0))
    throw std::invalid_argument("half_plane_influence_row: panels, panel length, modulus and reference length must be positive");
  const double r = reference_length, h = panel_length;
  const double scale = -2.0 / (M_PI * contact_modulus);
  std::vector<double> row(panels);
  for (int m = 0; m < panels; ++m) {
    const double d = m * h / r;  // in units of the reference length
    row[m] = scale * r * (log_integral(d + 0.5 * h / r) - log_integral(d - 0.5 * h / r));
  }
  return row;
}

Eigen::MatrixXd symmetric_toeplitz(const std::vector<double> &row) {
  const int n = static_cast<int>(row.size());
  Eigen::MatrixXd k(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) k(i, j) = row[std::abs(i - j)];
  return k;
}

double smallest_eigenvalue_bound(const Eigen::MatrixXd &compliance) {
  const int n = static_cast<int>(compliance.rows());
  Eigen::LLT<Eigen::MatrixXd> llt(compliance);
  if (llt.info() != Eigen::Success)
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(compliance, Eigen::EigenvaluesOnly).eigenvalues()[0];
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = (i % 2 ? -1.0 : 1.0);
  v.normalize();
  for (int it = 0; it < 60; ++it) {
    Eigen::VectorXd next = llt.solve(v);
    v = next.normalized();
  }
  // Rayleigh quotient minus the residual norm: a lower bound on the nearest eigenvalue, so the
  // stiffness 1 / lambda errs on the stiff (safe) side.
  const Eigen::VectorXd kv = compliance * v;
  const double rayleigh = v.dot(kv);
  return rayleigh - (kv - rayleigh * v).norm();
}

const Eigen::LLT<Eigen::MatrixXd> *ToeplitzBlockCache::get(const Eigen::MatrixXd &compliance, int size) {
  if (size < 1 || size > compliance.rows()) return nullptr;
  if (static_cast<int>(llt_.size()) < size) llt_.resize(size);
  auto &slot = llt_[size - 1];
  if (!slot) {
    slot = std::make_unique<Eigen::LLT<Eigen::MatrixXd>>(compliance.topLeftCorner(size, size));
    if (slot->info() != Eigen::Success) {
      slot.reset();
      return nullptr;
    }
  }
  return slot.get();
}

const Eigen::VectorXd &ToeplitzBlockCache::ones_solution(int size) {
  if (static_cast<int>(ones_.size()) < size) ones_.resize(size);
  auto &v = ones_[size - 1];
  if (v.size() != size) v = llt_[size - 1]->solve(Eigen::VectorXd::Ones(size));
  return v;
}

LineContactResult solve_line_contact(const Eigen::MatrixXd &compliance, const Eigen::VectorXd &rigid_gap,
                                     const Eigen::VectorXd &direction, double panel_length, double load_per_length,
                                     double tolerance, std::vector<char> &active, ToeplitzBlockCache *cache) {
  const int n = static_cast<int>(compliance.rows());
  const double h = panel_length;
  LineContactResult result;
  result.pressure = Eigen::VectorXd::Zero(n);
  active.resize(n, 0);
  int count = 0;
  for (char a : active) count += a != 0;
  if (count == 0) {  // first touch of the rigid body
    int first = 0;
    for (int i = 1; i < n; ++i)
      if (rigid_gap[i] / direction[i] < rigid_gap[first] / direction[first]) first = i;
    active[first] = 1;
  }

  Eigen::VectorXd &p = result.pressure;
  double e = 0.0;
  const int max_iterations = 4 * n + 20;
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    std::vector<int> index;
    for (int i = 0; i < n; ++i)
      if (active[i]) index.push_back(i);
    const int m = static_cast<int>(index.size());
    Eigen::VectorXd b(m), c(m);
    for (int a = 0; a < m; ++a) {
      b[a] = -rigid_gap[index[a]];
      c[a] = direction[index[a]];
    }
    // K p = b + e c with the load balance h c.p = load: p = u + e v.
    Eigen::VectorXd u, v;
    const bool contiguous = index.back() - index.front() + 1 == m;
    const Eigen::LLT<Eigen::MatrixXd> *block = cache && contiguous ? cache->get(compliance, m) : nullptr;
    if (block) {
      u = block->solve(b);
      if ((c.array() == 1.0).all())
        v = cache->ones_solution(m);  // the flat ring face: the same for every block of this size
      else
        v = block->solve(c);
    } else {
      Eigen::MatrixXd kaa(m, m);
      for (int a = 0; a < m; ++a)
        for (int bb = 0; bb < m; ++bb) kaa(a, bb) = compliance(index[a], index[bb]);
      Eigen::LLT<Eigen::MatrixXd> llt(kaa);
      if (llt.info() == Eigen::Success) {
        u = llt.solve(b);
        v = llt.solve(c);
      } else {
        Eigen::PartialPivLU<Eigen::MatrixXd> lu(kaa);
        u = lu.solve(b);
        v = lu.solve(c);
      }
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
    bool added = false;
    if (block) {
      // Gaps of the unloaded panels only, from the loaded block (K symmetric: column i is row i).
      const int first = index.front();
      for (int i = 0; i < n; ++i) {
        if (active[i]) continue;
        const double gap =
            rigid_gap[i] - e * direction[i] + compliance.col(i).segment(first, m).dot(p.segment(first, m));
        if (gap < -tolerance) {
          active[i] = 1;
          added = true;
        }
      }
    } else {  // the full product keeps the bore arc's round-off as it was
      const Eigen::VectorXd gap = rigid_gap - e * direction + compliance * p;
      for (int i = 0; i < n; ++i)
        if (!active[i] && gap[i] < -tolerance) {
          active[i] = 1;
          added = true;
        }
    }
    if (!added) {
      result.converged = true;
      break;
    }
  }
  result.approach = e;
  return result;
}

}  // namespace runin::continuum
