// Dry conformal contact of a shaft (radius R) in a bore (radius R + c), plane strain per unit
// axial length, solved on a discretised bore arc theta in [-theta_max, theta_max] around the
// load line (theta = 0). Unknowns: nodal pressures p_i >= 0 and the shaft approach e along
// the load line. The gap at node i is
//   g_i = c + w_i - e cos(theta_i) + sum_j K_ij p_j,
// with w_i the bore wear depth and K the combined-surface compliance of piecewise-constant
// pressure panels on an elastic half-plane (Steuermann / Johnson eq. 2.25c):
//   K_ij = -2 / (pi E*) * integral over panel j of ln(|x_i - x| / R) dx,   x = R theta.
// The ln reference length R fixes the rigid-body constant of the half-plane solution; it
// shifts e only, not the pressure, while cos(theta) ~ 1 over the contact (see
// doc/journal_bearing.md for the range of validity). Active set on the pressures, with the
// load balance sum_i p_i cos(theta_i) R dtheta = load per length as the extra equation.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "continuum/half_plane_contact.h"

namespace runin::continuum {

struct BoreGeometry {
  double shaft_radius = 0.0;     // m, R
  double clearance = 0.0;        // m, radial clearance c of the unworn bore
  double axial_width = 0.0;      // m, bearing length L
  double youngs_modulus = 0.0;   // Pa, shaft and bore (same material)
  double poisson_ratio = 0.0;
  double arc_half_angle = 0.0;   // rad, theta_max of the discretised arc (< pi/2)
  int nodes = 0;                 // panels on the arc

  void validate() const;  // throws std::invalid_argument naming the field
  // Plane-strain combined modulus E* = E / (2 (1 - nu^2)) for two equal bodies.
  double contact_modulus() const;
};

enum class ConformalStatus { Converged, NoContact, ArcTooShort, NotConverged };
const char *to_string(ConformalStatus status);

struct ConformalSolution {
  ConformalStatus status = ConformalStatus::NotConverged;
  std::vector<double> pressure;   // Pa, per node
  double approach = 0.0;          // m, e
  int iterations = 0;             // active-set passes
  int active_nodes = 0;
  double contact_half_angle = 0.0;  // rad, half of the arc spanned by the loaded panels
  double peak_pressure = 0.0, mean_pressure = 0.0;  // Pa; mean over the loaded panels
  double normal_force_per_length = 0.0;  // N/m, sum p R dtheta (>= the load: cos < 1)

  bool ok() const { return status == ConformalStatus::Converged; }
};

class ConformalContact {
 public:
  explicit ConformalContact(BoreGeometry geometry);

  const BoreGeometry &geometry() const { return g_; }
  int nodes() const { return g_.nodes; }
  double node_angle(int i) const { return theta_[i]; }
  double panel_angle() const { return dtheta_; }
  double panel_length() const { return g_.shaft_radius * dtheta_; }
  const Eigen::MatrixXd &compliance() const { return compliance_; }

  // Pressure for a load per unit length (N/m) on a bore worn by `wear` (m per node, empty =
  // unworn). `warm_start` may hold the previous solution's pressures (an active-set guess).
  ConformalSolution solve(double load_per_length, const std::vector<double> &wear = {},
                        const std::vector<double> *warm_start = nullptr) const;

  // Pressure drop per unit uniform-mode wear depth of the stiffest panel mode, k_c = 1 / lambda_min(K)
  // (Pa/m): by interlacing it bounds the stiffness of every active set, so ArchardWear::stable_slip_step(k_c)
  // is a safe explicit wear step.
  double contact_stiffness_per_area() const { return stiffness_per_area_; }

 private:
  BoreGeometry g_;
  double dtheta_ = 0.0;
  std::vector<double> theta_;
  Eigen::MatrixXd compliance_;  // K, m/Pa
  double stiffness_per_area_ = 0.0;
  // Factorisations of K's leading blocks (K is Toeplitz, so any contiguous active block is one of them); shared
  // by copies, which have the same K
  std::shared_ptr<ToeplitzBlockCache> blocks_ = std::make_shared<ToeplitzBlockCache>();
};

// Hertz line contact of a cylinder (R1) in a concave cylinder (R2 > R1), load w per length:
// effective radius R1 R2 / (R2 - R1), half-width a = sqrt(4 w R_eff / (pi E*)), p0 = 2 w / (pi a).
double hertz_effective_radius(double shaft_radius, double bore_radius);
double hertz_half_width(double load_per_length, double effective_radius, double contact_modulus);
double hertz_peak_pressure(double load_per_length, double half_width);

}  // namespace runin::continuum
