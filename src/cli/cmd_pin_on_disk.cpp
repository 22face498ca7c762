#include "cli/cmd_pin_on_disk.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <tuple>

#include <fmt/core.h>

#include "cli/case_file.h"
#include "cli/line_stress_report.h"
#include "cli/run_summary.h"
#include "cli/staged_file.h"
#include "continuum/axisymmetric_contact.h"
#include "continuum/node_state_law.h"
#include "continuum/pin_on_disk.h"
#include "coupling/scale_separation.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

// The pin's wear stepper settings from [contact] (the grid radius is the caller's: it depends on the wear law).
continuum::PinWearParameters pin_wear_parameters(const PinContactCase &k) {
  continuum::PinWearParameters wp;
  wp.tip_radius = k.tip_radius;
  wp.effective_modulus = k.effective_modulus();
  wp.rings = k.rings;
  wp.step_safety = k.step_safety;
  wp.max_steps = k.max_wear_steps;
  return wp;
}

namespace fs = std::filesystem;
using continuum::PinOnDiskSample;

struct Row {
  PinOnDiskSample s;
  double wear_volume = 0.0, contact_radius = 0.0, peak_pressure = 0.0, mean_pressure = 0.0;
  double disk_wear_volume = 0.0, disk_track_depth = 0.0;  // 0 without wear.disk_k
  double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0;         // friction.model = "state_law" only
};

// The disk's worn track at the end of a run, and how it compares with the contact it is left out of.
struct DiskTrack {
  double volume = 0.0, depth = 0.0, width = 0.0, length = 0.0, passes = 0.0;
  double pin_depth = 0.0;            // m, largest wear depth of the pin face
  double approach_ratio = 0.0;       // max over the run of h_d / (elastic approach)
  double approach_ratio_time = 0.0;  // s, where that maximum is
};

struct Frame {  // pin face at one time, for VTK
  double time;
  std::vector<double> radius, height, pressure, depth;
  std::vector<double> mu;  // state law: mu(p_i, h_i) per ring (h_i is `depth`)
};

struct Curve {
  std::vector<Row> rows;
  continuum::SolveReport report;
  continuum::PinOnDiskSummary summary;
  std::vector<Frame> frames;
  long wear_steps = 0;
  double grid_radius = 0.0;
  std::vector<double> final_pressure;  // Pa per ring at the end of the run (subsurface stress)
  double ring_width = 0.0;
  std::optional<DiskTrack> disk;  // with wear.disk_k
  std::optional<coupling::RangeUse> range_use;  // friction.model = "state_law"
  double smallest_node_area = 0.0;  // m^2, smallest loaded ring of the pin face at the start (state law)
};

Curve run_state_law_case(const PinOnDiskCase &c, bool with_frames);

