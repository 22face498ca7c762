// Wear of the pin-on-disk along a computed run (doc/pin_on_disk.md): the pin's worn tip (PinWear: Archard wear
// and the elastic contact of the worn profile) and the disk's track (DiskTrackWear), driven by the sliding
// distance of each output sample. The coupling is one-way: none of the friction laws but the state law depends on
// the contact pressure (the state law is split: pin_state_law.h).
#pragma once

#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "continuum/axisymmetric_contact.h"
#include "continuum/pin_on_disk.h"
#include "tribo/wear.h"

namespace runin::continuum {

struct PinWearRow {  // at one output sample
  double wear_volume = 0.0, contact_radius = 0.0, peak_pressure = 0.0, mean_pressure = 0.0;
  double disk_wear_volume = 0.0, disk_track_depth = 0.0;  // 0 without disk wear
};

struct PinFaceFrame {  // the pin face at one time, per ring
  double time = 0.0;
  std::vector<double> radius, height, pressure, depth;
  std::vector<double> mu;  // state law: mu(p_i, h_i) per ring (h_i is `depth`); empty otherwise
};

// The disk's worn track at the end of a run, and how it compares with the contact it is left out of.
struct DiskTrackSummary {
  double volume = 0.0, depth = 0.0, width = 0.0, length = 0.0, passes = 0.0;
  double pin_depth = 0.0;            // m, largest wear depth of the pin face
  double approach_ratio = 0.0;       // max over the run of h_d / (elastic approach)
  double approach_ratio_time = 0.0;  // s, where that maximum is
};
DiskTrackSummary summarise(const DiskTrackWear &disk, double pin_depth);  // approach ratio left at 0

struct PinWearPassSettings {
  PinWearParameters tip;                        // tip radius, E*, rings, step safety, max steps
  std::optional<double> grid_radius;            // m; absent: suggested from Hertz and the Archard volume
  std::optional<tribo::ArchardWear> wear;       // the pin's; absent: contact only (worn at k = 0)
  std::optional<tribo::ArchardWear> disk_wear;  // the disk's track; absent: not worn
  double load = 0.0, track_radius = 0.0;        // N, m
  std::vector<double> frame_times;              // s: a face frame at the first sample at or after each
};

struct PinWearPass {
  std::vector<PinWearRow> rows;  // one per sample
  std::vector<PinFaceFrame> frames;
  long wear_steps = 0;
  double grid_radius = 0.0;              // m
  std::vector<double> final_pressure;    // Pa per ring at the end of the run (subsurface stress)
  double ring_width = 0.0;               // m
  std::optional<DiskTrackSummary> disk;  // with disk wear
};

// A wear step that failed at `time` (the contact did not converge, or the worn face left the grid).
struct PinWearError : std::runtime_error {
  PinWearError(double t, const std::string &message);
  double time;
};

// Throws std::invalid_argument when the grid cannot hold the unworn contact, PinWearError when a step fails.
PinWearPass pin_wear_pass(const std::vector<PinOnDiskSample> &samples, const PinWearPassSettings &settings);

// The tip's subsurface stress (doc/subsurface_stress.md) at the start, the unworn tip (Hertz, Hamilton's closed form,
// mu of break-away = start_friction_force / W), and at the end, the solved pressure of the worn profile (influence
// functions, the final |mu|).
std::pair<ContactStress, ContactStress> pin_start_end_stress(const PinWearParameters &tip, double load,
                                                             double start_friction_force,
                                                             const std::vector<double> &final_pressure,
                                                             double ring_width, double final_mu,
                                                             const tribo::Material &pin, const tribo::Material &disk);

}  // namespace runin::continuum
