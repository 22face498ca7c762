#include "continuum/pin_on_disk_wear.h"

#include "tribo/number_format.h"

#include <algorithm>
#include <cmath>

namespace runin::continuum {
PinWearError::PinWearError(double t, const std::string &message)
    : std::runtime_error("pin wear at t = " + tribo::format_g(t) + " s: " + message), time(t) {}

DiskTrackSummary summarise(const DiskTrackWear &disk, double pin_depth) {
  DiskTrackSummary track;
  track.volume = disk.volume();
  track.depth = disk.depth();
  track.width = disk.track_width();
  track.length = disk.worn_length();
  track.passes = disk.passes();
  track.pin_depth = pin_depth;
  return track;
}

namespace {
PinFaceFrame face_frame(const PinWear &pin, double t) {
  PinFaceFrame f;
  f.time = t;
  for (int i = 0; i < pin.grid().rings(); ++i) {
    f.radius.push_back(pin.grid().ring_radius(i));
    f.height.push_back(pin.profile_height(i));
    f.pressure.push_back(pin.contact().pressure[i]);
    f.depth.push_back(pin.wear_depth()[i]);
  }
  return f;
}

// The disk's track after the pin's step at the sample `t`, and the largest groove depth / elastic approach.
void wear_disk(DiskTrackWear &disk, const PinWear &pin, double load, double distance, double t, PinWearRow &row,
               DiskTrackSummary &track) {
  const auto &contact = pin.contact();
  disk.slide(load, std::max(distance - disk.slid(), 0.0), 2.0 * contact.contact_radius);
  row.disk_wear_volume = disk.volume();
  row.disk_track_depth = disk.depth();
  // Elastic approach: the rigid approach beyond first touch of the (worn) profile, the scale of the gap
  // that sets the pressure. A groove much shallower than it leaves the pressure as solved on the flat.
  double touch = pin.profile_height(0);
  for (int i = 1; i < pin.grid().rings(); ++i) touch = std::min(touch, pin.profile_height(i));
  const double elastic = contact.approach - touch;
  if (elastic > 0.0 && disk.depth() / elastic > track.approach_ratio) {
    track.approach_ratio = disk.depth() / elastic;
    track.approach_ratio_time = t;
  }
}
}  // namespace

PinWearPass pin_wear_pass(const std::vector<PinOnDiskSample> &samples, const PinWearPassSettings &settings) {
  PinWearPass out;
  const double load = settings.load;
  PinWearParameters wp = settings.tip;
  wp.grid_radius = settings.grid_radius ? *settings.grid_radius
                                        : suggested_grid_radius(wp.tip_radius, wp.effective_modulus, load,
                                                                settings.wear ? &*settings.wear : nullptr,
                                                                samples.back().distance);
  out.grid_radius = wp.grid_radius;
  // Without a wear law the pin is worn at k = 0: contact only.
  const tribo::ArchardWear archard = settings.wear ? *settings.wear : tribo::ArchardWear(0.0, 1.0);
  PinWear pin(wp, archard, load);
  std::optional<DiskTrackWear> disk;
  if (settings.disk_wear) disk.emplace(*settings.disk_wear, settings.track_radius);
  DiskTrackSummary track;
  std::size_t next_frame = 0;
  std::vector<double> frame_times = settings.frame_times;
  std::sort(frame_times.begin(), frame_times.end());
  out.rows.reserve(samples.size());
  for (const auto &s : samples) {
    if (!pin.advance(std::max(s.distance - pin.slid(), 0.0))) throw PinWearError(s.t, pin.message());
    const auto &contact = pin.contact();
    PinWearRow row;
    row.wear_volume = pin.wear_volume();
    row.contact_radius = contact.contact_radius;
    row.peak_pressure = contact.peak_pressure;
    row.mean_pressure = contact.mean_pressure;
    if (disk) wear_disk(*disk, pin, load, s.distance, s.t, row, track);
    out.rows.push_back(row);
    for (; next_frame < frame_times.size() && s.t >= frame_times[next_frame] - 1e-12; ++next_frame)
      out.frames.push_back(face_frame(pin, s.t));
  }
  out.wear_steps = pin.steps();
  out.final_pressure = pin.contact().pressure;
  out.ring_width = pin.grid().ring_width();
  if (disk) {
    const DiskTrackSummary end = summarise(*disk, *std::max_element(pin.wear_depth().begin(), pin.wear_depth().end()));
    track.volume = end.volume, track.depth = end.depth, track.width = end.width, track.length = end.length;
    track.passes = end.passes, track.pin_depth = end.pin_depth;
    out.disk = track;
  }
  return out;
}

std::pair<ContactStress, ContactStress> pin_start_end_stress(const PinWearParameters &tip, double load,
                                                             double start_friction_force,
                                                             const std::vector<double> &final_pressure,
                                                             double ring_width, double final_mu,
                                                             const tribo::Material &pin, const tribo::Material &disk) {
  const auto hertz = hertz_sphere_on_flat(tip.tip_radius, tip.effective_modulus, load);
  const double mu_start = start_friction_force / load;
  return {hertz_contact_stress(hertz.peak_pressure, hertz.contact_radius, mu_start, pin, disk),
          ring_contact_stress(final_pressure, ring_width, std::abs(final_mu), pin, disk)};
}

}  // namespace runin::continuum
