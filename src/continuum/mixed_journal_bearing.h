// Mixed-lubrication run-in of a journal bearing on the homogenised micro state law (doc/lubricated_journal_bearing.md).
//
// A journal of radius R turns at U(t) = omega(t) R in a bore of radial clearance c under a fixed radial load W.
// The bore is the law's rough body: it carries a worn depth h_i per circumferential node, fixed to the bore and
// positioned relative to the load line (bore angle alpha from the point the load presses on, in the direction of
// rotation). The gap between the mean planes is
//   g_i = c (1 - eps cos(alpha_i - alpha_min)) + h_i + h_shaft
// (alpha_min: the attitude, where the journal approaches the bore; h_shaft the journal's circumference-mean worn
// depth). Film: the average Reynolds equation (average_reynolds.h) with the node's combined roughness; asperities:
// Greenwood-Tripp with eta = 1/spacing^2, beta = summit radius and the node's combined summit roughness
//   sigma_i = sqrt(rq(p_a,i, h_i)^2 + rq(p_a,i, h_shaft)^2)     (the cell's counterface is rough too)
// Each step: (eps, alpha_min) such that film + asperity force = W along the load line (the resultant); wear
// dh_i/ds = law wear_rate(p_a,i, h_i) from the asperity pressure only; the journal wears by the law's
// counterface_wear_rate, spread over its circumference. Friction = viscous shear (Patir-Cheng shear stress
// factors) + sum_i mu_body(p_a,i, h_i) p_a,i A_i.
//
// House style (as odeint / SUNDIALS): MixedJournalBearingSystem (the physics: equilibrium and wear rates at a
// state) is separate from the stepper (run_in: explicit wear steps bounded adaptively) and the observer.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "continuum/average_reynolds.h"
#include "continuum/worn_surface.h"
#include "coupling/state_law.h"

namespace runin::continuum {

struct MixedJournalBearingParameters {
  double radius = 0.0;           // m, R
  double length = 0.0;           // m, L
  double clearance = 0.0;        // m, c (radial)
  double load = 0.0;             // N, W
  double viscosity = 0.0;        // Pa s
  double supply_pressure = 0.0;  // Pa (gauge) in the axial groove
  double groove_angle = 3.14159265358979323846;  // rad, bore angle of the groove (default: opposite the load)
  // Journal speed: constant `speed` (m/s, surface speed U), or a table speed_time (s) -> speed_value (m/s),
  // linear between the points and held beyond them.
  double speed = 0.0;
  std::vector<double> speed_time, speed_value;
  int n_theta = 72, n_axial = 9;   // film grid (n_axial includes both ends)
  double gamma = 1.0;              // Peklenik number of both surfaces
  bool flow_factors = true;        // Patir-Cheng flow and shear stress factors (false: classical film)
  bool counterface_rough = true;   // the journal is the cell's rough counterface (false: smooth journal)
  // Greenwood-Tripp statistics: summit density eta (1/m^2), summit radius beta (m), contact modulus E* (Pa).
  double summit_density = 0.0, summit_radius = 0.0, effective_modulus = 0.0;
  std::shared_ptr<const coupling::StateLaw> law;
  coupling::OutOfRange policy = coupling::OutOfRange::Archard;
  // Fixed roughness (m) instead of the law's rq (> 0: every node, both surfaces together; for checks).
  double sigma_override = 0.0;
  // worn summits: the cut follows the bore's plus the journal's worn volume at the node (worn_surface.h)
  WornSurface worn_surface = WornSurface::LawRq;

