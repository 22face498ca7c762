// Dry journal bearing (thesis ch. 5): a shaft of radius R turns in a fixed bore under a radial
// load W. Thesis set-up (the default, halves = 2): "a 1 kg vertical load is applied equally and in
// opposite directions to each bearing half": two opposite bore halves (lower, upper) are each pressed
// onto the shaft with W, so there are two conformal contacts, each with its own pressure, wear and
// friction-law state; the shaft sees the sum of their friction torques (and the net radial force
// cancels). halves = 1 is the single-contact model (one bore pressed with W). The drive end follows a prescribed rotation (linear ramp to `ramp_angle` at
// `ramp_time`, then an optional constant speed); it turns the journal through a torsional
// coupling (stiffness k, damping c), so the resisting torque of the contact is finite:
//   J dw/dt = T_c - T_f,   T_c = k (theta_drive - theta) + c (w_drive - w),   ds/dt = R |w|
//   stick: w = 0, T_f = T_c        while |T_c| < sum_h mu_static(R_h) N_h R
//   slip:  T_f = sign(w) sum_h mu(s, R|w|, R_h) N_h R,   N_h = integral of half h's contact pressure (>= W)
// The shaft lags the prescribed drive angle by the coupling wind-up |T_c| / k <= mu_static N R / k.
// CVODE integrates (theta, w, s, R_h...) (R_h: half h's friction-law state, feedback roughness) with break-away / re-stick events (root finding). Between wear
// updates the pressure is frozen; a wear update (root s = s_next) applies Archard wear
// dw_i = (k/H) p_i ds to the bore and re-solves the conformal contact (conformal_contact.h).
// The wear step ds is a fraction of ArchardWear::stable_slip_step(k_c), or fixed if asked.
// With friction.model = "state_law" (doc/state_law_continuum.md) each node of each half carries its worn depth
// h_i: a half's friction is mu_eff,h = sum_i mu(p_i, h_i) p_i / sum_i p_i (+ alpha V), its static limit the law's
// peak (or friction.mu_static), and a wear update advances h_i by the law's wear_rate (the same dh_i wears the
// bore; the Archard k/H is not used) and the shaft by its counterface_wear_rate (bookkeeping volume). Updates
// happen at the wear-step roots (step = fraction x 2 / (k_c max w/p), or fixed) and at every output sample
// (operator splitting at the output interval), each followed by a contact re-solve and a CVODE restart.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "continuum/conformal_contact.h"
#include "continuum/contact_stress.h"
#include "continuum/cvode_integrator.h"
#include "continuum/node_state_law.h"
#include "continuum/stick_slip_loop.h"  // ContactState, SolveStatus
#include "continuum/sliding_friction.h"
#include "tribo/wear.h"

namespace runin::continuum {

// Torsional stiffness of a solid round shaft between the drive and the bearing:
//   k = G J / L,   G = E / (2 (1 + nu)),   J = pi d^4 / 32   (N m/rad).
double shaft_torsional_stiffness(double diameter, double length, double youngs_modulus, double poisson_ratio);

struct JournalBearingParameters {
  BoreGeometry bore;
  double load = 0.0;                 // N, radial load W pressing each bearing half onto the journal
  int halves = 2;                    // 2: two opposite bearing halves (thesis ch. 5); 1: one contact
  double second_half_load = 0.0;     // N, load on the upper half; 0: = load (the thesis's symmetric set-up)
  double ramp_angle = 1.0;           // rad, drive rotation reached at ramp_time (linear from 0)
  double ramp_time = 2.0;            // s
  double run_speed = 0.0;            // rad/s of the drive after the ramp (0: drive stops)
  double inertia = 0.0;              // kg m^2, journal
  double coupling_stiffness = 0.0;   // N m/rad
  double coupling_damping = 0.0;     // N m s/rad
  double wear_coefficient = 0.0;     // Archard k (0: no wear)
  double hardness = 0.0;             // Pa, bore
  tribo::ArchardForm archard_form = tribo::ArchardForm::plain;

