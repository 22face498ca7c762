// Mixed-lubrication run-in of a piston-ring face on the micro state law (doc/lubricated_piston_ring.md).
// The ring face (the law's rough body) slides on the liner (its counterface) at the slider-crank speed U(theta)
// under W' = (p_elastic + gas factor p_gas(theta)) b per unit circumference. Each crank step finds the
// minimum gap h_min at which the average-Reynolds film (Patir-Cheng, JFO cavitation, squeeze by implicit Euler
// (h_min - h_min,prev)/dt, fill carried from the previous step) and the Greenwood-Tripp asperities carry W':
//   gap_i = h_min + crown (2 x_i / b - 1)^2 + h_i - min_j(crown_j + h_j)   (h_i worn depth of face node i)
//   p_a,i = K_i E* F_5/2(gap_i / sigma_i),  sigma_i = sqrt(rq(p_a,i, h_i)^2 + sigma_liner^2)
//   friction = film shear (shear stress factors) + sum_i mu_body(p_a,i, h_i) p_a,i dx
//   dh_i/ds = wear_rate(p_a,i, h_i)   (only the asperity pressure wears; OutOfRange::Archard below the grid)
// The geometry is fixed over a cycle; the stepper (run_in) advances the wear by N cycles after each computed
// cycle (cycle jumping). System (MixedPistonRing), stepper (run_in) and observer (CycleObserver) are separate.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "continuum/average_reynolds.h"
#include "continuum/piston_ring.h"   // SliderCrank, GasPressureTable
#include "continuum/worn_surface.h"
#include "coupling/state_law.h"

namespace runin::continuum {

enum class OilSupply { Flooded, Starved };
// Liner roughness: Law: the liner's summit rms follows the law's rq like the ring's (the cell's counter-body is
// rough, statistically equal and wears at the same rate: sigma = sqrt(2) rq); Fixed: a constant liner_sigma.
enum class LinerRoughness { Law, Fixed };

// Greenwood-Tripp statistics of the law's surface (metadata surface.R, surface.spacing): eta = 1/spacing^2,
// beta = R. Throws std::invalid_argument naming the missing entry.
struct SummitStatistics {
  double density = 0.0;   // 1/m^2
  double radius = 0.0;    // m
};
SummitStatistics summit_statistics(const coupling::StateLaw &law);

// F_5/2(H) of Greenwood-Tripp as interpolated here (cubic Hermite in ln F on a grid of 0.01 in H)
double f52_interpolated(double H);

struct MixedRingParameters {
  SliderCrank crank;
  double crank_speed = 0.0;        // rad/s
  GasPressureTable gas;            // optional; when given its cycle is the cycle
  double bore = 0.0;               // m, D
  double face_width = 0.0;         // m, b (axial)
  double crown_height = 0.0;       // m, parabolic barrel crown (2x/b - 1)^2
  double elastic_pressure = 0.0;   // Pa
  double viscosity = 0.0;          // Pa s
  OilSupply supply = OilSupply::Flooded;
  double oil_film = 0.0;           // m, starved: oil layer on the liner ahead of the ring
  int nodes = 101;                 // face nodes
  int steps_per_cycle = 720;       // crank steps per cycle
  double effective_modulus = 0.0;  // Pa, E* of ring and liner
  SummitStatistics summits;
  LinerRoughness liner = LinerRoughness::Law;
  double liner_sigma = 0.0;        // m (Fixed)
  double gamma = 1.0;              // Peklenik number of both surfaces
  // worn summits: the cut follows the face's worn volume at the node (the liner's wear is spread over the stroke)
  WornSurface worn_surface = WornSurface::LawRq;

