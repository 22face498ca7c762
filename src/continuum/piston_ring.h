// Piston ring in a cylinder, dry (thesis ch. 6). The piston follows a prescribed motion x_p(t)
// (slider-crank eq. 6.1, or the thesis's linear displacement ramp); the ring (mass m) is held on
// the piston by an elastic land (stiffness k, damping c) and rubs on the fixed liner:
//   land force    F_s = -k e - c (u - v_p),   e = x_ring - x_p,   u = dx_ring/dt (sliding speed)
//   stick:  u = 0, friction = F_s               while |F_s| <= mu_static W(t)
//   slip:   m du/dt = F_s - sign(u) mu(s, |u|, R) W(t),   ds/dt = |u|
//   W(t) = (p_elastic + gas_factor p_gas(crank angle)) pi D w    (ring pressed on the bore)
// y = (e, u, s, R); break-away and re-stick (velocity reversals at the dead centres) are CVODE roots.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "continuum/cvode_integrator.h"
#include "continuum/stick_slip_loop.h"  // ContactState, SolveStatus, SolveReport
#include "continuum/sliding_friction.h"

namespace runin::continuum {

// Eq. 6.1: x(theta) = r cos(theta) + l sqrt(1 - (r/l)^2 sin^2(theta)), theta = 0 at top dead centre.
struct SliderCrank {
  double crank_radius = 0.0;  // m
  double link_length = 0.0;   // m, > crank_radius

  void validate() const;  // throws std::invalid_argument
  double position(double theta) const;
  double velocity(double theta, double omega) const;  // dx/dt at crank speed omega = dtheta/dt
  double top_dead_centre() const { return link_length + crank_radius; }
  double bottom_dead_centre() const { return link_length - crank_radius; }
  // Inverse of position() on 0 <= theta <= pi (acos of the cosine rule).
  double angle_at(double x) const;
};

// Crank-angle dependent gas pressure behind the ring: linear interpolation, periodic over cycle.
struct GasPressureTable {
  std::vector<double> crank_angle;  // rad, increasing, within [0, cycle)
  std::vector<double> pressure;     // Pa (gauge), >= 0
  double cycle = 4.0 * 3.14159265358979323846;  // rad (720 deg: four-stroke)
  double factor = 1.0;                           // share of the gas pressure acting behind the ring

  bool empty() const { return crank_angle.empty(); }
  void validate() const;
  double at(double theta) const;
};

enum class PistonMotion { Ramp, Crank };

struct PistonRingParameters {
  SliderCrank crank;
  PistonMotion motion = PistonMotion::Ramp;
  double start_angle = 75.0 * 3.14159265358979323846 / 180.0;  // rad before TDC
  double ramp_time = 2.0;      // s (Ramp): linear displacement from x(start) to TDC, then held
  double crank_speed = 0.0;    // rad/s (Crank): theta(t) = -start_angle + omega t

  double bore = 0.1;           // m, D
  double ring_width = 0.01;    // m, axial width w
  double ring_mass = 0.0;      // kg
  double land_stiffness = 0.0; // N/m, k
  double land_damping = 0.0;   // N s/m, c
  double elastic_pressure = 0.0;  // Pa, ring tension as a uniform pressure on the bore
  GasPressureTable gas;

  void validate() const;  // throws std::invalid_argument naming the field
  double contact_area() const;  // pi D w
};

// Axial stiffness of the land that carries a ring, from the piston's and the ring's dimensions
// (the thesis: piston and rings of the same grey cast iron). Two compliances in series:
//  - land: the piston land between the groove root (diameter D_g) and the piston's outer
//    diameter (taken as the bore D; the running clearance is << the land) is an annular plate of
//    axial thickness h, built in at the groove root, free at the outside, loaded by the ring over
//    its flank. With L = (D - D_g)/2 << D the plate is a strip in cylindrical bending
//    (Timoshenko & Woinowsky-Krieger, Theory of Plates and Shells, 2nd ed., sec. 1-2) with
//    Timoshenko's shear term (shear coefficient 5/6). For a uniform flank pressure, the mean
//    (work-conjugate) deflection under a load F per unit circumference is
//      delta = F (L^3 / (20 D_p) + L / (3 kappa G h)),   D_p = E h^3 / (12 (1 - nu^2)),
//    so k_land = pi D_m / (L^3 / (20 D_p) + L / (3 kappa G h)),  D_m = (D + D_g) / 2.
//  - ring: the liner's friction enters the ring at its face (radius D/2) and leaves through the
//    flank; axial shear of the annular section of width w, tau = F / (2 pi r w), gives
//      k_ring = 2 pi G w / ln(D / (D - 2 t)).
struct RingLandGeometry {
  double bore = 0.0;             // m, D
  double groove_diameter = 0.0;  // m, D_g, groove root
  double land_width = 0.0;       // m, h, axial thickness of the land carrying the ring
  double ring_width = 0.0;       // m, w
  double ring_thickness = 0.0;   // m, t, radial
  double youngs_modulus = 0.0;   // Pa
  double poisson_ratio = 0.0;