  double speed_at(double t) const;
  double omega_at(double t) const { return speed_at(t) / radius; }
  double mean_pressure() const { return load / (2.0 * radius * length); }   // P = W / (L D)
  void validate() const;   // throws tribo::InvalidCoefficient naming the field
};

// Greenwood-Tripp statistics from a state law's metadata `surface` {R, spacing}: eta = 1/spacing^2, beta = R.
// Throws std::invalid_argument ("a law without the statistics mixed lubrication needs ...") when absent.
void asperity_statistics_from_law(const coupling::StateLaw &law, double &summit_density, double &summit_radius);

// Worn state: bore worn depth per circumferential node, journal mean worn depth.
struct MixedWearState {
  std::vector<double> bore;   // m, h_i
  double shaft = 0.0;         // m
  std::vector<double> asperity_pressure;   // Pa, the last equilibrium's p_a,i: the law's rq is taken there (lagged)
};

enum class MixedStatus { Converged, GapCloses, FilmFailed, NotConverged };
const char *to_string(MixedStatus status);

struct MixedEquilibrium {
  MixedStatus status = MixedStatus::NotConverged;
  std::string message;
  double eccentricity = 0.0;       // eps (> 1 possible in a worn bore)
  double attitude = 0.0;           // rad, alpha_min: bore angle of the approach from the load line
  double h_min = 0.0;              // m, smallest gap (mean planes)
  double lambda = 0.0;             // h_min / sigma at that node
  double sigma_contact = 0.0;      // m, asperity-load-weighted combined sigma (R of the contact); h_min node's if none
  double film_load = 0.0;          // N, film force along the load line
  double asperity_load = 0.0;      // N, asperity force along the load line
  double perpendicular_load = 0.0; // N, film + asperity resultant across the load line (0 at the balance)
  double asperity_share = 0.0;     // asperity_load / W
  double viscous_friction = 0.0;   // N, film shear on the journal
  double boundary_friction = 0.0;  // N, sum mu_body p_a A
  double mu = 0.0, mu_viscous = 0.0, mu_boundary = 0.0;   // / W
  double peak_film_pressure = 0.0, peak_asperity_pressure = 0.0;   // Pa
  double sommerfeld = 0.0, hersey = 0.0;   // (R/c)^2 eta N / P, eta N / P (N rev/s)
  double cavitated_fraction = 0.0;
  int film_solves = 0;
  std::vector<double> gap, sigma, asperity_pressure, mu_body;   // per circumferential node (sigma: R, after any cut)
  std::vector<double> top;                                     // m, the worn summits' cut (+inf: none)
  HydroJournalResult film;   // the film at the equilibrium (pressure, fill on the n_theta x n_axial grid)
  // d(residual)/d(eps, attitude), row-major, residual = (S_along - W, S_across) / W: warm-starts the next solve
  double jacobian[4] = {0.0, 0.0, 0.0, 0.0};
  bool jacobian_valid = false;
  bool ok() const { return status == MixedStatus::Converged; }
};

// Wear rates at an equilibrium (per unit sliding distance).
struct MixedWearRates {
  std::vector<double> bore;      // dh_i/ds
  double shaft = 0.0;            // dh_shaft/ds = mean over the bore nodes of counterface_wear_rate
  double bore_volume = 0.0;      // m^3/m, sum_i dh_i/ds A_i
};

class MixedJournalBearingSystem {
 public:
  explicit MixedJournalBearingSystem(MixedJournalBearingParameters parameters);   // validates

  const MixedJournalBearingParameters &parameters() const { return p_; }
  MixedWearState initial_state() const;
  double node_area() const;   // m^2, R (2 pi / n_theta) L
  double bore_angle(int i) const;

  // (eps, attitude) carrying W at the state and surface speed U; `guess` (optional) warm-starts from an earlier
  // equilibrium (its eps, attitude and film pattern). rel_tol: on the force balance, relative to W.
  MixedEquilibrium equilibrium(const MixedWearState &state, double speed, const MixedEquilibrium *guess = nullptr,
                               double rel_tol = 1e-8) const;
  // The film and asperity forces at a given (eps, attitude) (no balance), for checks. `surface`: the state's
  // node_surface, when the caller evaluates one state many times (the balance solve).
  MixedEquilibrium evaluate(const MixedWearState &state, double speed, double eccentricity, double attitude,
                            const std::vector<double> *initial = nullptr) const;
  struct NodeSurface {
    std::vector<double> sigma, top, rms;   // before the cut, the cut, after the cut (see node_top, node_rms)
  };
  NodeSurface node_surface(const MixedWearState &state) const;
  MixedEquilibrium evaluate(const MixedWearState &state, const NodeSurface &surface, double speed, double eccentricity,
                            double attitude, const std::vector<double> *initial = nullptr) const;
  MixedWearRates wear_rates(const MixedWearState &state, const MixedEquilibrium &eq,
                            coupling::RangeUse *use = nullptr) const;
  // Eccentricity at which the smallest gap closes for a displacement toward `attitude`.
  double closing_eccentricity(const MixedWearState &state, double attitude) const;
  // Combined roughness per node at the state (lagged asperity pressure): the summits' sigma before any cut.
  std::vector<double> node_sigma(const MixedWearState &state, coupling::RangeUse *use = nullptr) const;
  // Worn summits: the cut per node (m above the summits' unworn mean plane; +inf: none, LawRq), and the RMS of
  // the summits after it (R; sigma itself under LawRq).
  std::vector<double> node_top(const MixedWearState &state, const std::vector<double> &sigma) const;
  std::vector<double> node_rms(const std::vector<double> &sigma, const std::vector<double> &top) const;

