// Average Reynolds equation of Patir & Cheng (1978, 1979) with mass-conserving (JFO) cavitation.
//   div q = -d(theta h_T)/dt,
//   q_x = -phi_x h^3/(12 mu) dp/dx + theta (u_m h_T + u_d sigma phi_s),   q_y = -phi_y h^3/(12 mu) dp/dy
// u_m = (U1 + U2)/2, u_d = (U1 - U2)/2 (surface 1 moves at U1 along x); h_T the mean gap (h when smooth or
// when the contact factor is off). Cavitation: p >= 0, 0 <= theta <= 1, p (1 - theta) = 0 (the
// complementarity form of Giacopini et al. 2010) with the universal variable u: p = max(u, 0),
// theta = 1 + min(u, 0). The finite-volume residual is piecewise linear in u and is solved by semi-smooth
// (active-set) Newton: fix the full/cavitated pattern, solve the linear system (Eigen SparseLU), update
// the pattern, until it no longer changes. See doc/mixed_lubrication.md.
//
// A ReynoldsSystem holds a grid and the film on it; ReynoldsSolver solves it; the journal bearing and the
// ring face build systems and post-process the solution.
#pragma once

#include <optional>
#include <vector>

#include "tribo/greenwood_tripp.h"

namespace runin::continuum {

// Roughness of the film; sigma = 0: smooth (all flow factors 1, classical Reynolds equation).
struct FilmRoughness {
  double sigma_moving = 0.0;   // m, rms of the moving surface (surface 1)
  double sigma_fixed = 0.0;    // m, rms of the stationary surface (surface 2)
  double gamma = 1.0;          // Peklenik number, both surfaces (Patir & Cheng's fits: [1/9, 9])
  bool contact_factor = true;  // Couette content h_T (mean gap) instead of h
  bool flow_factors = true;    // false: classical Reynolds equation (sigma only for the asperity contact)

  double sigma() const;        // combined rms
  double averaged_sigma() const;   // sigma if flow_factors, else 0: the roughness the film equation sees
  void validate() const;       // throws tribo::InvalidCoefficient naming the field
};

// Grid: nodes (i, j), i = 0..nx-1 along x (sliding), j = 0..ny-1 across (ny = 1: one-dimensional film
// per unit width). Node index k = i + nx j. Fixed nodes carry a prescribed pressure and fill fraction
// (boundaries, supply grooves); the others are unknown, each the centre of a dx x dy cell.
struct ReynoldsSystem {
  int nx = 0, ny = 1;
  double dx = 0.0, dy = 1.0;       // m (dy = 1 m: per unit width when ny = 1)
  bool periodic_x = false;
  double viscosity = 0.0;          // Pa s
  double u_moving = 0.0;           // m/s, surface 1 (the stationary surface 2 is at rest)
  FilmRoughness roughness;
  std::vector<double> h;           // m, nominal gap at the nodes
  std::vector<double> dhdt;        // m/s, squeeze velocity at the nodes (empty: 0)
  std::vector<double> theta_prev;  // fill fraction at the previous time (empty: quasi-steady, no d theta/dt)
  double dt = 0.0;                 // s, with theta_prev
  std::vector<char> fixed;         // 1: prescribed node
  std::vector<double> fixed_pressure, fixed_fill;   // Pa, - at the fixed nodes
  // Combined rms roughness per node (m; empty: roughness.sigma() everywhere), e.g. a worn surface whose roughness
  // varies. The split between the surfaces (V_r of the shear terms) stays roughness's sigma_moving : sigma_fixed;
  // a face takes the mean of its two nodes. Ignored when roughness.flow_factors is false.
  std::vector<double> sigma;

  int nodes() const { return nx * ny; }
  int index(int i, int j) const { return i + nx * j; }
  void validate() const;   // throws tribo::InvalidCoefficient naming the field
};

enum class ReynoldsStatus { Converged, NotConverged, SingularMatrix };
const char *to_string(ReynoldsStatus status);

struct ReynoldsSolution {
  ReynoldsStatus status = ReynoldsStatus::NotConverged;
  std::vector<double> pressure;   // Pa
  std::vector<double> fill;       // theta, 1: full film
  int iterations = 0;             // active-set passes
  double residual = 0.0;          // max |mass residual| over the cells, m^3/s
  bool ok() const { return status == ReynoldsStatus::Converged; }
};

class ReynoldsSolver {
 public:
  explicit ReynoldsSolver(int max_iterations = 200) : max_iterations_(max_iterations) {}

  // initial: a start pattern, one value per node (< 0: start cavitated), e.g. the previous step's
  // pressure - (1 - fill); default: full film everywhere.
  ReynoldsSolution solve(const ReynoldsSystem &system,
                         const std::optional<std::vector<double>> &initial = std::nullopt) const;
  ReynoldsStatus info() const { return status_; }

  // Volume flux (m^3/s; m^2/s per unit width when ny = 1) through the face between node (i, j) and
  // (i + 1, j) in +x (i = nx - 1 wraps to 0: periodic systems only), and between (i, j) and (i, j + 1) in +y.
  static double flux_x(const ReynoldsSystem &s, const ReynoldsSolution &sol, int i, int j);
  static double flux_y(const ReynoldsSystem &s, const ReynoldsSolution &sol, int i, int j);

