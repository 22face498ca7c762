// Boundary-element kernel of a frictionless line contact on an elastic half-plane (plane strain),
// shared by the journal-bearing bore arc (conformal_contact.h) and the piston-ring face
// (ring_liner_wear.h). n piecewise-constant pressure panels of length h on a line, collocation
// at the panel centres; the surface displacement of the combined surfaces is (Johnson, Contact
// Mechanics, eq. 2.25c, per unit axial length)
//   u_i = sum_j K_ij p_j,   K_ij = -2 / (pi E*) * integral over panel j of ln(|x_i - x| / L) dx,
// with E* the combined plane-strain modulus (1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2) and L a
// reference length that fixes the half-plane's undetermined rigid-body constant (it shifts the
// approach only). K is symmetric Toeplitz.
//
// The contact problem: find p >= 0 and the approach d with
//   g_i = g0_i - d c_i + (K p)_i >= 0,   p_i g_i = 0,   h sum_i c_i p_i = load per length,
// c_i the projection of the approach on node i (cos(theta_i) on the bore arc, 1 on a flat face).
// Active set on the pressures, the load balance as the extra equation (p = u + d v on the set).
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Dense>

namespace runin::continuum {

// First row of the Toeplitz compliance K (m/Pa): row[m] = K_{i,i+m}.
std::vector<double> half_plane_influence_row(int panels, double panel_length, double contact_modulus,
                                             double reference_length);
Eigen::MatrixXd symmetric_toeplitz(const std::vector<double> &row);

// Lower bound on the smallest eigenvalue of a symmetric positive definite K (inverse power
// iteration from the alternating mode, Rayleigh quotient minus the residual norm). <= 0 if K is
// not positive definite.
double smallest_eigenvalue_bound(const Eigen::MatrixXd &compliance);

// Factorisations of contiguous diagonal blocks of a Toeplitz K, by block size (a block of m
// consecutive panels is the same matrix wherever it starts): the flat ring face's active set is
// contiguous, so each solve after the first of a given width is two triangular solves.
class ToeplitzBlockCache {
 public:
  const Eigen::LLT<Eigen::MatrixXd> *get(const Eigen::MatrixXd &compliance, int size);
  // K_m^-1 (1, ..., 1) of the block of that size (after get() succeeded for it).
  const Eigen::VectorXd &ones_solution(int size);

 private:
  std::vector<std::unique_ptr<Eigen::LLT<Eigen::MatrixXd>>> llt_;
  std::vector<Eigen::VectorXd> ones_;
};

struct LineContactResult {
  bool converged = false;
  Eigen::VectorXd pressure;  // Pa, per panel
  double approach = 0.0;     // m, d
  int iterations = 0;        // active-set passes
};

// `active` (size n, 1 = loaded) is the initial guess and is left at the final set; all zero
// starts from the node with the smallest g0_i / c_i. `tolerance` (m) is the penetration allowed
// before an unloaded node is added. `cache` may be given when `compliance` is Toeplitz.
LineContactResult solve_line_contact(const Eigen::MatrixXd &compliance, const Eigen::VectorXd &rigid_gap,
                                     const Eigen::VectorXd &direction, double panel_length, double load_per_length,
                                     double tolerance, std::vector<char> &active,
                                     ToeplitzBlockCache *cache = nullptr);

}  // namespace runin::continuum