// Dynamics first (CVODE), then the wear stepper driven by the sliding distance of each output
// sample. The coupling is one-way: none of the friction laws depends on contact pressure.
Curve run_case(const PinOnDiskCase &c, bool with_frames) {
  if (c.friction->state_law()) return run_state_law_case(c, with_frames);
  Curve curve;
  const continuum::PinOnDiskSystem system(c.parameters, *c.friction);
  std::vector<PinOnDiskSample> samples;
  curve.report = continuum::simulate(system, c.run, [&](const PinOnDiskSample &s) { samples.push_back(s); });
  if (!curve.report.ok()) {
    std::string message = std::string(continuum::to_string(curve.report.status)) + ": " + curve.report.message;
    // Friction falling with speed under a held torque: V grows without bound (thesis eq. 4.5, minus sign).
    const std::size_t n = samples.size();
    if (message.find("[CV_TOO_MUCH_WORK]") != std::string::npos && c.friction->speed_coefficient() < 0.0 && n >= 2 &&
        samples[n - 1].speed > samples[n - 2].speed && samples[n - 1].speed > 0.0)
      message = fmt::format(
          "CVODE could not advance past t = {:.6g} s (too much work): the sliding speed runs away under "
          "velocity-weakening friction (alpha < 0; V = {:.4g} m/s at t = {:.6g} s and rising)",
          curve.report.end_time, samples[n - 1].speed, samples[n - 1].t);
    throw std::runtime_error(message);
  }
  curve.summary = continuum::summarise(samples);
  curve.rows.reserve(samples.size());
  for (const auto &s : samples) curve.rows.push_back({s});
  if (!c.contact) return curve;

  const auto &k = *c.contact;
  const double load = c.parameters.normal_load;
  continuum::PinWearParameters wp = pin_wear_parameters(k);
  wp.grid_radius = k.grid_radius ? *k.grid_radius
                                 : continuum::suggested_grid_radius(wp.tip_radius, wp.effective_modulus, load,
                                                                    k.wear ? &*k.wear : nullptr,
                                                                    samples.back().distance);
  curve.grid_radius = wp.grid_radius;
  // Without [wear] the pin is worn at k = 0: contact only.
  const tribo::ArchardWear archard = k.wear ? *k.wear : tribo::ArchardWear(0.0, 1.0);
  std::optional<continuum::PinWear> pin;
  try {
    pin.emplace(wp, archard, load);
  } catch (const std::invalid_argument &e) {
    throw std::runtime_error(std::string(e.what()) + " (raise contact.grid_radius)");
  }
  std::optional<continuum::DiskTrackWear> disk;
  if (k.disk_wear) disk.emplace(*k.disk_wear, c.parameters.track_radius);
  DiskTrack track;
  std::size_t next_frame = 0;
  std::vector<double> frame_times = c.vtk_times;
  std::sort(frame_times.begin(), frame_times.end());
  for (auto &row : curve.rows) {
    if (!pin->advance(std::max(row.s.distance - pin->slid(), 0.0)))
      throw std::runtime_error(fmt::format("pin wear at t = {:g} s: {}{}", row.s.t, pin->message(),
                                           pin->message().find("edge of the grid") != std::string::npos
                                               ? " (raise contact.grid_radius)"
                                               : ""));
    const auto &contact = pin->contact();
    row.wear_volume = pin->wear_volume();
    row.contact_radius = contact.contact_radius;
    row.peak_pressure = contact.peak_pressure;
    row.mean_pressure = contact.mean_pressure;
    if (disk) {
      disk->slide(load, std::max(row.s.distance - disk->slid(), 0.0), 2.0 * contact.contact_radius);
      row.disk_wear_volume = disk->volume();
      row.disk_track_depth = disk->depth();
      // Elastic approach: the rigid approach beyond first touch of the (worn) profile, the scale of the gap
      // that sets the pressure. A groove much shallower than it leaves the pressure as solved on the flat.
      double touch = pin->profile_height(0);
      for (int i = 1; i < pin->grid().rings(); ++i) touch = std::min(touch, pin->profile_height(i));
      const double elastic = contact.approach - touch;
      if (elastic > 0.0 && disk->depth() / elastic > track.approach_ratio) {
        track.approach_ratio = disk->depth() / elastic;
        track.approach_ratio_time = row.s.t;
      }
    }
    while (with_frames && next_frame < frame_times.size() && row.s.t >= frame_times[next_frame] - 1e-12) {
      Frame f{row.s.t, {}, {}, {}, {}, {}};
      for (int i = 0; i < pin->grid().rings(); ++i) {
        f.radius.push_back(pin->grid().ring_radius(i));
        f.height.push_back(pin->profile_height(i));
        f.pressure.push_back(contact.pressure[i]);
        f.depth.push_back(pin->wear_depth()[i]);
      }
      curve.frames.push_back(std::move(f));
      ++next_frame;
    }
  }
  curve.wear_steps = pin->steps();
  curve.final_pressure = pin->contact().pressure;
  curve.ring_width = pin->grid().ring_width();
  if (disk) {
    track.volume = disk->volume();
    track.depth = disk->depth();
    track.width = disk->track_width();
    track.length = disk->worn_length();
    track.passes = disk->passes();
    track.pin_depth = *std::max_element(pin->wear_depth().begin(), pin->wear_depth().end());
    curve.disk = track;
  }
  return curve;
}

