// Subsurface stress below a contact: the full stress tensor at points of an elastic half-space loaded by the
// contact's normal pressure p and tangential (friction) shear q, and the von Mises / Tresca equivalent
// stresses that decide whether the body yields. Pure functions, no I/O; SI units or any consistent set.
// Equations, references, ranges of validity and the verification numbers: doc/subsurface_stress.md.
//
// Conventions (all tiers): tension positive; x is the sliding direction in the surface, z >= 0 the depth into
// the body; the body occupies z >= 0. p > 0 presses on the body; q is the tangential traction ON THE BODY,
// positive in +x (a slider moving in +x over the body drags it in +x: q = +mu p). With these, the surface
// (z = 0) stresses are sigma_zz = -p and sigma_xz = -q (equilibrium of the surface element).
//
// Closed forms (tier 1):
//   hamilton_stress:   sliding Hertzian sphere, p = p0 sqrt(1 - r^2/a^2), q = mu p. G.M. Hamilton (1983),
//                      "Explicit equations for the stresses beneath a sliding spherical contact", Proc. IMechE
//                      197C:53-59; every component at any (x, y, z).
//   hertz_axis_stress: the frictionless sphere on its axis, Johnson, Contact Mechanics (1985), eq. 3.45
//                      (an independent check of the mu = 0 Hamilton normal part).
//   mcewen_stress:     sliding Hertzian line contact (plane strain), p = p0 sqrt(1 - x^2/b^2), q = mu p;
//                      McEwen (1949), Phil. Mag. 40:454, as in Johnson §4.2 (normal) and §7.1 (tangential).
// Influence-function tier (tier 2), for any traction distribution (worn profiles):
//   line_traction_*:   2-D plane strain. Tractions piecewise constant on strips; each strip integrated
//                      analytically from the Flamant line-load solutions (Johnson eqs. 2.15, 2.19, §2.6).
//   patch_traction_*:  3-D. Tractions piecewise constant on the rectangles of a regular grid; each rectangle
//                      integrated analytically from the Boussinesq and Cerruti point-load solutions (closed-form
//                      corner functions, derived in doc/subsurface_stress.md). axisymmetric_patches() puts
//                      the ring pressure of an axisymmetric contact (the pin) on such a grid.
// The piecewise-constant traction gives a log-singular surface stress exactly on a strip/patch edge where the
// shear jumps: keep surface field points off the edges (the section helpers place them at patch centres).
#pragma once

#include "tribo/contact.h"    // InvalidCoefficient

#include <array>
#include <functional>
#include <vector>

namespace runin::tribo {

// Cauchy stress at one point [Pa, or units of the tractions].
struct StressTensor {
  double xx = 0.0, yy = 0.0, zz = 0.0, yz = 0.0, xz = 0.0, xy = 0.0;

  StressTensor &operator+=(const StressTensor &o)
  {
    xx += o.xx, yy += o.yy, zz += o.zz, yz += o.yz, xz += o.xz, xy += o.xy;
    return *this;
  }
  StressTensor scaled(double f) const { return {f * xx, f * yy, f * zz, f * yz, f * xz, f * xy}; }
  double von_mises() const;                   // sqrt(3 J2)
  std::array<double, 3> principal() const;    // sigma_1 >= sigma_2 >= sigma_3 (Eigen self-adjoint solver)
  double tresca() const;                      // sigma_1 - sigma_3 (twice the largest shear stress)
};

// ---------------------------------------------------------------- tier 1: closed forms

// Sliding Hertzian sphere on the body: p = p0 sqrt(1 - r^2/a^2) on r < a, q = mu p in +x.
struct SlidingHertzSphere {
  double peak_pressure = 0.0;           // p0 >= 0
  double contact_radius = 0.0;          // a > 0
  double poisson_ratio = 0.3;           // nu of the body, -1 < nu <= 0.5
  double friction_coefficient = 0.0;    // mu, any finite sign (sign = direction of q)

  void validate() const;    // throws InvalidCoefficient naming the field
};

// Hamilton (1983) at (x, y, z), z >= 0. Within 1e-2 a of the axis the off-axis formulas lose digits (1/r^4
// terms); there the value is interpolated linearly in r between the axis limit and r = 1e-2 a (error O(1e-4)).
// Throws InvalidCoefficient for an invalid contact or a non-finite / negative-depth point.
StressTensor hamilton_stress(const SlidingHertzSphere &contact, double x, double y, double z);

// Johnson eq. 3.45: the frictionless Hertz sphere on its axis (r = 0), depth z >= 0.
struct AxisStress {
  double radial = 0.0;    // sigma_r = sigma_theta
  double axial = 0.0;     // sigma_z
};
AxisStress hertz_axis_stress(double peak_pressure, double contact_radius, double poisson_ratio, double z);

// Sliding Hertzian line contact (2-D, plane strain: sigma_yy = nu (sigma_xx + sigma_zz)), half-width b.
struct SlidingHertzLine {
  double peak_pressure = 0.0;           // p0 >= 0
  double half_width = 0.0;              // b > 0
  double poisson_ratio = 0.3;
  double friction_coefficient = 0.0;

