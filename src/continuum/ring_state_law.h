// A piston ring on a homogenised state law (friction.model = "state_law", doc/state_law_continuum.md): the slow
// subsystem of the splitting driver (state_law_splitting.h) for one ring of a pack. The ring face's cells are the
// contact nodes (RingLinerWear with the law attached); a slow step slides the face over the liner along the
// interval that ends at the sample (the law's dh_i on the face cells, the counterface rate on the liner under it)
// and recomputes mu_eff at the new pressures.
#pragma once

#include <optional>
#include <vector>

#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#include "continuum/sliding_friction.h"
#include "continuum/state_law_splitting.h"

namespace runin::continuum {

class RingStateLaw final : public SlowSystem<PistonRingSample> {
 public:
  // `wear` has the law attached; samples are in the piston's coordinate with the ring's groove at
  // `groove_position` (ring_position includes it). `system` gives the initial position and load.
  RingStateLaw(RingLinerWear &wear, StateLawFriction &held, const PistonRingSystem &system, double groove_position);

  void start() override;                          // held static (mu_static or the law's peak) and kinetic mu_eff
  bool step(const PistonRingSample &s) override;  // slides from the previous sample when the ring moved on

  // What a sample reads after its step.
  struct State {
    ContactPressure contact;                      // of the face at the sample
    double ring_volume = 0.0, liner_volume = 0.0;  // m^3
    double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0;  // h_mean over the loaded cells
    double film_coverage = 0.0;                      // [film]: the face's, load-weighted
  };
  State state(const PistonRingSample &s) const;

 private:
  RingLinerWear &wear_;
  StateLawFriction &held_;
  double x0_ = 0.0, w0_ = 0.0;
  std::optional<PistonRingSample> prev_;
};

}  // namespace runin::continuum