 private:
  HydroJournalBearing film_bearing(const MixedWearState &state, const std::vector<double> &sigma, double speed,
                                   double eccentricity, double attitude) const;
  MixedJournalBearingParameters p_;
};

// ---------------------------------------------------------------------------------------------------
struct MixedRunSettings {
  double t_end = 0.0;                // s
  double output_interval = 0.0;      // s (<= 0: t_end / 200)
  std::vector<double> frame_times;   // s: field frames at the first output at or after each
  // Largest worn-depth increment per step: fraction x (the law's local depth spacing while inside its table,
  // 0.1 sigma beyond it). The explicit step is stable below ~2 sigma / 3 (the asperity pressure falls as
  // exp(-~3 h / sigma)), so the bound is set by accuracy, not stability.
  double depth_step_fraction = 0.5;
  long max_steps = 200000;
  double rel_tol = 1e-8;             // force balance
  bool sample_wear_limited_steps = true;   // also a sample after every step shorter than the output interval
};

struct MixedSample {
  double t = 0.0, distance = 0.0, speed = 0.0;
  double eccentricity = 0.0, attitude = 0.0, h_min = 0.0, lambda = 0.0;
  double asperity_share = 0.0, mu = 0.0, mu_viscous = 0.0, mu_boundary = 0.0;
  double sigma_contact = 0.0;        // R: asperity-load-weighted combined sigma
  double h_max = 0.0, h_mean = 0.0;  // m, bore worn depth (mean over the nodes)
  double bore_volume = 0.0;          // m^3, worn volume of the bore
  double shaft_depth = 0.0;          // m, journal mean worn depth
  double peak_film_pressure = 0.0, peak_asperity_pressure = 0.0;
  double sommerfeld = 0.0;
  long steps = 0;                    // wear steps so far
};

struct MixedFrame {
  double t = 0.0;
  std::vector<double> gap, worn_depth, asperity_pressure;   // per circumferential node
  std::vector<double> pressure, fill;                        // n_theta x n_axial, index i + n_theta j
};

enum class MixedRunStatus { Finished, EquilibriumFailed, TooManySteps, LawOutOfRange };
const char *to_string(MixedRunStatus status);

struct MixedRunReport {
  MixedRunStatus status = MixedRunStatus::Finished;
  std::string message;
  MixedStatus equilibrium_status = MixedStatus::Converged;   // EquilibriumFailed: the failed balance's status
  std::string equilibrium_message;                           // and its message
  long steps = 0, film_solves = 0;
  coupling::RangeUse range_use;
  double rate_volume_integral = 0.0;   // m^3: sum over steps of bore_volume rate x ds (the bookkeeping check)
  MixedWearState final_state;
  MixedEquilibrium initial, final;
  bool ok() const { return status == MixedRunStatus::Finished; }
};

using MixedObserver = std::function<void(const MixedSample &)>;
using MixedFrameObserver = std::function<void(const MixedFrame &)>;

MixedRunReport run_in(const MixedJournalBearingSystem &system, const MixedRunSettings &settings,
                      const MixedObserver &observer, const MixedFrameObserver &frames = nullptr);

// ---------------------------------------------------------------------------------------------------
// Stribeck sweep at a fixed worn state: `points` speeds log-spaced from speed_min to speed_max (m/s).
struct StribeckPoint {
  double speed = 0.0, hersey = 0.0, sommerfeld = 0.0;
  double mu = 0.0, mu_viscous = 0.0, mu_boundary = 0.0, lambda = 0.0, asperity_share = 0.0;
  double eccentricity = 0.0, attitude = 0.0, h_min = 0.0;
};
struct StribeckResult {
  MixedStatus status = MixedStatus::Converged;
  std::string message;
  std::vector<StribeckPoint> points;
  bool ok() const { return status == MixedStatus::Converged; }
};
StribeckResult stribeck_sweep(const MixedJournalBearingSystem &system, const MixedWearState &state, double speed_min,
                              double speed_max, int points = 50, double rel_tol = 1e-8);

}    // namespace runin::continuum