  void validate() const;           // throws std::invalid_argument naming the field
  double cycle_angle() const;      // rad: 2 pi, or the gas table's cycle
  double period() const;           // s
  double load_per_length(double theta) const;   // N/m, W'
  double liner_speed(double theta) const;       // m/s, liner relative to the ring (-piston velocity)
  double circumference() const;
};

// Film state carried between crank steps.
struct FaceState {
  double h_min = 0.0;              // m
  std::vector<double> fill;        // theta per node (face coordinate x from 0 to b)
  double log_rate = 0.0;           // ln(h_min / h_min,prev) of the last step: the next step's guess
  bool started = false;
};

enum class RingFilmStatus { Ok, FilmNotConverged, LoadNotBracketed, LoadNotConverged, LawOutOfRange };
const char *to_string(RingFilmStatus status);

struct FaceSolution {
  RingFilmStatus status = RingFilmStatus::Ok;
  double speed = 0.0, load = 0.0;        // m/s, N/m
  double h_min = 0.0, squeeze_velocity = 0.0;
  double film_load = 0.0, asperity_load = 0.0;         // N/m
  double viscous_friction = 0.0, boundary_friction = 0.0;   // N/m (magnitudes, against the sliding)
  double lambda = 0.0;                   // h_min / sigma at the node of the smallest gap
  double peak_film_pressure = 0.0, peak_asperity_pressure = 0.0;
  std::vector<double> gap, pressure, fill, asperity_pressure, mu_body, wear_rate;   // per node
  int film_solves = 0;
  double friction() const { return viscous_friction + boundary_friction; }
  double asperity_share() const { return load > 0.0 ? asperity_load / load : 0.0; }
  double mu() const { return load > 0.0 ? friction() / load : 0.0; }
};

// Per crank step of a cycle (whole ring: per unit circumference x pi D).
struct CrankSample {
  double crank_angle = 0.0, t = 0.0, speed = 0.0, load = 0.0;   // rad, s (from the cycle start), m/s, N
  double h_min = 0.0, friction_force = 0.0, mu = 0.0, asperity_share = 0.0, lambda = 0.0;
  double peak_film_pressure = 0.0, peak_asperity_pressure = 0.0;
};

// Face profiles at one crank step (VTK).
struct FaceFrame {
  double crank_angle = 0.0, t = 0.0;
  std::vector<double> gap, pressure, fill, asperity_pressure, worn_depth;
};

struct CycleResult {
  RingFilmStatus status = RingFilmStatus::Ok;
  std::string message;
  std::vector<CrankSample> curve;
  std::vector<FaceFrame> frames;
  std::vector<double> wear;            // m per node, worn depth of this cycle
  std::vector<double> mean_asperity_pressure;   // Pa per node, sliding-weighted (sets rq for the next cycle)
  std::vector<double> asperity_impulse;         // N s/m^2 per node, integral of p_a dt (R's weights)
  double mean_friction_force = 0.0;    // N, time mean of |F|
  double mu = 0.0;                     // integral |F| dt / integral W dt
  double power_loss = 0.0;             // W, mean |F| |U|
  double fmep = 0.0;                   // Pa, friction work per cycle / swept volume
  double min_h = 0.0, min_lambda = 0.0;
  double asperity_share = 0.0;         // integral W_a dt / integral W dt
  double peak_film_pressure = 0.0, peak_asperity_pressure = 0.0;
  double sliding_distance = 0.0;       // m per cycle
  long film_solves = 0;
  coupling::RangeUse use;
  bool ok() const { return status == RingFilmStatus::Ok; }
};

class MixedPistonRing {
 public:
  // Throws std::invalid_argument (bad parameters, no law).
  MixedPistonRing(MixedRingParameters parameters, std::shared_ptr<const coupling::StateLaw> law,
                  coupling::OutOfRange policy = coupling::OutOfRange::Archard);

  const MixedRingParameters &parameters() const { return p_; }
  const coupling::StateLaw &law() const { return *law_; }
  coupling::OutOfRange policy() const { return policy_; }
  int nodes() const { return p_.nodes; }
  double dx() const { return p_.face_width / (p_.nodes - 1); }
  double x(int i) const { return i * dx(); }
  double crown(int i) const;

  const std::vector<double> &worn_depth() const { return worn_; }
  void set_worn_depth(std::vector<double> h);   // also resets the roughness to the new depths
  // h_i += cycles dh_i, then rq from the cycle's asperity pressures
  void advance_wear(const std::vector<double> &dh, double cycles, const std::vector<double> &asperity_pressure);
  double worn_volume() const;                 // m^3 on the whole ring, pi D int h dx (trapezoid)
  const std::vector<double> &ring_rq() const { return rq_; }
  const std::vector<double> &sigma() const { return sigma_; }   // combined, per node
  // rq and combined sigma weighted by w (e.g. the asperity impulse; all zero: the face mean)
  double weighted_rq(const std::vector<double> &w) const;
  double weighted_sigma(const std::vector<double> &w) const;
  double film_sigma() const { return film_sigma_; }
  // worn summits: the cut per node (m above the unworn summit plane; +inf: none), and the worn depth over which
  // the node's contact changes by about one sigma (sigma; under a cut, the volume that moves it by sigma)
  const std::vector<double> &summit_top() const { return top_; }
  double wear_scale(int i) const;