// friction.model = "state_law" (doc/state_law_continuum.md): two-way coupling by operator splitting at
// the output interval. CVODE integrates one interval with mu_eff held; after it, the node states h_i and the
// pin's worn profile advance by the distance slid (the same dh_i: the law's wear_rate is the pin's only wear
// law), the disk by the law's counterface_wear_rate, the contact pressure is re-solved, mu_eff recomputed and
// CVODE restarted.
Curve run_state_law_case(const PinOnDiskCase &c, bool with_frames) {
  auto *law = c.friction->state_law();
  const auto &k = *c.contact;
  const double load = c.parameters.normal_load;
  Curve curve;

  // Geometry: rings of the spherical tip (elastic solve) or of the flat end (uniform nominal pressure).
  std::optional<continuum::PinWear> pin;
  std::optional<continuum::AxisymmetricContact> flat_grid;
  if (k.flat) {
    flat_grid.emplace(k.flat_radius, k.rings, k.effective_modulus());
  } else {
    continuum::PinWearParameters wp = pin_wear_parameters(k);
    // Grid size: Hertz, and the cap an Archard wear at the law's largest w/p would flatten over the run.
    double factor = 0.0;
    const auto &w = law->law->table(coupling::StateField::WearRate).mean;
    for (std::size_t i = 0; i < w.size(); ++i)
      for (double x : w[i]) factor = std::max(factor, x / law->law->pressure()[i]);
    const double slid_estimate =
        c.parameters.drive == continuum::PinDrive::Speed ? c.parameters.sliding_speed * c.run.t_end : 0.0;
    const tribo::ArchardWear equivalent(factor, 1.0);
    wp.grid_radius = k.grid_radius ? *k.grid_radius
                                   : continuum::suggested_grid_radius(wp.tip_radius, wp.effective_modulus, load,
                                                                      &equivalent, slid_estimate);
    curve.grid_radius = wp.grid_radius;
    try {
      pin.emplace(wp, tribo::ArchardWear(0.0, 1.0), load);
    } catch (const std::invalid_argument &e) {
      throw std::runtime_error(std::string(e.what()) + " (raise contact.grid_radius)");
    }
  }
  const continuum::AxisymmetricContact &grid = pin ? pin->grid() : *flat_grid;
  if (k.flat) curve.grid_radius = k.flat_radius;
  const int n = grid.rings();
  std::vector<double> area(n);
  for (int i = 0; i < n; ++i) area[i] = grid.ring_area(i);
  double flat_area = 0.0;
  for (double a : area) flat_area += a;
  const std::vector<double> uniform(n, load / flat_area);
  auto pressure = [&]() -> const std::vector<double> & { return pin ? pin->contact().pressure : uniform; };
  for (int i = 0; i < n; ++i)
    if (pressure()[i] > 0.0 && (curve.smallest_node_area == 0.0 || area[i] < curve.smallest_node_area))
      curve.smallest_node_area = area[i];
  auto contact_radius = [&] { return pin ? pin->contact().contact_radius : k.flat_radius; };

  continuum::NodeStateLaw nodes(law->law, law->policy, n);
  continuum::DiskTrackWear disk(tribo::ArchardWear(0.0, 1.0), c.parameters.track_radius);
  double slid = 0.0, disk_volume = 0.0;
  long wear_steps = 0;
  double t_now = 0.0;
  auto where = [&](const std::exception &e) {
    return std::runtime_error(fmt::format("state law at t = {:g} s: {}{}", t_now, e.what(),
                                          law->policy == coupling::OutOfRange::Error &&
                                                  dynamic_cast<const std::out_of_range *>(&e)
                                              ? " (friction.out_of_range = \"archard\" takes friction at the nearest grid pressure, keeps "
 "wear proportional to p and counts it)"
                                              : ""));
  };
  try {
    law->held_static = law->mu_static ? *law->mu_static : nodes.peak_mu(pressure(), area);
    law->held_kinetic = nodes.mu_effective(pressure(), area);
  } catch (const std::exception &e) {
    throw where(e);
  }

  // Slides ds: outer steps bounded by the pressure-wear stability of the tip (flat: one step, p stays uniform).
  auto wear = [&](double ds) {
    double remaining = ds;
    while (remaining > 0.0) {
      double step = remaining;
      if (pin) {
        if (wear_steps >= k.max_wear_steps)
          throw std::runtime_error(fmt::format("pin wear at t = {:g} s: more than {} wear updates; raise "
                                               "wear.max_steps or lower contact.rings", t_now, k.max_wear_steps));
        step = std::min(remaining, nodes.stable_contact_step(pressure(), pin->contact_stiffness(), k.step_safety));
        if (remaining - step < 1e-9 * ds) step = remaining;
      }
      const double width = 2.0 * contact_radius();
      const auto inc = nodes.advance(pressure(), step);
      double volume = 0.0;
      for (int i = 0; i < n; ++i) volume += inc.counterface[i] * area[i];
      disk.slide_volume(volume, step, width);
      disk_volume += volume;
      if (pin && !pin->apply(inc.body, step))
        throw std::runtime_error(fmt::format("pin wear at t = {:g} s: {}{}", t_now, pin->message(),
                                             pin->message().find("edge of the grid") != std::string::npos
                                                 ? " (raise contact.grid_radius)"
                                                 : ""));
      ++wear_steps;
      remaining -= step;
    }
  };

  bool changed = false;
  std::size_t next_frame = 0;
  std::vector<double> frame_times = c.vtk_times;
  std::sort(frame_times.begin(), frame_times.end());
  std::vector<PinOnDiskSample> samples;
  const continuum::PinOnDiskSystem system(c.parameters, *c.friction);
  auto observer = [&](const PinOnDiskSample &s) {
    t_now = s.t;
    samples.push_back(s);
    Row row{s};
    try {
      const double ds = s.distance - slid;
      if (ds > 0.0) {
        wear(ds);
        slid = s.distance;
        law->held_kinetic = nodes.mu_effective(pressure(), area);
        changed = true;
      }
    } catch (const std::out_of_range &e) {
      throw where(e);
    } catch (const std::invalid_argument &e) {
      throw where(e);
    }
    const auto &p = pressure();
    const auto &h = nodes.state();
    double loaded = 0.0, volume = 0.0;
    for (int i = 0; i < n; ++i) {
      volume += h[i] * area[i];
      if (p[i] > 0.0) {
        row.h_mean += h[i] * area[i];
        loaded += area[i];
      }
      row.h_max = std::max(row.h_max, h[i]);
    }
    row.h_mean = loaded > 0.0 ? row.h_mean / loaded : 0.0;
    row.mu_eff = law->held_kinetic;
    row.wear_volume = volume;
    row.contact_radius = contact_radius();
    row.peak_pressure = *std::max_element(p.begin(), p.end());
    row.mean_pressure = pin ? pin->contact().mean_pressure : load / flat_area;
    row.disk_wear_volume = disk.volume();
    row.disk_track_depth = disk.depth();
    curve.rows.push_back(row);
    while (with_frames && next_frame < frame_times.size() && s.t >= frame_times[next_frame] - 1e-12) {
      Frame f{s.t, {}, {}, {}, {}, nodes.node_mu(p)};
      for (int i = 0; i < n; ++i) {
        f.radius.push_back(grid.ring_radius(i));
        f.height.push_back(pin ? pin->profile_height(i) : h[i]);
        f.pressure.push_back(p[i]);
        f.depth.push_back(h[i]);
      }
      curve.frames.push_back(std::move(f));
      ++next_frame;
    }
  };
  auto refresh = [&] {
    const bool was = changed;
    changed = false;
    return was;
  };
  curve.report = continuum::simulate(system, c.run, observer, refresh);
  if (!curve.report.ok())
    throw std::runtime_error(std::string(continuum::to_string(curve.report.status)) + ": " + curve.report.message);
  curve.summary = continuum::summarise(samples);
  curve.wear_steps = wear_steps;
  curve.final_pressure = pressure();
  curve.ring_width = grid.ring_width();
  curve.range_use = nodes.use();
  DiskTrack track;
  track.volume = disk.volume();
  track.depth = disk.depth();
  track.width = disk.track_width();
  track.length = disk.worn_length();
  track.passes = disk.passes();
  track.pin_depth = *std::max_element(nodes.state().begin(), nodes.state().end());
  curve.disk = track;
  return curve;
}

