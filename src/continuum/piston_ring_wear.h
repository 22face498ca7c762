// Wear of a piston ring pack on its liner along computed runs (doc/piston_ring.md): the rings' samples on one
// time grid, the pack's sums, the one-way wear pass (Archard wear along the trajectory: wear changes the pressure
// distribution, not W or mu, so it does not feed back into the dynamics), and the state law's split run of one
// ring (ring_state_law.h), which does feed back.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "continuum/contact_stress.h"
#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#include "continuum/sliding_friction.h"
#include "continuum/state_law_splitting.h"

namespace runin::continuum {

struct RingWearRow {  // one ring at one sample
  double ring = 0.0, liner = 0.0, width = 0.0, peak = 0.0, mean = 0.0;  // m^3, m^3, m, Pa, Pa
  double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0;                       // state law only
  double film_coverage = 0.0;                                           // [film] only
};

// Profiles and pressures at one output time, for the VTK frames.
struct RingWearSnapshot {
  double time = 0.0, ring_position = 0.0;
  std::vector<double> liner_wear, liner_pressure, ring_wear, ring_pressure;
  std::vector<double> ring_mu;  // state law: mu(p_i, h_i) per face cell (h_i = ring_wear)
};
RingWearSnapshot snapshot(const RingLinerWear &wear, const PistonRingSample &s);

struct RingWearPass {  // one ring over the run
  std::vector<RingWearRow> rows;
  std::vector<RingWearSnapshot> snapshots;
  double initial_peak = 0.0;
  std::vector<double> initial_pressure, final_pressure;  // Pa per ring cell, first and last sample
};

// The rings' samples on one time grid: the union of their sample times (each ring's events are its samples), every
// ring linearly interpolated between its own samples (no event in between, so the ring moves monotonically and stays
// in one phase there). One ring: its own samples, unchanged.
std::vector<std::vector<PistonRingSample>> common_grid(const std::vector<const std::vector<PistonRingSample> *> &rings);
// The piston's friction: the rings' sums on the common grid (friction, land force, W; mean sliding speed; slip if any
// ring slips). One ring: its own samples.
std::vector<PistonRingSample> pack_samples(const std::vector<std::vector<PistonRingSample>> &grid);

// A wear step of ring `ring` that failed at `time`: the ring left the liner grid, or a wear depth passed its limit.
struct RingWearError : std::runtime_error {
  enum class Kind { LeftTheLiner, WornThrough };
  RingWearError(Kind k, std::size_t r, double t, const std::string &what) : std::runtime_error(what), kind(k), ring(r), time(t) {}
  Kind kind;
  std::size_t ring;
  double time;
};

// The one-way wear pass: all rings slide sample by sample on the common grid (they share the liner, so they wear it
// in time order); a snapshot at the first sample at or after each of `frame_times`. Throws RingWearError.
std::vector<RingWearPass> ring_wear_pass(std::vector<RingLinerWear> &wear,
                                         const std::vector<std::vector<PistonRingSample>> &rings,
                                         const std::vector<double> &frame_times);

// Wear run-in (crank motion): per cycle the largest peak contact pressure; settled from the first cycle after which
// every cycle's value is within 1 % of the last full cycle's. -1: not settled (or ramp motion).
double pressure_settling_time(const PistonRingParameters &p, const std::vector<PistonRingSample> &samples,
                              const std::vector<RingWearRow> &rows);

// A ring face's subsurface stress at the start and the end (StartEndStress): `samples` are the ring's on the common
// grid, `start_friction_force` the largest |F| up to the first slip sample, the pressures the pass's first and last.
StartEndStress ring_face_start_end_stress(const RingLinerWear &wear, const std::vector<PistonRingSample> &samples,
                                          double start_friction_force, const std::vector<double> &initial_pressure,
                                          const std::vector<double> &final_pressure, const tribo::Material &liner,
                                          const tribo::Material &ring);

// One ring on the state law, split (state_law_splitting.h): its dynamics and its face/liner wear advance together.
struct RingStateLawRun {
  SplitReport report;
  std::vector<PistonRingSample> samples;  // the ring's own samples, ring_position with the groove position
  RingWearPass pass;                      // rows per own sample
  double mu_static = 0.0;                 // the held static coefficient
};
// `wear` has the law attached; `held` is the one `system`'s friction holds.
RingStateLawRun simulate_state_law(const PistonRingSystem &system, const PistonRingRun &run, RingLinerWear &wear,
                                   StateLawFriction &held, double groove_position, const std::vector<double> &frame_times);

}  // namespace runin::continuum