  void validate() const;  // throws std::invalid_argument naming the field
  double half_load(int half) const { return half == 1 && second_half_load > 0.0 ? second_half_load : load; }
  double drive_speed(double t) const;
  double drive_angle(double t) const;
};

// One bearing half's share of a sample (lower: index 0, upper: index 1).
struct JournalBearingHalfSample {
  double friction_torque = 0.0;   // N m; in stick the total in proportion to the halves' static limits
  double normal_force = 0.0;      // N, integral of this half's pressure
  double mu = 0.0;                // friction_torque / (normal_force R)
  double roughness = 0.0;         // this half's friction-law state
  double wear_volume = 0.0;       // m^3, this half's bore
  double contact_half_angle = 0.0;  // rad
  double peak_pressure = 0.0, mean_pressure = 0.0;  // Pa
  // state law only: mu_eff of this half (after the update at this sample), mean (over loaded nodes) and largest
  // worn depth h, the shaft's worn volume under this half (counterface_wear_rate)
  double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0, counterface_volume = 0.0;
  double film_coverage = 0.0;  // [film]: the bore's coverage, load-weighted over its nodes
};

// Totals over the bearing halves unless noted.
struct JournalBearingSample {
  double t = 0.0;
  double drive_angle = 0.0, drive_speed = 0.0, journal_speed = 0.0;  // rad, rad/s, rad/s
  double coupling_torque = 0.0;   // N m
  double friction_torque = 0.0;   // N m, resisting torque of the contact
  double friction_force = 0.0;    // N, friction_torque / R
  double normal_force = 0.0;      // N, integral of the pressure over the contact
  double mu = 0.0;                // mobilised F / N (stick: below mu_static)
  double mu_law = 0.0;            // law value at s without the speed term (lower half's state)
  double roughness = 0.0;         // friction-law state R (feedback model) of the lower half, 0 without one
  double sliding_speed = 0.0;     // m/s, R w
  double distance = 0.0;          // m, sliding distance s
  double wear_volume = 0.0;       // m^3, bore
  double contact_half_angle = 0.0;  // rad, largest of the halves
  double peak_pressure = 0.0, mean_pressure = 0.0;  // Pa; peak: largest of the halves, mean: over all loaded panels
  ContactState state = ContactState::Stick;
  int halves = 1;
  double mu_eff = 0.0;            // state law: normal-force-weighted mu_eff of the halves
  JournalBearingHalfSample half[2];  // [0] lower, [1] upper (only with halves = 2)
};

struct JournalBearingFrame {
  double t = 0.0;
  std::vector<double> pressure, wear_depth;  // per arc node, lower half
  std::vector<double> upper_pressure, upper_wear_depth;  // upper half (empty with one half)
  std::vector<double> mu, upper_mu;  // state law: mu(p_i, h_i) per node (h_i = wear depth); empty otherwise
};

struct JournalBearingRun {
  double t_end = 2.0;                 // s
  double output_interval = 1e-3;      // s
  std::vector<double> frame_times;    // s; a frame is taken at the first output sample at or after each
  double wear_step_fraction = 0.5;    // adaptive wear step = fraction * stable_slip_step(k_c)
  double fixed_wear_step = 0.0;       // m; > 0 replaces the adaptive step (for stability studies)
  CvodeIntegrator::Settings integrator;
  int max_events = 10000;

  void validate() const;
};

// The stick/slip loop's report plus the wear updates.
struct JournalBearingReport : SolveReport {
  long wear_updates = 0;
  double stable_wear_step = 0.0;  // m, 2H/(k k_c)
  // Per half (lower, upper): the contact pressure (Pa per arc node) of the unworn bore at the start and the
  // last solved one (worn bore) at the end, for the subsurface stress.
  std::vector<std::vector<double>> initial_pressure, final_pressure;
  std::optional<coupling::RangeUse> range_use;  // state law: lookups of all halves
  double state_law_static = 0.0;                // state law: normal-force-weighted static coefficient
};

class JournalBearingSystem {
 public:
  JournalBearingSystem(JournalBearingParameters parameters, SlidingFriction friction);