std::string csv_text(const std::vector<Row> &rows, bool state_law) {
  std::string text =
      "t_s,applied_torque_N_m,friction_force_N,friction_torque_N_m,mu,speed_m_s,sliding_distance_m,state_slip,"
      "mu_law,roughness,wear_volume_m3,contact_radius_m,peak_pressure_Pa,mean_pressure_Pa,disk_wear_volume_m3,"
      "disk_track_depth_m";
  text += state_law ? ",mu_eff,h_mean_m,h_max_m\n" : "\n";
  for (const auto &r : rows) {
    const auto &s = r.s;
    text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{},{:.12g},{:.12g},{:.12g},{:.12g},"
                        "{:.12g},{:.12g},{:.12g},{:.12g}\n",
                        s.t, s.applied_torque, s.friction_force, s.friction_torque, s.mu, s.speed, s.distance,
                        s.state == continuum::ContactState::Slip ? 1 : 0, s.mu_law, s.roughness, r.wear_volume,
                        r.contact_radius, r.peak_pressure, r.mean_pressure, r.disk_wear_volume, r.disk_track_depth);
    if (state_law) {
      text.pop_back();
      text += fmt::format(",{:.12g},{:.12g},{:.12g}\n", r.mu_eff, r.h_mean, r.h_max);
    }
  }
  return text;
}

// Subsurface stress at the start (unworn tip: Hertz, Hamilton's closed form, mu of break-away) and at the end
// (solved pressure of the worn profile: influence functions, the final mu). doc/subsurface_stress.md.
struct StressFrame {
  double time;
  continuum::ContactStress stress;
};
std::vector<StressFrame> subsurface_stress(const PinOnDiskCase &c, const Curve &curve) {
  std::vector<StressFrame> frames;
  if (!c.contact || c.contact->flat) return frames;  // flat end: no Hertz start, nominal pressure only
  const auto &k = *c.contact;
  const double load = c.parameters.normal_load;
  const auto hertz = continuum::hertz_sphere_on_flat(k.tip_radius, k.effective_modulus(), load);
  const double mu_start = curve.summary.start_friction_force / load;
  frames.push_back({curve.rows.front().s.t, continuum::hertz_contact_stress(hertz.peak_pressure, hertz.contact_radius,
                                                                            mu_start, k.pin, k.disk)});
  const double mu_end = std::abs(curve.rows.back().s.mu);
  frames.push_back({curve.rows.back().s.t, continuum::ring_contact_stress(curve.final_pressure, curve.ring_width,
                                                                          mu_end, k.pin, k.disk)});
  return frames;
}

