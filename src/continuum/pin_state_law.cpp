#include "continuum/pin_state_law.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace runin::continuum {
namespace {
std::string g(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}
}  // namespace

PinStateLaw::PinStateLaw(const PinStateLawSettings &settings, StateLawFriction &held)
    : s_(settings), held_(held), nodes_(held.law, held.policy, 0), disk_(tribo::ArchardWear(0.0, 1.0), settings.track_radius) {
  if (s_.flat_radius) {
    flat_grid_.emplace(*s_.flat_radius, s_.tip.rings, s_.tip.effective_modulus);
    grid_radius_ = *s_.flat_radius;
  } else {
    PinWearParameters wp = s_.tip;
    // Grid size: Hertz, and the cap an Archard wear at the law's largest w/p would flatten over the run.
    double factor = 0.0;
    const auto &w = held.law->table(coupling::StateField::WearRate).mean;
    for (std::size_t i = 0; i < w.size(); ++i)
      for (double x : w[i]) factor = std::max(factor, x / held.law->pressure()[i]);
    const tribo::ArchardWear equivalent(factor, 1.0);
    wp.grid_radius = s_.grid_radius ? *s_.grid_radius
                                    : suggested_grid_radius(wp.tip_radius, wp.effective_modulus, s_.load, &equivalent,
                                                            s_.slid_estimate);
    grid_radius_ = wp.grid_radius;
    pin_.emplace(wp, tribo::ArchardWear(0.0, 1.0), s_.load);
  }
  const int n = grid().rings();
  area_.resize(n);
  for (int i = 0; i < n; ++i) area_[i] = grid().ring_area(i);
  for (double a : area_) flat_area_ += a;
  uniform_.assign(n, s_.load / flat_area_);
  for (int i = 0; i < n; ++i)
    if (pressure()[i] > 0.0 && (smallest_node_area_ == 0.0 || area_[i] < smallest_node_area_))
      smallest_node_area_ = area_[i];
  nodes_ = NodeStateLaw(held.law, held.policy, n);
}

void PinStateLaw::start() {
  held_.held_static = held_.mu_static ? *held_.mu_static : nodes_.peak_mu(pressure(), area_);
  held_.held_kinetic = nodes_.mu_effective(pressure(), area_);
}

bool PinStateLaw::step(const PinOnDiskSample &s) {
  t_now_ = s.t;
  const double ds = s.distance - slid_;
  if (!(ds > 0.0)) return false;
  wear(ds);
  slid_ = s.distance;
  held_.held_kinetic = nodes_.mu_effective(pressure(), area_);
  return true;
}

// Slides ds: outer steps bounded by the pressure-wear stability of the tip (flat: one step, p stays uniform).
void PinStateLaw::wear(double ds) {
  const int n = grid().rings();
  double remaining = ds;
  while (remaining > 0.0) {
    double step = remaining;
    if (pin_) {
      if (wear_steps_ >= s_.tip.max_steps)
        throw SlowStepError(SplitStatus::TooManySlowSteps, "pin wear at t = " + g(t_now_) + " s: more than " +
                                                               std::to_string(s_.tip.max_steps) + " wear updates");
      step = std::min(remaining, nodes_.stable_contact_step(pressure(), pin_->contact_stiffness(), s_.tip.step_safety));
      if (remaining - step < 1e-9 * ds) step = remaining;
    }
    const double width = 2.0 * contact_radius();
    const auto inc = nodes_.advance(pressure(), step);
    double volume = 0.0;
    for (int i = 0; i < n; ++i) volume += inc.counterface[i] * area_[i];
    disk_.slide_volume(volume, step, width);
    if (pin_ && !pin_->apply(inc.body, step))
      throw SlowStepError(SplitStatus::SlowFailure, "pin wear at t = " + g(t_now_) + " s: " + pin_->message());
    ++wear_steps_;
    remaining -= step;
  }
}

PinStateLaw::State PinStateLaw::state() const {
  State row;
  const auto &p = pressure();
  const auto &h = nodes_.state();
  double loaded = 0.0, volume = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    volume += h[i] * area_[i];
    if (p[i] > 0.0) {
      row.h_mean += h[i] * area_[i];
      loaded += area_[i];
    }
    row.h_max = std::max(row.h_max, h[i]);
  }
  row.h_mean = loaded > 0.0 ? row.h_mean / loaded : 0.0;
  row.mu_eff = held_.held_kinetic;
  row.wear_volume = volume;
  row.contact_radius = contact_radius();
  row.peak_pressure = *std::max_element(p.begin(), p.end());
  row.mean_pressure = pin_ ? pin_->contact().mean_pressure : s_.load / flat_area_;
  row.disk_wear_volume = disk_.volume();
  row.disk_track_depth = disk_.depth();
  return row;
}

double PinStateLaw::profile_height(int ring) const {
  return pin_ ? pin_->profile_height(ring) : nodes_.state()[static_cast<std::size_t>(ring)];
}

}  // namespace runin::continuum
