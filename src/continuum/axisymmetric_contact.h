// Frictionless normal contact of an axisymmetric body on an elastic half-space, and Archard
// wear of that body with the geometry update (the pin of the pin-on-disk tribometer).
//
// Discretisation: n rings of width h = grid_radius / n, uniform pressure p_j on ring j,
// surface displacement collocated at the ring mid-radii r_i = (i + 1/2) h. The influence of a
// uniformly loaded disk of radius a at radius r is (Johnson, Contact Mechanics, eq. 3.39)
//   u = 4 p a E(r/a) / (pi E*)                                   r <= a
//   u = 4 p r [E(a/r) - (1 - a^2/r^2) K(a/r)] / (pi E*)          r >  a
// and a ring is the difference of two disks. With the initial separation g0_i, the rigid
// approach delta and the load W, the contact conditions are
//   g_i = g0_i - delta + sum_j C_ij p_j >= 0,  p_i >= 0,  g_i p_i = 0,  sum_j A_j p_j = W,
// solved by an active-set iteration (Eigen LU of the active block, re-used while the set holds).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "tribo/wear.h"

namespace runin::continuum {

struct ContactSolution {
  bool converged = false;
  std::string message;              // why not, when not converged
  std::vector<double> pressure;     // Pa, per ring
  double approach = 0.0;            // m, rigid-body approach delta
  double contact_radius = 0.0;      // m, outer edge of the outermost loaded ring
  double peak_pressure = 0.0;       // Pa
  double mean_pressure = 0.0;       // Pa, W / (pi a^2)
  int iterations = 0;
};

class AxisymmetricContact {
 public:
  // Throws std::invalid_argument on a non-positive size, ring count (< 2 or > 8192) or modulus.
  AxisymmetricContact(double grid_radius, int rings, double effective_modulus);

  int rings() const { return n_; }
  double ring_width() const { return h_; }
  double grid_radius() const { return h_ * n_; }
  double ring_radius(int i) const { return (i + 0.5) * h_; }  // collocation radius
  double ring_area(int i) const;
  const Eigen::MatrixXd &influence() const { return c_; }

  // `gap0` (size rings()) is the separation at zero approach. Loads that reach the last ring
  // are reported as not converged (the grid is too small).
  ContactSolution solve(const std::vector<double> &gap0, double load);
  // Largest pressure change per unit uniform-wear-depth perturbation on the active set of the
  // last solution [Pa/m]: the spectral radius of the inverse active influence block.
  double active_stiffness();

 private:
  // Makes `active` solvable and returns it ordered as base_ then extra_: the LU of the base
  // block is re-used, a few added rings are handled by the Schur complement.
  const std::vector<int> &prepare(const std::vector<int> &active);
  Eigen::VectorXd solve_ordered(const Eigen::VectorXd &b) const;  // C_{order,order} x = b

  int n_;
  double h_, e_star_;
  Eigen::MatrixXd c_;
  std::vector<int> active_;        // last converged active set
  std::vector<int> base_, extra_, order_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;        // of C_{base,base}
  Eigen::MatrixXd z_;                              // C_{base,base}^-1 C_{base,extra}
  Eigen::MatrixXd c_eb_;                           // C_{extra,base}
  Eigen::PartialPivLU<Eigen::MatrixXd> schur_lu_;  // of C_ee - C_eb z
  double stiffness_ = -1.0;  // cached for base_
  Eigen::VectorXd mode_;     // dominant mode, warm start of the power iteration
};

// Hertz reference for a sphere of radius R on a flat: a, p0, delta.
struct HertzSolution {
  double contact_radius, peak_pressure, approach;
  double pressure(double r) const;
};
HertzSolution hertz_sphere_on_flat(double sphere_radius, double effective_modulus, double load);

// Grid radius that holds the contact over a run: 1.5 x the larger of the Hertz radius and the
// flat worn into a sphere of radius R by the Archard volume V (cap: a = (4 R V / pi)^(1/4)).
double suggested_grid_radius(double tip_radius, double effective_modulus, double load,
                             const tribo::ArchardWear *wear, double sliding_distance);

struct PinWearParameters {
  double tip_radius = 0.0;        // m, spherical tip of the pin
  double effective_modulus = 0.0; // Pa, E* of the pin/disk pair
  double grid_radius = 0.0;       // m, radial extent of the discretised contact face
  int rings = 256;
  double step_safety = 0.5;       // wear step <= safety * 2H/(k k_c); 0.5 keeps the update monotone
  long max_steps = 1000000;       // budget of wear updates; advance() stops with a message beyond it
};

// Archard wear of the pin tip along the sliding distance: dh_i/ds = (k/H) p_i, gap0 = r^2/2R + h.
// The contact is solved against a flat disk: the disk's worn track (DiskTrackWear) is not in the gap.
class PinWear {
 public:
  PinWear(const PinWearParameters &parameters, tribo::ArchardWear wear, double load);