#ifdef RUNIN_HAVE_VTK
// Section y = 0 below the contact: points (x, 0, -depth), one frame per stress evaluation, each body's
// von Mises and Tresca stress and the disk's tensor.
std::vector<std::string> write_stress(const std::vector<StressFrame> &frames, const fs::path &dir) {
  std::vector<coupling::SurfaceFrame> out;
  for (const auto &f : frames) {
    const auto &disk = f.stress.disk.field, &pin = f.stress.pin.field;
    coupling::SurfaceFrame s = section_frame(f.time, disk);
    std::vector<double> xx, yy, zz, yz, xz, xy;
    for (const auto &t : disk.stress) {
      xx.push_back(t.xx), yy.push_back(t.yy), zz.push_back(t.zz);
      yz.push_back(t.yz), xz.push_back(t.xz), xy.push_back(t.xy);
    }
    s.fields = {{"von_mises_disk_Pa", disk.von_mises()}, {"tresca_disk_Pa", disk.tresca()},
                {"von_mises_pin_Pa", pin.von_mises()},   {"tresca_pin_Pa", pin.tresca()},
                {"sigma_xx_disk_Pa", xx}, {"sigma_yy_disk_Pa", yy}, {"sigma_zz_disk_Pa", zz},
                {"sigma_yz_disk_Pa", yz}, {"sigma_xz_disk_Pa", xz}, {"sigma_xy_disk_Pa", xy}};
    out.push_back(std::move(s));
  }
  return coupling::write_surface_series(out, dir.string(), "subsurface");
}

// Revolved pin face: radius x angle grid, z = height of the worn tip profile above its apex.
std::vector<std::string> write_frames(const std::vector<Frame> &frames, const fs::path &dir) {
  constexpr int angles = 49;  // 7.5 degree steps, closed
  std::vector<coupling::SurfaceFrame> out;
  for (const auto &f : frames) {
    coupling::SurfaceFrame s;
    s.time = f.time;
    s.nu = static_cast<int>(f.radius.size());
    s.nv = angles;
    std::vector<double> pressure, depth;
    for (int j = 0; j < angles; ++j) {
      const double theta = 2.0 * M_PI * j / (angles - 1);
      for (int i = 0; i < s.nu; ++i) {
        s.points.push_back({f.radius[i] * std::cos(theta), f.radius[i] * std::sin(theta), f.height[i]});
        pressure.push_back(f.pressure[i]);
        depth.push_back(f.depth[i]);
      }
    }
    s.fields = {{"pressure_Pa", pressure}, {"wear_depth_m", depth}};
    if (!f.mu.empty()) {  // state law: h_i is the wear depth; mu(p_i, h_i) per ring
      std::vector<double> mu;
      for (int j = 0; j < angles; ++j) mu.insert(mu.end(), f.mu.begin(), f.mu.end());
      s.fields.push_back({"h_m", depth});
      s.fields.push_back({"mu", mu});
    }
    out.push_back(std::move(s));
  }
  return coupling::write_surface_series(out, dir.string(), "pin_face");
}
#endif

// Track depth / elastic approach above which the groove left out of the contact solve is reported.
constexpr double kGrooveTolerance = 0.05;

std::string or_none(double t) { return t < 0.0 ? std::string("none") : fmt::format("{:.6g} s", t); }

}  // namespace

