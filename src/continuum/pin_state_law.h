// The pin-on-disk on a homogenised state law (friction.model = "state_law", doc/state_law_continuum.md): the slow
// subsystem of the splitting driver (state_law_splitting.h). The pin face is cut into rings, each a contact node with
// its own h_i: rings of the spherical tip (pressure from the elastic contact of the worn profile) or of a flat end
// (uniform nominal pressure W / pi a^2). A slow step slides the distance of the interval: the node states and the
// pin's worn profile advance by the law's wear_rate (the same dh_i: the law is the pin's only wear law), the disk
// by its counterface_wear_rate, in outer steps bounded by the pressure-wear stability of the tip; the contact is
// re-solved and mu_eff recomputed.
//
// run_pin_split drives it: at the output interval (split_run), or with adaptive wear steps under the speed drive
// (WearSteps: distance steps whose size is set by the change of mu_eff and of the node states).
#pragma once

#include <functional>
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

// The node states, the pin's worn face and the disk's track, and the held coefficients they set; with held.film a
// surface film on the nodes (NodeStateLaw::set_film; the disk's film exposed counterface_duty() of the time).
class PinStateLaw final : public SlowSystem<PinOnDiskSample> {
 public:
  // Throws std::invalid_argument when the tip's grid cannot hold the contact (raise the grid radius).
  PinStateLaw(const PinStateLawSettings &settings, StateLawFriction &held);

  // A disk film's duty (held.film): a point of the track is under the pin for the footprint's share of the track's
  // area, pi a^2 / (2 a 2 pi r) = a / (4 r).
  double counterface_duty() const { return std::min(1.0, contact_radius() / (4.0 * s_.track_radius)); }
  void start() override;                         // held static (mu_static or the law's peak) and kinetic mu_eff
  bool step(const PinOnDiskSample &s) override;  // the distance slid since the last step

  // What a sample reads after its step.
  struct State {
    double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0;  // h_mean over the loaded rings, area-weighted
    double wear_volume = 0.0;                        // m^3, sum h_i A_i (the pin's worn volume)
    double contact_radius = 0.0, peak_pressure = 0.0, mean_pressure = 0.0;
    double disk_wear_volume = 0.0, disk_track_depth = 0.0;
    double film_coverage = 0.0;                      // load-weighted mean theta of the film (0 without one)
  };
  State state() const;

  const AxisymmetricContact &grid() const { return pin_ ? pin_->grid() : *flat_grid_; }
  double grid_radius() const { return grid_radius_; }
  const std::vector<double> &pressure() const { return pin_ ? pin_->contact().pressure : uniform_; }
  double profile_height(int ring) const;  // the tip's worn profile; flat: h_i
  const NodeStateLaw &nodes() const { return nodes_; }
  const StateLawFriction &held() const { return held_; }
  const DiskTrackWear &disk() const { return disk_; }
  long wear_steps() const { return wear_steps_; }
  double smallest_node_area() const { return smallest_node_area_; }  // m^2, smallest loaded ring at the start

  // The slow state and the held kinetic coefficient, to take a rejected adaptive step back.
  struct Snapshot {
    std::optional<PinWear> pin;
    NodeStateLaw nodes;
    DiskTrackWear disk;
    double slid, t_now, held_kinetic;
    long wear_steps;
  };
  Snapshot save() const { return {pin_, nodes_, disk_, slid_, t_now_, held_.held_kinetic, wear_steps_}; }
  void restore(const Snapshot &s);

 private:
  void wear(double ds, double dt);
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

// How the slow steps are taken (doc/state_law_continuum.md, "Adaptive wear steps").
struct WearSteps {
  bool adaptive = false;  // false: one slow step per output interval (split_run)
  // Adaptive: a step is accepted when the relative change of mu_eff, and the change of every node's h inside the
  // law's depth range over that range's length, are both <= tolerance.
  double tolerance = 1e-3;
  double max_fraction = 1e-3;      // largest step / the distance of the quasi-static phase
  std::vector<double> stop_times;  // s: steps end exactly at these (VTK frames)
  long max_steps = 10000000;       // accepted + rejected quasi-static steps
  long dynamics_chunk = 10;        // torque drive: output intervals of full dynamics between steadiness checks

  void validate() const;  // throws std::invalid_argument naming the field
};

// Runs the pin's split. Fixed: split_run at run.output_interval (CVODE over each interval, mu_eff held).
// Adaptive, speed drive: the drive prescribes s(t), so the pin's dynamics are kinematic (F = (mu_eff + alpha V) W,
// plus J dw/dt on the ramp) and only the slow system is stepped, by distances set by the error control of `steps`,
// from t = 0 (the first try: the distance of the first output interval).
// Adaptive, torque drive (alpha > 0): the full dynamics (split_run at run.output_interval) over the ramp and in
// stretches of `dynamics_chunk` intervals wherever the pin may stick or would lag its quasi-static speed
// V_ss = (T / r - mu_eff W) / (alpha W) by more than the tolerance (the lag is tau dV_ss/dt, tau = m / (alpha W));
// quasi-static distance steps at V_ss(mu_eff) where it slides steadily.
// A sample is emitted after every accepted step, F/W being the coefficient held over it, as in split_run.
// Failures are statuses (SplitReport); bad settings (std::invalid_argument: a torque drive without alpha > 0, a
// bad tolerance) throw.
SplitReport run_pin_split(const PinOnDiskSystem &system, const PinOnDiskRun &run, PinStateLaw &pin,
                          const WearSteps &steps, const std::function<void(const PinOnDiskSample &)> &observer);

// Archard's invariant of a state-law run: worn volume / (K integral W ds), K = the law's rate / p at its lowest
// grid pressure and h = 0 (pin: wear_rate; disk: counterface_wear_rate).
struct ArchardRatios {
  double pin = 0.0, disk = 0.0;      // 0 when there was no sliding
  double k_pin = 0.0, k_disk = 0.0;  // 1/Pa
};
ArchardRatios archard_ratios(const coupling::StateLaw &law, double pin_volume, double disk_volume,
                             double load_distance);

}  // namespace runin::continuum