  // Slides `distance` (>= 0) in adaptive steps bounded by ArchardWear::stable_slip_step.
  // Returns false (and stops) if the contact fails to converge; see message().
  bool advance(double distance);
  // One explicit step of the given size, no bound (for tests of the bound).
  bool step(double distance);
  // One step with depth increments from outside (the state law's per-node dh_i over `distance`, which replace
  // the Archard rate): depth += increment, re-solve. Returns false (see message()) if the contact fails.
  bool apply(const std::vector<double> &increment, double distance);
  double contact_stiffness() { return contact_.active_stiffness(); }  // Pa/m on the current active set

  const ContactSolution &contact() const { return solution_; }
  const std::vector<double> &wear_depth() const { return depth_; }
  double wear_volume() const;           // m^3, sum of ring area x depth
  double stable_step();                 // m, safety * 2H/(k k_c) on the current active set
  double slid() const { return slid_; }
  long steps() const { return steps_; }
  const std::string &message() const { return message_; }
  const AxisymmetricContact &grid() const { return contact_; }
  double profile_height(int ring) const;  // m, r^2/2R + wear depth above the tip apex

 private:
  bool resolve();

  PinWearParameters p_;
  tribo::ArchardWear wear_;
  double load_;
  AxisymmetricContact contact_;
  std::vector<double> depth_;
  ContactSolution solution_;
  double slid_ = 0.0;
  long steps_ = 0;
  std::string message_;
};

// Archard wear of the disk's track under the pin. Each body wears by its own k_i/H_i
// (with equal k the split of the pair's volume is tribo::wear_share): the disk loses
//   V_d = (k_d/H_d) int W ds          (plain form; / 3H_d for ArchardForm::thesis)
// spread over the band the pin has swept: the track length L = min(s, 2 pi r) (one pass covers s; after a
// revolution the whole circumference) times the width w = the widest contact diameter so far. The mean
// track depth is h_d = V_d / (L w): one pass leaves (k_d/H_d) W / w, n passes n times that.
// A bookkeeping model: the groove is not fed back into the contact (see doc/pin_on_disk.md for why that is
// negligible while h_d << the elastic approach; the CLI checks it).
class DiskTrackWear {
 public:
  // Throws std::invalid_argument on a non-positive or non-finite track radius.
  DiskTrackWear(tribo::ArchardWear wear, double track_radius);

  // Slides `distance` (>= 0) under the normal force `load` through a contact `contact_width` wide (m).
  void slide(double load, double distance, double contact_width);
  // The same with the worn volume given (the state law's counterface_wear_rate summed over the nodes).
  void slide_volume(double volume, double distance, double contact_width);

  double volume() const { return volume_; }           // m^3
  double slid() const { return slid_; }               // m
  double track_width() const { return width_; }       // m, widest contact diameter so far
  double worn_length() const;                         // m, min(s, 2 pi r)
  double depth() const;                               // m, V_d / (L w); 0 before any sliding
  double passes() const;                              // s / (2 pi r)
  const tribo::ArchardWear &wear() const { return wear_; }

 private:
  tribo::ArchardWear wear_;
  double circumference_;
  double volume_ = 0.0, slid_ = 0.0, width_ = 0.0;
};

}  // namespace runin::continuum