CLI::App *add_pin_on_disk_command(CLI::App &app, PinOnDiskOptions &o) {
  auto *cmd = app.add_subcommand("pin-on-disk", "Pin-on-disk run-in curve with contact and wear (thesis ch. 4)");
  cmd->add_option("case", o.case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  cmd->add_option("--law", o.law_path,
                  "law file: from fit-law (friction.model = \"law_file\"), or from homogenise (\"state_law\", overrides friction.law)");
  cmd->add_option("--output-dir", o.output_dir,
                  "directory for pin_on_disk.csv/.png, pin_face_*.vts/.pvd and the mu0 sweep files")
      ->required()
      ->check(output_directory());
  cmd->add_flag("--no-plot", o.no_plot, "write the CSV (and VTK) only");
  return cmd;
}

int run_pin_on_disk(const PinOnDiskOptions &o, const PlotRunner &plot) {
  const PinOnDiskCase c = read_pin_on_disk_case(o.case_path, o.law_path);
#ifndef RUNIN_HAVE_VTK
  if (!c.vtk_times.empty())
    throw std::runtime_error("output.vtk_times: this runin was built without VTK (configure with -DRUNIN_WITH_VTK=ON)");
#endif
  const Curve curve = run_case(c, true);
  struct SweepRun {
    double mu0, torque;
    Curve curve;
  };
  std::vector<SweepRun> sweep;
  for (double mu0 : c.sweep_mu0) {
    const PinOnDiskCase variant = with_mu0(c, mu0);
    sweep.push_back({mu0, variant.parameters.applied_torque, run_case(variant, false)});
  }

  // Everything is computed; the output set is staged and moved in only when complete.
  StagedOutput out(o.output_dir, {"pin_on_disk.csv", "pin_on_disk_summary.csv", "pin_on_disk.png", "pin_on_disk_mu0.csv", "pin_on_disk_mu0.png",
                                  "pin_on_disk_mu0_summary.csv", "pin_face.pvd", "pin_face_*.vts", "subsurface.pvd",
                                  "subsurface_*.vts"});
  const std::vector<StressFrame> stress = subsurface_stress(c, curve);
  out.write("pin_on_disk.csv", csv_text(curve.rows, c.friction->state_law() != nullptr));
  {
    const auto &m = curve.summary;
    out.write("pin_on_disk_summary.csv",
              std::string(kRunSummaryHeader) + "\n" +
                  run_summary_row({m.peak_friction_force, m.peak_time, m.breakaway_time, m.steady_time, m.steady_mu,
                                   curve.rows.back().wear_volume}) +
                  "\n");
  }
  std::vector<std::string> written = {"pin_on_disk.csv", "pin_on_disk_summary.csv"};
  if (!sweep.empty()) {
    std::string curves = "mu0,t_s,friction_force_N,mu,speed_m_s,sliding_distance_m,wear_volume_m3\n";
    std::string table =
        "mu0,applied_torque_N_m,breakaway_s,peak_friction_force_N,peak_time_s,steady_time_s,steady_mu,"
        "wear_volume_m3\n";
    for (const auto &run : sweep) {
      for (const auto &r : run.curve.rows)
        curves += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", run.mu0, r.s.t,
                              r.s.friction_force, r.s.mu, r.s.speed, r.s.distance, r.wear_volume);
      const auto &s = run.curve.summary;
      table += fmt::format("{:.12g},{:.12g},{},{:.12g},{:.12g},{},{:.12g},{:.12g}\n", run.mu0, run.torque,
                           time_cell(s.breakaway_time), s.peak_friction_force, s.peak_time, time_cell(s.steady_time),
                           s.steady_mu, run.curve.rows.back().wear_volume);
    }
    out.write("pin_on_disk_mu0.csv", curves);
    out.write("pin_on_disk_mu0_summary.csv", table);
    written.insert(written.end(), {"pin_on_disk_mu0.csv", "pin_on_disk_mu0_summary.csv"});
  }
  if (!o.no_plot) {
    plot("plot_curves.py",
         {out.file("pin_on_disk.csv").string(), out.file("pin_on_disk.png").string(), "--title", c.title});
    written.push_back("pin_on_disk.png");
    if (!sweep.empty()) {
      plot("plot_curves.py", {"--overlay", out.file("pin_on_disk_mu0.csv").string(),
                              out.file("pin_on_disk_mu0.png").string(), "--title", c.title + ": mu0 sweep"});
      written.push_back("pin_on_disk_mu0.png");
    }
  }
  std::string vtk_index, stress_index;
#ifdef RUNIN_HAVE_VTK
  if (!curve.frames.empty()) vtk_index = out.destination_of(write_frames(curve.frames, out.staging()).back()).string();
  if (!stress.empty()) stress_index = out.destination_of(write_stress(stress, out.staging()).back()).string();
#endif
  out.commit();

  const auto &s = curve.summary;
  const auto &p = c.parameters;
  const auto &first = curve.rows.front(), &last = curve.rows.back();
  fmt::print("runin pin-on-disk: {}\n  {}\n", o.case_path, c.title);
  fmt::print("  friction          {}\n", c.friction->description());
  fmt::print("  applied torque    {:.6g} N m ({}), ramp {:g} s\n", p.applied_torque, c.torque_origin, p.ramp_time);
  fmt::print("  static limit      {:.6g} N m (mu_static = {:.6g})\n", c.friction->static_coefficient() *
                                                                          p.normal_load * p.track_radius,
             c.friction->static_coefficient());
  std::string scale_warning;  // state law: the contact narrower than 3 homogenisation cells
  fmt::print("  break-away        {}\n", or_none(s.breakaway_time));
  fmt::print("  peak friction     {:.6g} N at t = {:.6g} s\n", s.peak_friction_force, s.peak_time);
  fmt::print("  steady state      {} (friction force and speed within {:g} % of final values from then on)\n",
             or_none(s.steady_time), 100 * continuum::PinOnDiskSummary::steady_tolerance);
  fmt::print("  steady mu         {:.6g} = F / W; law part without the speed term {:.6g} (at s = 0: {:.6g})\n",
             s.steady_mu, s.steady_mu_law, first.s.mu_law);
  fmt::print("  final speed       {:.6g} m/s, sliding distance {:.6g} m at t = {:g} s\n", s.final_speed,
             last.s.distance, last.s.t);
  if (c.contact) {
    if (c.contact->flat)
      fmt::print("  contact           flat end a = {:g} m at the uniform nominal pressure W / (pi a^2) = {:.4g} Pa, "
                 "{} rings\n",
                 c.contact->flat_radius, first.mean_pressure, c.contact->rings);
    else
      fmt::print("  contact           tip R = {:g} m, E* = {:.4g} Pa, {} rings to {:.4g} m\n", c.contact->tip_radius,
                 c.contact->effective_modulus(), c.contact->rings, curve.grid_radius);
    fmt::print("  contact radius    {:.4g} m -> {:.4g} m\n", first.contact_radius, last.contact_radius);
    fmt::print("  pressure          peak {:.4g} -> {:.4g} Pa, mean {:.4g} -> {:.4g} Pa\n", first.peak_pressure,
               last.peak_pressure, first.mean_pressure, last.mean_pressure);
    if (c.contact->wear)
      fmt::print("  wear volume       {:.6g} m^3 (Archard k W s / {}H = {:.6g}), {} adaptive wear steps\n",
                 last.wear_volume, c.contact->wear->form() == tribo::ArchardForm::thesis ? "3" : "",
                 c.contact->wear->volume(p.normal_load, last.s.distance), curve.wear_steps);
    if (const auto *law = c.friction->state_law()) {
      const auto &d = *curve.disk;
      fmt::print("  state law         {} (p {:.4g} .. {:.4g} Pa, h 0 .. {:.4g} m)\n", law->path,
                 law->law->pressure().front(), law->law->pressure().back(), law->law->worn_depth().back());
      fmt::print("  mu_eff            {:.6g} -> {:.6g} (pressure-weighted over the rings); static limit {:.6g} ({})\n",
                 first.mu_eff, last.mu_eff, law->held_static,
                 law->mu_static ? "friction.mu_static" : "the law's peak over h at the initial pressures");
      fmt::print("  pin wear          h mean {:.4g} m, max {:.4g} m, volume {:.6g} m^3 (law wear_rate), {} wear steps\n",
                 last.h_mean, last.h_max, last.wear_volume, curve.wear_steps);
      fmt::print("  disk wear         {:.6g} m^3 (law counterface_wear_rate), track depth {:.4g} m over {:.4g} m x "
                 "{:.4g} m\n",
                 d.volume, d.depth, d.width, d.length);
      fmt::print("  law lookups       {}\n", continuum::describe(*curve.range_use, *law->law));
      if (const auto cell = coupling::cell_scale(*law->law)) {
        const coupling::ScaleSeparation sep{*cell, 2.0 * first.contact_radius, curve.smallest_node_area};
        fmt::print("  scale separation  {}\n", coupling::describe(sep));
        scale_warning = coupling::scale_separation_warning(sep);
      }
    } else if (curve.disk) {
      const auto &d = *curve.disk;
      const auto &w = *c.contact->disk_wear;
      const bool thesis = w.form() == tribo::ArchardForm::thesis;
      fmt::print("  disk wear         {:.6g} m^3 (Archard k_d W s / {}H_d = {:.6g}), k_d = {:g}, H_d = {:.4g} Pa ({})\n",
                 d.volume, thesis ? "3" : "", w.volume(p.normal_load, last.s.distance), w.coefficient(), w.hardness(),
                 c.contact->disk_hardness_origin);
      fmt::print("  pin + disk        {:.6g} m^3 worn, the pin's part {:.4g}\n", last.wear_volume + d.volume,
                 last.wear_volume + d.volume > 0.0 ? last.wear_volume / (last.wear_volume + d.volume) : 0.0);
      fmt::print("  disk track        mean depth {:.4g} m, {:.4g} m wide x {:.4g} m long ({:.3g} passes of 2 pi r); "
                 "pin wear depth {:.4g} m\n",
                 d.depth, d.width, d.length, d.passes, d.pin_depth);
      fmt::print("  groove            track depth / elastic approach <= {:.3g} (t = {:g} s); the contact is solved "
                 "on the flat disk{}\n",
                 d.approach_ratio, d.approach_ratio_time,
                 d.approach_ratio <= kGrooveTolerance ? fmt::format(" (negligible: <= {:g})", kGrooveTolerance) : "");
    }
  }
  std::vector<std::string> warnings;
  if (!scale_warning.empty()) warnings.push_back(scale_warning);
  for (std::size_t i = 0; i < stress.size(); ++i) {
    const auto &f = stress[i].stress;
    fmt::print("  subsurface stress {} (t = {:g} s): {}, p0 = {:.4g} Pa, a = {:.4g} m, mu = {:.3g}\n",
               i == 0 ? "start" : "end", stress[i].time, f.method, f.peak_pressure, f.contact_radius,
               f.friction_coefficient);
    const auto &k = *c.contact;
    for (const auto &[body, name, b] : {std::make_tuple("disk", k.disk_name, &f.disk), std::make_tuple("pin", k.pin_name, &f.pin)}) {
      const std::string label = name.empty() ? std::string(body) : fmt::format("{} ({})", body, name);
      const std::string verdict =
          b->yield_strength > 0.0
              ? fmt::format("S_y = {:.4g} Pa: {} (peak / S_y = {:.3g})", b->yield_strength,
                            b->yields() ? "YIELDS" : "elastic", b->peak.von_mises / b->yield_strength)
              : std::string("S_y unknown (set contact.materials)");
      fmt::print("    {:<10} peak von Mises {:.4g} Pa at x = {:.3g} m, depth {:.3g} m (nu = {:.3g}); {}\n", label,
                 b->peak.von_mises, b->peak.x, b->peak.z, b->poisson_ratio, verdict);
      if (b->yields())
        warnings.push_back(fmt::format("WARNING: the {} yields at the {} of the run: peak von Mises {:.4g} Pa > S_y = "
                                       "{:.4g} Pa ({:.3g} x) at depth {:.3g} m; the elastic contact and wear model "
                                       "is outside its range there",
                                       label, i == 0 ? "start" : "end", b->peak.von_mises, b->yield_strength,
                                       b->peak.von_mises / b->yield_strength, b->peak.z));
    }
  }
  if (!stress.empty()) {
    // The frictionless Hertz field for reference (0.62 p0 at 0.48 a for nu = 0.3).
    const auto &k = *c.contact;
    const auto &h = stress.front().stress;
    const auto f0 = continuum::hertz_contact_stress(h.peak_pressure, h.contact_radius, 0.0, k.pin, k.disk);
    fmt::print("    frictionless: disk peak von Mises {:.4g} Pa at depth {:.3g} m, pin {:.4g} Pa at depth {:.3g} m\n",
               f0.disk.peak.von_mises, f0.disk.peak.z, f0.pin.peak.von_mises, f0.pin.peak.z);
  }
  if (curve.range_use)
    if (auto w = continuum::out_of_range_warning(*curve.range_use, *c.friction->state_law()->law,
                                                  c.friction->state_law()->policy);
        !w.empty())
      warnings.push_back(std::move(w));
  if (curve.disk && curve.disk->approach_ratio > kGrooveTolerance)
    warnings.push_back(fmt::format("WARNING: the disk's track depth reaches {:.3g} x the elastic approach (t = {:g} s, "
                                   "> {:g}): the worn groove, left out of the contact solve, would change the "
                                   "contact pressure",
                                   curve.disk->approach_ratio, curve.disk->approach_ratio_time, kGrooveTolerance));
  for (const auto &w : warnings) fmt::print("  {}\n", w);
  fmt::print("  CVODE             {} steps, {} break-away, {} re-stick events\n", curve.report.steps,
             curve.report.breakaway_times.size(), curve.report.restick_times.size());
  if (!sweep.empty()) {
    fmt::print("  mu0 sweep         (torque from eq. 4.11 per mu0 when targeted)\n");
    fmt::print("    {:>6} {:>11} {:>11} {:>11} {:>11} {:>11} {:>12}\n", "mu0", "T_app N m", "break-away", "peak F N",
               "steady at", "steady mu", "wear m^3");
    for (const auto &run : sweep) {
      const auto &r = run.curve.summary;
      fmt::print("    {:>6.3g} {:>11.5g} {:>11} {:>11.5g} {:>11} {:>11.5g} {:>12.4g}\n", run.mu0, run.torque,
                 or_none(r.breakaway_time), r.peak_friction_force, or_none(r.steady_time), r.steady_mu,
                 run.curve.rows.back().wear_volume);
    }
  }
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  if (!vtk_index.empty()) fmt::print(", {} ({} frames)", vtk_index, curve.frames.size());
  if (!stress_index.empty()) fmt::print(", {} (subsurface stress, {} frames)", stress_index, stress.size());
  fmt::print("\n");
  return 0;
}

}  // namespace runin::cli
