#include "continuum/ring_state_law.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace runin::continuum {

RingStateLaw::RingStateLaw(RingLinerWear &wear, StateLawFriction &held, const PistonRingSystem &system,
                           double groove_position)
    : wear_(wear), held_(held), x0_(system.piston_position(0.0) + groove_position), w0_(system.normal_load(0.0)) {}

void RingStateLaw::start() {
  held_.held_static = held_.mu_static ? *held_.mu_static : wear_.peak_mu(x0_, w0_);
  held_.held_kinetic = wear_.mu_effective(x0_, w0_);
}

bool RingStateLaw::step(const PistonRingSample &s) {
  bool changed = false;
  if (prev_ && s.distance > prev_->distance) {
    if (!wear_.slide(prev_->ring_position, s.ring_position, prev_->normal_load, s.normal_load,
                     std::max(s.t - prev_->t, 0.0))) {
      char at[32];
      std::snprintf(at, sizeof at, "%.6g", s.t);
      throw SlowStepError(SplitStatus::SlowFailure,
                          std::string(to_string(wear_.status())) + " at t = " + at + " s: " + wear_.message());
    }
    held_.held_kinetic = wear_.mu_effective(s.ring_position, s.normal_load);
    changed = true;
  }
  prev_ = s;
  return changed;
}

RingStateLaw::State RingStateLaw::state(const PistonRingSample &s) const {
  State row;
  row.contact = wear_.pressure(s.ring_position, s.normal_load);
  row.ring_volume = wear_.ring_volume();
  row.liner_volume = wear_.liner_volume();
  row.mu_eff = held_.held_kinetic;
  const auto &h = wear_.state_law()->state();
  int loaded = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    row.h_max = std::max(row.h_max, h[i]);
    if (row.contact.pressure[i] > 0.0) row.h_mean += h[i], ++loaded;
  }
  row.h_mean = loaded ? row.h_mean / loaded : 0.0;
  if (const NodeFilm *film = wear_.state_law()->film()) row.film_coverage = film->mean_coverage(row.contact.pressure);
  return row;
}

}  // namespace runin::continuum