  void validate() const;
};
StressTensor mcewen_stress(const SlidingHertzLine &contact, double x, double z);

// ---------------------------------------------------------------- tier 2: influence functions

// 2-D tractions, constant on strip j = [edges[j], edges[j+1]] (edges strictly increasing, size n + 1).
struct LineTraction {
  std::vector<double> edges;
  std::vector<double> pressure;    // p_j, size n
  std::vector<double> shear;       // q_j (on the body, +x), size n, or empty for none

  void validate() const;           // throws InvalidCoefficient
  // Strips of width h centred on nodes x_j (a contact solver's nodal output), edges half-way between.
  static LineTraction from_nodes(const std::vector<double> &x, const std::vector<double> &pressure,
                                 const std::vector<double> &shear = {});
};
StressTensor line_traction_stress(const LineTraction &traction, double poisson_ratio, double x, double z);

// 3-D tractions on a regular grid of nx x ny rectangles [x0 + i dx, x0 + (i+1) dx] x [y0 + j dy, ...],
// values at i + nx j. Shear is in x only (the sliding direction).
struct PatchTraction {
  double x0 = 0.0, y0 = 0.0, dx = 0.0, dy = 0.0;
  int nx = 0, ny = 0;
  std::vector<double> pressure;    // nx * ny
  std::vector<double> shear_x;     // nx * ny, or empty for none

  void validate() const;
};
StressTensor patch_traction_stress(const PatchTraction &traction, double poisson_ratio, double x, double y, double z);

// An axisymmetric pressure p(r) (zero beyond `radius`) with q = mu p, on n x n patches covering
// [-half_size, half_size]^2 (half_size >= radius); each patch value is the average of p over 4 x 4 points.
PatchTraction axisymmetric_patches(const std::function<double(double)> &pressure_of_radius, double radius,
                                   double friction_coefficient, double half_size, int n);
// The same for a ring solution: pressure[i] on ring [i h, (i+1) h] (continuum::AxisymmetricContact).
PatchTraction axisymmetric_patches(const std::vector<double> &ring_pressure, double ring_width,
                                   double friction_coefficient, double half_size, int n);

// ---------------------------------------------------------------- fields on a section

// Stress on the grid x[i], z[k] of one section (y = const for 3-D), point (i, k) at i + x.size() k.
struct StressPeak {
  double von_mises = 0.0, x = 0.0, z = 0.0;
};
struct StressField {
  std::vector<double> x, z;
  std::vector<StressTensor> stress;

  std::vector<double> von_mises() const;
  std::vector<double> tresca() const;
  StressPeak peak_von_mises() const;             // largest on the grid
  StressPeak peak_von_mises_on_axis() const;     // largest at the x closest to 0 (depth profile)
};

// Uniform grid of n points on [lo, hi] (n >= 2), or the n cell centres of [lo, hi] (n >= 1).
std::vector<double> uniform_points(double lo, double hi, int n);
std::vector<double> cell_centres(double lo, double hi, int n);

StressField hamilton_field(const SlidingHertzSphere &contact, const std::vector<double> &x,
                           const std::vector<double> &z, double y = 0.0);
StressField mcewen_field(const SlidingHertzLine &contact, const std::vector<double> &x, const std::vector<double> &z);

// The largest von Mises stress of the closed form on the section, not only at the grid's points: with friction
// the maximum can be a cusp on the surface at the trailing edge of the contact (x = -a for mu > 0, z = 0), which
// a grid misses by several per cent. Candidates: the grid's largest point, its largest surface point and both
// contact edges on the surface (x = +-a, z = 0, evaluated exactly); each is refined by a compass search in
// (x, z) (z >= 0, x within the grid) down to 1e-9 a. `grid` is the closed form's field on that section
// (hamilton_field / mcewen_field with this contact); the result is >= grid.peak_von_mises().
StressPeak hamilton_peak_von_mises(const SlidingHertzSphere &contact, const StressField &grid, double y = 0.0);
StressPeak mcewen_peak_von_mises(const SlidingHertzLine &contact, const StressField &grid);
// Tier 2 on a section. line_traction_field: one pass per strip edge (O(edges x points)).
StressField line_traction_field(const LineTraction &traction, double poisson_ratio, const std::vector<double> &x,
                                const std::vector<double> &z);
// patch_traction_field: y = const section. When x is the set of patch-centre abscissae (x[i] = x0 + (i + 1/2) dx
// for i < nx, the layout axisymmetric_section uses), the corner functions are shared along x (Toeplitz path).
StressField patch_traction_field(const PatchTraction &traction, double poisson_ratio, const std::vector<double> &x,
                                 const std::vector<double> &z, double y = 0.0);

// The section y = 0 below an axisymmetric contact with q = mu p: patches of size 2 half_size / n centred on the
// n field abscissae (so no surface point sits on a patch edge), depths z (z = 0 allowed).
StressField axisymmetric_section(const std::vector<double> &ring_pressure, double ring_width,
                                 double friction_coefficient, double poisson_ratio, double half_size, int n,
                                 const std::vector<double> &z);

}  // namespace runin::tribo