  void validate() const;  // throws std::invalid_argument naming the field
};
struct LandStiffness {
  double land = 0.0, ring = 0.0, total = 0.0;  // N/m
};
LandStiffness land_stiffness(const RingLandGeometry &geometry);

struct PistonRingSample {
  double t = 0.0;
  double crank_angle = 0.0;      // rad (negative before TDC)
  double piston_position = 0.0;  // m, eq. 6.1 coordinate
  double piston_velocity = 0.0;  // m/s
  double ring_position = 0.0;    // m, x_p + e
  double speed = 0.0;            // m/s, ring sliding velocity on the liner (signed; 0 in stick)
  double distance = 0.0;         // m, accumulated sliding distance
  double friction_force = 0.0;   // N, force of the ring on the liner along +x (sign of the sliding velocity)
  double land_force = 0.0;       // N, force of the piston land on the ring (FEA's "resultant contact force")
  double normal_load = 0.0;      // N, W
  double mu = 0.0;               // |friction_force| / W (stick: mobilised, below mu_static)
  double mu_law = 0.0;           // law value at s without the speed term
  double roughness = 0.0;        // friction-law state R, 0 without one
  ContactState state = ContactState::Stick;
};

class PistonRingSystem {
 public:
  PistonRingSystem(PistonRingParameters parameters, SlidingFriction friction);

  static constexpr std::size_t state_size = 4;
  const PistonRingParameters &parameters() const { return p_; }
  const SlidingFriction &friction() const { return friction_; }

  double crank_angle(double t) const;
  double piston_position(double t) const;
  double piston_velocity(double t) const;
  double normal_load(double t) const;
  double land_force(double t, const double *y) const;
  double static_limit(double t, const double *y) const;  // mu_static(R) W(t)
  void rhs(double t, const double *y, double *dydt, ContactState state, int direction) const;
  PistonRingSample sample(double t, const double *y, ContactState state, int direction) const;
  // Time of a kink in the prescribed motion (ramp end), or a negative value.
  double motion_kink() const;

 private:
  PistonRingParameters p_;
  SlidingFriction friction_;
};

struct PistonRingRun {
  double t_end = 2.0;
  double output_interval = 1e-3;
  CvodeIntegrator::Settings integrator;
  int max_events = 20000;  // 50 x the long crank case (401 events); run.max_events raises it

  void validate() const;
};

using PistonRingObserver = std::function<void(const PistonRingSample &)>;
// Called after each output-grid sample: true when the friction changed there (the state law's operator
// splitting, doc/state_law_continuum.md); CVODE then restarts from that sample.
using PistonRingRefresh = std::function<bool()>;

// CVODE per contact phase, restarted at each event and at the ramp end. Numerical failure is
// reported in the status; bad settings throw std::invalid_argument.
SolveReport simulate(const PistonRingSystem &system, const PistonRingRun &run, const PistonRingObserver &observer,
                     const PistonRingRefresh &refresh = {});

struct PistonRingSummary {
  double peak_friction_force = 0.0, peak_time = 0.0;  // largest |friction_force|
  double peak_land_force = 0.0;
  double breakaway_time = -1.0;   // first stick -> slip, -1: never
  double start_friction_force = 0.0;  // largest |F| up to the first slip sample: mu_static W at break-away
  double steady_time = -1.0;      // -1: not steady by the criterion below
  double steady_mu = 0.0;
  double steady_friction_force = 0.0;
  std::string steady_criterion;
  static constexpr double steady_tolerance = 0.02;  // ramp: relative, on |friction force| and speed
  static constexpr double cycle_tolerance = 0.01;   // crank: relative, on the cycle-mean |friction force|
};
// Ramp: steady from the first sample after which |friction force| and sliding speed stay within
// 2 % of their final values (not steady if that is in the last 10 % of the run).
// Crank: per crank revolution (per gas cycle if there is a gas table), the mean |friction force|;
// steady from the first cycle whose mean is within 1 % of the last full cycle's (not steady if
// only the last one is); steady mu = integral |F| / integral W over the last cycle.
PistonRingSummary summarise(const PistonRingSystem &system, const std::vector<PistonRingSample> &samples);

}  // namespace runin::continuum