 private:
  int max_iterations_;
  mutable ReynoldsStatus status_ = ReynoldsStatus::NotConverged;
};

// ---------------------------------------------------------------------------------------------------
// Journal bearing of finite length: shaft of radius R turning at omega in a fixed bore of radial clearance
// c, journal centre displaced by e = eps c. theta is measured from the line of centres at the largest gap
// in the direction of rotation: h = c (1 + eps cos theta). An axial supply groove (full width, one grid
// column) at groove_angle feeds oil at supply_pressure; both ends are at ambient pressure 0 (flooded).
struct HydroJournalBearing {
  double radius = 0.0;             // m, R
  double length = 0.0;            // m, L
  double clearance = 0.0;         // m, c
  double viscosity = 0.0;         // Pa s
  double omega = 0.0;             // rad/s
  double eccentricity_ratio = 0.0;  // eps in [0, 1)
  double groove_angle = 0.0;      // rad from the largest gap
  double supply_pressure = 0.0;   // Pa (gauge)
  int n_theta = 180, n_axial = 21;  // grid nodes (n_axial includes both ends)
  FilmRoughness roughness;
  double boundary_friction = 0.0;   // asperity friction coefficient (with a GreenwoodTripp contact)
  // Couette shear in the cavitated zone: false: carried by the filled share theta (striated film);
  // true: as if the film were full (Raimondi & Boyd's friction variable)
  bool full_film_shear_in_cavitation = false;
  // Bore-fixed grid (the mixed-lubrication run-in): node i sits at the bore angle i 2 pi / n_theta, the largest gap
  // of the journal's displacement at line_of_centres (rad; 0: the grid is the line-of-centres frame as above);
  // h_i = c (1 + eps cos(angle_i - line_of_centres)) + gap_addition[i] (m per circumferential node, e.g. the worn
  // depth of the bore; empty: none). With a gap_addition, eps may reach or pass 1 (the journal sinks into the
  // worn bore) as long as every gap stays positive. node_sigma (m per circumferential node; empty: roughness):
  // the film's local combined roughness (ReynoldsSystem::sigma). The groove stays at groove_angle on the grid.
  double line_of_centres = 0.0;
  std::vector<double> gap_addition, node_sigma;

  void validate() const;   // throws tribo::InvalidCoefficient naming the field
  ReynoldsSystem system() const;
};

struct HydroJournalResult {
  ReynoldsSolution film;
  double load_radial = 0.0;       // N, along the line of centres (toward the bore centre)
  double load_tangential = 0.0;   // N, perpendicular, in the direction of rotation
  double load = 0.0;              // N
  double attitude_angle = 0.0;    // rad, between the load line and the line of centres
  double sommerfeld = 0.0;        // (R/c)^2 mu N / P, N in rev/s, P = W / (L D)
  double friction_force = 0.0;    // N, on the journal surface (film shear + asperity friction)
  double friction_torque = 0.0;   // N m
  double friction_coefficient = 0.0;   // friction_force / total_load
  double inlet_flow = 0.0;        // m^3/s, leaving the groove downstream
  double outlet_flow = 0.0;       // m^3/s, returning into the groove from upstream
  double side_leakage = 0.0;      // m^3/s, out of both ends
  double cavitated_fraction = 0.0;   // area share with theta < 1
  double rupture_angle = 0.0;     // rad, first cavitated node at mid-length after the groove
  double reformation_angle = 0.0; // rad, last cavitated node at mid-length before the groove
  double asperity_load = 0.0;     // N, Greenwood-Tripp resultant (magnitude), when a contact is given
  double total_load = 0.0;        // N, resultant of film and asperity pressure
  double asperity_share = 0.0;    // asperity normal force / (film + asperity normal force), integrated |p|
  double peak_pressure = 0.0;     // Pa
};

// initial: start pattern of the active-set solve (see ReynoldsSolver::solve), e.g. the last solution's
// pressure - (1 - fill); the result does not depend on it, only the number of passes.
HydroJournalResult solve_journal_bearing(const HydroJournalBearing &bearing,
                                         const tribo::GreenwoodTripp *contact = nullptr,
                                         const ReynoldsSolver &solver = ReynoldsSolver(),
                                         const std::vector<double> *initial = nullptr);

// ---------------------------------------------------------------------------------------------------
// Piston-ring face (one-dimensional, per unit circumference): the ring face of axial width b with profile
// h(x) = h_min + profile(x) slides at speed U over the liner (the liner moves at -U in the ring frame:
// here surface 1 = liner at u_moving = U), approaching at dh/dt. Inlet pressure and fill at x = 0 (leading
// edge), outlet pressure at x = b.
struct RingFace {
  double width = 0.0;             // m, b
  double viscosity = 0.0;         // Pa s
  double speed = 0.0;             // m/s, liner relative to the ring (+x: from the inlet edge)
  double min_gap = 0.0;           // m, h_min (mean planes)
  double squeeze_velocity = 0.0;  // m/s, dh_min/dt (< 0: approaching)
  double inlet_pressure = 0.0, outlet_pressure = 0.0;   // Pa
  double inlet_fill = 1.0;        // oil available at the inlet (1: flooded)
  std::vector<double> profile;    // m, gap above h_min at n equally spaced nodes (size >= 3)
  FilmRoughness roughness;
  std::vector<double> fill_prev;  // fill fraction per node at the previous time (empty: quasi-steady)
  double dt = 0.0;                // s, time since fill_prev (> 0 with fill_prev)

  void validate() const;   // throws tribo::InvalidCoefficient naming the field
  ReynoldsSystem system() const;
};

struct RingFaceResult {
  ReynoldsSolution film;
  double load = 0.0;              // N/m, film load per unit circumference
  double friction = 0.0;          // N/m, shear on the liner
  double inlet_flow = 0.0, outlet_flow = 0.0;   // m^2/s per unit circumference
  double asperity_load = 0.0;     // N/m
};

RingFaceResult solve_ring_face(const RingFace &ring, const tribo::GreenwoodTripp *contact = nullptr,
                               const ReynoldsSolver &solver = ReynoldsSolver());

}    // namespace runin::continuum