  // One transient crank step from `prev` (implicit Euler in h_min, fill carried), at liner speed U and load W'.
  FaceSolution step(const FaceState &prev, double speed, double load, double dt, coupling::RangeUse *use) const;
  // Steady sliding (no squeeze, quasi-steady fill): the Stribeck point.
  FaceSolution steady(double speed, double load, coupling::RangeUse *use, double guess = 0.0) const;
  // A cycle at the present geometry from `state` (updated to the cycle end). keep_curve: crank samples and
  // frames every frame_every steps (0: none).
  CycleResult cycle(FaceState &state, bool keep_curve, int frame_every = 0) const;
  // Starts a film state: a quasi-steady solve at crank angle 0 then one cycle without wear (the periodic film).
  RingFilmStatus start(FaceState &state, std::string &message) const;

  double asperity_pressure(int i, double gap) const;   // Pa

 private:
  FaceSolution solve(double h_min, double speed, double squeeze, const std::vector<double> *fill_prev, double dt,
                     double load) const;
  FaceSolution balance(double h_prev, double speed, double load, const std::vector<double> *fill_prev, double dt,
                       coupling::RangeUse *use, double guess) const;
  void update_roughness(const std::vector<double> &pressure);
  void update_profile();

  MixedRingParameters p_;
  std::shared_ptr<const coupling::StateLaw> law_;
  coupling::OutOfRange policy_;
  std::vector<double> worn_, profile_, rq_, sigma_, k_;   // k_ = K_i E*; rq_, sigma_: after any cut
  std::vector<double> uncut_sigma_, top_;                 // the summits' sigma before the cut, and the cut
  double film_sigma_ = 0.0, film_rq_ = 0.0, film_liner_ = 0.0;
};

// ---------------------------------------------------------------------------------------------------
// Run-in with cycle jumping. After each computed cycle (fixed geometry) the wear advances by N cycles:
//   N = min over nodes of limit_i / dh_i,   limit_i = jump_sigma_fraction sigma_i, and while h_i is inside the
//   law's depth table also jump_depth_fraction x its depth spacing; N <= growth x the previous N, >= 1.
struct RunInSettings {
  long cycles = 100;
  bool jumping = true;                 // false: every cycle computed
  double jump_depth_fraction = 0.5;
  double jump_sigma_fraction = 0.05;
  double growth = 2.0;
  // a cycle that wears a node by more than this fraction of its sigma is not a gradual run-in at fixed geometry:
  // the run stops (WearPerCycleTooLarge)
  double max_cycle_wear_fraction = 0.5;
  // more computed cycles than this stops the run (TooManyCycles): jumping that barely jumps is hours of cycles
  long max_computed_cycles = 10000;
  int frame_every = 0;                 // crank steps between VTK frames of the first and last cycle (0: none)
  void validate() const;
};

struct CycleSample {
  long cycle = 0;                      // cycles completed before this one
  long jump = 1;                       // cycles this computed one stands for
  double time = 0.0, sliding_distance = 0.0;   // s, m at the cycle start
  double mean_friction_force = 0.0, mu = 0.0, power_loss = 0.0, fmep = 0.0;
  double min_h = 0.0, min_lambda = 0.0, asperity_share = 0.0;
  double rq = 0.0, sigma = 0.0;        // m, asperity-load-weighted ring rq (R) and combined sigma
  double max_worn_depth = 0.0, mean_worn_depth = 0.0, worn_volume = 0.0;   // at the cycle start
  double cycle_wear_volume = 0.0;      // m^3 worn in this cycle
  double peak_film_pressure = 0.0, peak_asperity_pressure = 0.0;
};
using CycleObserver = std::function<void(const CycleSample &)>;

enum class RunInStatus { Completed, CycleFailed, WearPerCycleTooLarge, TooManyCycles };
struct RunInReport {
  RunInStatus status = RunInStatus::Completed;
  std::string message;
  long cycles = 0, computed_cycles = 0;   // cycles: completed (at a failure: before the failing one)
  double booked_wear_volume = 0.0;     // sum over computed cycles of N x cycle wear volume
  CycleResult first, last;             // with curves
  coupling::RangeUse use;
  bool ok() const { return status == RunInStatus::Completed; }
};

RunInReport run_in(MixedPistonRing &system, const RunInSettings &settings, const CycleObserver &observer = {});

// ---------------------------------------------------------------------------------------------------
// Stribeck curve: steady sliding at fixed load W', log-spaced speeds from speed_min to speed_max.
struct RingStribeckPoint {
  RingFilmStatus status = RingFilmStatus::Ok;
  double speed = 0.0, duty = 0.0;      // m/s, eta U / W' (-)
  double h_min = 0.0, lambda = 0.0, mu = 0.0, asperity_share = 0.0;
  double viscous_friction = 0.0, boundary_friction = 0.0;   // N/m
};
std::vector<RingStribeckPoint> stribeck_sweep(const MixedPistonRing &system, double load, double speed_min,
                                          double speed_max, int points = 50, coupling::RangeUse *use = nullptr);

}  // namespace runin::continuum
