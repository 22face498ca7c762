// The pin-on-disk on a homogenised state law (friction.model = "state_law", doc/state_law_continuum.md): the slow
// subsystem of the splitting driver (state_law_splitting.h). The pin face is cut into rings, each a contact node with
// its own h_i: rings of the spherical tip (pressure from the elastic contact of the worn profile) or of a flat end
// (uniform nominal pressure W / pi a^2). A slow step slides the distance of the interval: the node states and the
// pin's worn profile advance by the law's wear_rate (the same dh_i: the law is the pin's only wear law), the disk
// by its counterface_wear_rate, in outer steps bounded by the pressure-wear stability of the tip; the contact is
// re-solved and mu_eff recomputed.
#pragma once

#include <optional>
#include <vector>

#include "continuum/axisymmetric_contact.h"
#include "continuum/node_state_law.h"
#include "continuum/pin_on_disk.h"
#include "continuum/sliding_friction.h"
#include "continuum/state_law_splitting.h"

namespace runin::continuum {

struct PinStateLawSettings {
  std::optional<double> flat_radius;  // m: a flat end of this radius; absent: the spherical tip of `tip`
  PinWearParameters tip;              // tip radius, E*, rings, step safety, max wear steps (flat: rings and E*)
  std::optional<double> grid_radius;  // m, of the tip's grid; absent: suggested for the law's largest w/p
  double load = 0.0;                  // N
  double track_radius = 0.0;          // m, of the disk's track
  double slid_estimate = 0.0;         // m, the run's sliding distance for the suggested grid (0: unknown)
};

// The node states, the pin's worn face and the disk's track, and the held coefficients they set.
class PinStateLaw final : public SlowSystem<PinOnDiskSample> {
 public:
  // Throws std::invalid_argument when the tip's grid cannot hold the contact (raise the grid radius).
  PinStateLaw(const PinStateLawSettings &settings, StateLawFriction &held);

  void start() override;                         // held static (mu_static or the law's peak) and kinetic mu_eff
  bool step(const PinOnDiskSample &s) override;  // the distance slid since the last step

  // What a sample reads after its step.
  struct State {
    double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0;  // h_mean over the loaded rings, area-weighted
    double wear_volume = 0.0;                        // m^3, sum h_i A_i (the pin's worn volume)
    double contact_radius = 0.0, peak_pressure = 0.0, mean_pressure = 0.0;
    double disk_wear_volume = 0.0, disk_track_depth = 0.0;
  };
  State state() const;

  const AxisymmetricContact &grid() const { return pin_ ? pin_->grid() : *flat_grid_; }
  double grid_radius() const { return grid_radius_; }
  const std::vector<double> &pressure() const { return pin_ ? pin_->contact().pressure : uniform_; }
  double profile_height(int ring) const;  // the tip's worn profile; flat: h_i
  const NodeStateLaw &nodes() const { return nodes_; }
  const DiskTrackWear &disk() const { return disk_; }
  long wear_steps() const { return wear_steps_; }
  double smallest_node_area() const { return smallest_node_area_; }  // m^2, smallest loaded ring at the start

 private:
  void wear(double ds);
  double contact_radius() const { return pin_ ? pin_->contact().contact_radius : *s_.flat_radius; }

  PinStateLawSettings s_;
  StateLawFriction &held_;
  std::optional<PinWear> pin_;
  std::optional<AxisymmetricContact> flat_grid_;
  double grid_radius_ = 0.0, flat_area_ = 0.0, smallest_node_area_ = 0.0;
  std::vector<double> area_, uniform_;
  NodeStateLaw nodes_;
  DiskTrackWear disk_;
  double slid_ = 0.0, t_now_ = 0.0;
  long wear_steps_ = 0;
};

}  // namespace runin::continuum