  const JournalBearingParameters &parameters() const { return p_; }
  const SlidingFriction &friction() const { return friction_; }
  const ConformalContact &contact() const { return contact_; }
  const tribo::ArchardWear &wear_law() const { return wear_; }
  double load_per_length(int half = 0) const { return p_.half_load(half) / p_.bore.axial_width; }

 private:
  JournalBearingParameters p_;
  SlidingFriction friction_;
  ConformalContact contact_;
  tribo::ArchardWear wear_;
};

using JournalBearingObserver = std::function<void(const JournalBearingSample &)>;
using JournalBearingFrameObserver = std::function<void(const JournalBearingFrame &)>;

// Numerical failure (CVODE, contact solver) is reported in the status; bad settings throw.
JournalBearingReport simulate(const JournalBearingSystem &system, const JournalBearingRun &run,
                              const JournalBearingObserver &observer,
                              const JournalBearingFrameObserver &frames = nullptr);

// Explicit Archard wear of the (lower half's) bore under a fixed load, without dynamics: `steps` updates of
// slip `ds` each (the pressure re-solved after every update). Returns the pressures after
// each update. Used for the wear-step stability study and the wear benchmark.
struct WearHistory {
  std::vector<std::vector<double>> pressure, wear;  // per update
  ConformalStatus status = ConformalStatus::Converged;
};
WearHistory wear_in(const JournalBearingSystem &system, double ds, int steps);

struct JournalBearingSummary {
  double peak_friction_force = 0.0, peak_time = 0.0;
  double breakaway_time = -1.0;  // -1: never broke away
  double start_friction_force = 0.0;  // largest |F| up to the first slip sample: mu_static N at break-away
  double steady_time = -1.0;     // -1: not steady
  double steady_mu = 0.0, steady_friction_force = 0.0, wear_volume = 0.0;
  double initial_peak_pressure = 0.0, final_peak_pressure = 0.0;
  double initial_half_angle = 0.0, final_half_angle = 0.0;
  static constexpr double steady_tolerance = 0.02;  // relative, on friction force and journal speed
};
// Steady from the first sample after which friction force and journal speed stay within
// steady_tolerance of their final values (speed band at least 1e-3 of the peak speed);
// "not steady" if that is in the last 10 % of the run.
JournalBearingSummary summarise(const std::vector<JournalBearingSample> &samples);

// Subsurface stress below one bearing half's contact (doc/subsurface_stress.md), plane strain, x = R theta
// along the bore (arc coordinate, centred on the load line), z the depth into each body. The bearing (body a)
// carries the friction shear q = mu p in +x (the shaft surface moving in +theta, mu > 0), the shaft (body b)
// -q; each body its own Poisson ratio and S_y.
// Influence tier on a solved nodal pressure (any wear profile):
LineContactStress bore_contact_stress(const ConformalContact &contact, const std::vector<double> &pressure, double mu,
                                      const tribo::Material &bearing, const tribo::Material &shaft, int points = 48);
// Each half's subsurface stress at the start and the end of a run (StartEndStress; `samples` and `report` of the
// run, `start_friction_force` its largest |F| up to the first slip sample). The shear's sign follows the journal's
// turning direction; the end mu is the half's |mu| (the total's when the half's is 0) of the last slip sample.
// Empty when the run has no samples or no pressures per half.
std::vector<StartEndStress> bore_start_end_stress(const JournalBearingParameters &p,
                                                  const std::vector<JournalBearingSample> &samples,
                                                  double start_friction_force, const JournalBearingReport &report,
                                                  const tribo::Material &bearing, const tribo::Material &shaft);
// McEwen's closed form on the Hertz line contact of the unworn bore (R_eff = R (R + c) / c, E* of the bore)
// under load_per_length.
LineContactStress bore_hertz_stress(const BoreGeometry &bore, double load_per_length, double mu,
                                    const tribo::Material &bearing, const tribo::Material &shaft, int points = 48);

}  // namespace runin::continuum
