#include "cli/cmd_pin_on_disk.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
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
#include "continuum/pin_on_disk_wear.h"
#include "continuum/pin_state_law.h"
#include "continuum/state_law_splitting.h"
#include "coupling/scale_separation.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

namespace fs = std::filesystem;
using continuum::PinOnDiskSample;
using DiskTrack = continuum::DiskTrackSummary;
using Frame = continuum::PinFaceFrame;

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

struct Row {
  PinOnDiskSample s;
  double wear_volume = 0.0, contact_radius = 0.0, peak_pressure = 0.0, mean_pressure = 0.0;
  double disk_wear_volume = 0.0, disk_track_depth = 0.0;  // 0 without wear.disk_k
  double mu_eff = 0.0, h_mean = 0.0, h_max = 0.0;         // friction.model = "state_law" only
  double film_coverage = 0.0;                             // with [film]
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
  double counterface_duty = 0.0;    // [film] with a disk film: the track's time under the pin
  continuum::SplitReport split;     // state law: slow steps (adaptive: quasi-static and rejected ones)
  std::optional<continuum::ArchardRatios> archard;  // state law
  double wall_seconds = 0.0;        // of the main run (run_case)
};

// A wear failure's message, with the key that helps when the worn face left the grid.
std::string with_grid_hint(const std::string &message) {
  return message + (message.find("edge of the grid") != std::string::npos ? " (raise contact.grid_radius)" : "");
}

// The dynamics' failure, explained where velocity weakening runs away under a held torque (thesis eq. 4.5, minus sign).
std::string dynamics_error(const PinOnDiskCase &c, const continuum::SolveReport &report,
                           const std::vector<PinOnDiskSample> &samples) {
  std::string message = std::string(continuum::to_string(report.status)) + ": " + report.message;
  const std::size_t n = samples.size();
  if (message.find("[CV_TOO_MUCH_WORK]") != std::string::npos && c.friction->speed_coefficient() < 0.0 && n >= 2 &&
      samples[n - 1].speed > samples[n - 2].speed && samples[n - 1].speed > 0.0)
    message = fmt::format(
        "CVODE could not advance past t = {:.6g} s (too much work): the sliding speed runs away under "
        "velocity-weakening friction (alpha < 0; V = {:.4g} m/s at t = {:.6g} s and rising)",
        report.end_time, samples[n - 1].speed, samples[n - 1].t);
  return message;
}

Curve run_state_law_case(const PinOnDiskCase &c, bool with_frames);

// Dynamics first (CVODE), then the library's wear pass driven by the sliding distance of each output sample.
Curve run_case(const PinOnDiskCase &c, bool with_frames) {
  if (c.friction->state_law()) return run_state_law_case(c, with_frames);
  Curve curve;
  const continuum::PinOnDiskSystem system(c.parameters, *c.friction);
  std::vector<PinOnDiskSample> samples;
  curve.report = continuum::simulate(system, c.run, [&](const PinOnDiskSample &s) { samples.push_back(s); });
  if (!curve.report.ok()) throw std::runtime_error(dynamics_error(c, curve.report, samples));
  curve.summary = continuum::summarise(samples);
  curve.rows.reserve(samples.size());
  for (const auto &s : samples) curve.rows.push_back({s});
  if (!c.contact) return curve;

  const auto &k = *c.contact;
  continuum::PinWearPassSettings settings{pin_wear_parameters(k), k.grid_radius, k.wear, k.disk_wear,
                                          c.parameters.normal_load, c.parameters.track_radius,
                                          with_frames ? c.vtk_times : std::vector<double>{}};
  continuum::PinWearPass pass;
  try {
    pass = continuum::pin_wear_pass(samples, settings);
  } catch (const std::invalid_argument &e) {
    throw std::runtime_error(std::string(e.what()) + " (raise contact.grid_radius)");
  } catch (const continuum::PinWearError &e) {
    throw std::runtime_error(with_grid_hint(e.what()));
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto &w = pass.rows[i];
    auto &row = curve.rows[i];
    row.wear_volume = w.wear_volume, row.contact_radius = w.contact_radius;
    row.peak_pressure = w.peak_pressure, row.mean_pressure = w.mean_pressure;
    row.disk_wear_volume = w.disk_wear_volume, row.disk_track_depth = w.disk_track_depth;
  }
  curve.frames = std::move(pass.frames);
  curve.grid_radius = pass.grid_radius;
  curve.wear_steps = pass.wear_steps;
  curve.final_pressure = std::move(pass.final_pressure);
  curve.ring_width = pass.ring_width;
  curve.disk = pass.disk;
  return curve;
}

// The one-line message of a failed split (the library's status and message, with the case keys that help).
std::string split_error(const continuum::SplitReport &r, const continuum::StateLawFriction &law) {
  switch (r.status) {
    case continuum::SplitStatus::FastFailure:
      return std::string(continuum::to_string(r.fast.status)) + ": " + r.fast.message;
    case continuum::SplitStatus::TooManySlowSteps:
      if (r.message.find("adaptive wear steps") != std::string::npos)
        return r.message + "; raise run.tolerance";
      return r.message + "; raise wear.max_steps or lower contact.rings";
    case continuum::SplitStatus::SlowFailure:
      return with_grid_hint(r.message);
    default:
      return fmt::format("state law at t = {:g} s: {}{}", r.time, r.message,
                         r.status == continuum::SplitStatus::LawOutOfRange && law.policy == coupling::OutOfRange::Error
                             ? " (friction.out_of_range = \"archard\" takes friction at the nearest grid pressure, "
                               "keeps wear proportional to p and counts it)"
                             : "");
  }
}

// An adaptive run stopped on its smallest step with a film that alone can move mu_eff by more than run.tolerance over
// that step (continuum::film_step_bound): the film's input is what the steps cannot resolve, as bad input.
std::optional<std::string> film_too_fast(const PinOnDiskCase &c, const continuum::SplitReport &r,
                                         const continuum::FilmSettings &f) {
  if (r.status != continuum::SplitStatus::SlowFailure || !c.wear_steps.adaptive || !(r.failed_step_distance > 0.0))
    return std::nullopt;
  const auto bound =
      continuum::film_step_bound(f, r.failed_step_distance, r.failed_step_duration, c.wear_steps.tolerance);
  using continuum::FilmInput;
  const char *key = nullptr;
  switch (bound.input) {
    case FilmInput::None: return std::nullopt;
    case FilmInput::RemovalDistance: key = "film.removal_distance"; break;
    case FilmInput::GrowthRate: key = "film.growth_rate"; break;
    case FilmInput::CounterfaceRemovalDistance: key = "film.counterface_removal_distance"; break;
    case FilmInput::CounterfaceGrowthRate: key = "film.counterface_growth_rate"; break;
    case FilmInput::FFilm: key = "film.f_film"; break;
  }
  const bool kinetic = bound.input != FilmInput::FFilm;
  return fmt::format("{}: key '{}': the film can change mu_eff by up to {:.3g} over the adaptive wear steps' "
                     "smallest step ({:.3g} m of sliding at t = {:.3g} s), above run.tolerance = {:.3g}: {}, or "
                     "run.wear_steps = \"fixed\"",
                     c.path, key, bound.change, r.failed_step_distance, r.time, c.wear_steps.tolerance,
                     kinetic ? "give a film that changes over a longer distance or time"
                             : fmt::format("at f_film = {:.17g} Tabor's friction is that steep in the coverage (f_film "
                                           "or the film.interface state's m); give one further from 0 and 1",
                                           std::fabs(f.f_film)));
}

continuum::PinStateLawSettings state_law_settings(const PinOnDiskCase &c) {
  const auto &k = *c.contact;
  continuum::PinStateLawSettings s;
  if (k.flat) s.flat_radius = k.flat_radius;
  s.tip = pin_wear_parameters(k);
  s.grid_radius = k.grid_radius;
  s.load = c.parameters.normal_load;
  s.track_radius = c.parameters.track_radius;
  s.slid_estimate = c.parameters.drive == continuum::PinDrive::Speed ? c.parameters.sliding_speed * c.run.t_end : 0.0;
  return s;
}

// The pin face as the state law left it at time t: per ring h_i, mu(p_i, h_i) and the profile.
Frame state_law_frame(const continuum::PinStateLaw &pin, double t) {
  const auto &p = pin.pressure();
  const auto &h = pin.nodes().state();
  Frame f{t, {}, {}, {}, {}, pin.nodes().node_mu(p)};
  for (int i = 0; i < pin.grid().rings(); ++i) {
    f.radius.push_back(pin.grid().ring_radius(i));
    f.height.push_back(pin.profile_height(i));
    f.pressure.push_back(p[i]);
    f.depth.push_back(h[i]);
  }
  return f;
}

// friction.model = "state_law" (doc/state_law_continuum.md): the library's splitting driver couples the dynamics
// (CVODE with mu_eff held over each output interval) with the pin face's node states (continuum::PinStateLaw).
Curve run_state_law_case(const PinOnDiskCase &c, bool with_frames) {
  auto *law = c.friction->state_law();
  Curve curve;
  std::optional<continuum::PinStateLaw> pin;
  try {
    pin.emplace(state_law_settings(c), *law);
  } catch (const std::invalid_argument &e) {
    if (c.contact->flat) throw;
    throw std::runtime_error(std::string(e.what()) + " (raise contact.grid_radius)");
  }
  std::size_t next_frame = 0;
  std::vector<double> frame_times = c.vtk_times;
  std::sort(frame_times.begin(), frame_times.end());
  std::vector<PinOnDiskSample> samples;
  const continuum::PinOnDiskSystem system(c.parameters, *c.friction);
  const auto observer = [&](const PinOnDiskSample &s) {
    samples.push_back(s);
    const auto st = pin->state();
    curve.rows.push_back({s, st.wear_volume, st.contact_radius, st.peak_pressure, st.mean_pressure,
                          st.disk_wear_volume, st.disk_track_depth, st.mu_eff, st.h_mean, st.h_max,
                          st.film_coverage});
    for (; with_frames && next_frame < frame_times.size() && s.t >= frame_times[next_frame] - 1e-12; ++next_frame)
      curve.frames.push_back(state_law_frame(*pin, s.t));
  };
  const auto split = continuum::run_pin_split(system, c.run, *pin, c.wear_steps, observer);
  if (!split.ok()) {
    if (law->film)
      if (const auto film_error = film_too_fast(c, split, *law->film)) throw InputError(*film_error);
    throw std::runtime_error(split_error(split, *law));
  }
  curve.report = split.fast;
  curve.split = split;
  curve.summary = continuum::summarise(samples);
  curve.grid_radius = pin->grid_radius();
  curve.smallest_node_area = pin->smallest_node_area();
  curve.counterface_duty = pin->counterface_duty();
  curve.wear_steps = pin->wear_steps();
  curve.final_pressure = pin->pressure();
  curve.ring_width = pin->grid().ring_width();
  curve.range_use = pin->nodes().use();
  const auto &h = pin->nodes().state();
  curve.disk = continuum::summarise(pin->disk(), *std::max_element(h.begin(), h.end()));
  const auto &last = curve.rows.back();
  curve.archard = continuum::archard_ratios(*law->law, last.wear_volume, last.disk_wear_volume,
                                            c.parameters.normal_load * last.s.distance);
  return curve;
}

std::string csv_text(const std::vector<Row> &rows, bool state_law, bool film) {
  std::string text =
      "t_s,applied_torque_N_m,friction_force_N,friction_torque_N_m,mu,speed_m_s,sliding_distance_m,state_slip,"
      "mu_law,roughness,wear_volume_m3,contact_radius_m,peak_pressure_Pa,mean_pressure_Pa,disk_wear_volume_m3,"
      "disk_track_depth_m";
  text += state_law ? ",mu_eff,h_mean_m,h_max_m" : "";
  text += film ? ",film_coverage\n" : "\n";
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
    if (film) {
      text.pop_back();
      text += fmt::format(",{:.12g}\n", r.film_coverage);
    }
  }
  return text;
}

// Subsurface stress at the start and the end of the run (continuum::pin_start_end_stress, doc/subsurface_stress.md).
struct StressFrame {
  double time;
  continuum::ContactStress stress;
};
std::vector<StressFrame> subsurface_stress(const PinOnDiskCase &c, const Curve &curve) {
  if (!c.contact || c.contact->flat) return {};  // flat end: no Hertz start, nominal pressure only
  const auto &k = *c.contact;
  const auto [start, end] = continuum::pin_start_end_stress(
      pin_wear_parameters(k), c.parameters.normal_load, curve.summary.start_friction_force, curve.final_pressure,
      curve.ring_width, curve.rows.back().s.mu, k.pin, k.disk);
  return {{curve.rows.front().s.t, start}, {curve.rows.back().s.t, end}};
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

struct SweepRun {
  double mu0, torque;
  Curve curve;
};

// The run-in distance of the curve (continuum::run_in_distance on its samples).
continuum::RunInDistance run_in(const Curve &curve) {
  std::vector<PinOnDiskSample> samples;
  samples.reserve(curve.rows.size());
  for (const auto &r : curve.rows) samples.push_back(r.s);
  return continuum::run_in_distance(samples);
}

// Adaptive wear steps append the run-in distance, the step counts, the wall time and Archard's ratios.
std::string summary_csv_text(const PinOnDiskCase &c, const Curve &curve) {
  const auto &m = curve.summary;
  std::string header = kRunSummaryHeader;
  std::string row = run_summary_row({m.peak_friction_force, m.peak_time, m.breakaway_time, m.steady_time, m.steady_mu,
                                     curve.rows.back().wear_volume});
  if (c.wear_steps.adaptive) {
    const auto r = run_in(curve);
    header += ",settle_distance_m,steady_mu_last_10pc,slow_steps,rejected_steps,dynamics_stretches,wall_time_s,"
              "archard_ratio_pin,archard_ratio_disk";
    row += fmt::format(",{},{:.12g},{},{},{},{:.6g},{:.12g},{:.12g}",
                       r.distance < 0.0 ? std::string() : fmt::format("{:.12g}", r.distance), r.steady_mu,
                       curve.split.slow_steps, curve.split.rejected_steps, curve.split.fallbacks,
                       curve.wall_seconds, curve.archard->pin, curve.archard->disk);
  }
  return header + "\n" + row + "\n";
}

// The mu0 sweep's curves and its summary table.
std::pair<std::string, std::string> sweep_csv_text(const std::vector<SweepRun> &sweep) {
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
  return {curves, table};
}

// The CSV files and the plots, staged; returns their names in order.
std::vector<std::string> write_curves(StagedOutput &out, const PinOnDiskCase &c, const Curve &curve,
                                      const std::vector<SweepRun> &sweep, bool no_plot, const PlotRunner &plot) {
  out.write("pin_on_disk.csv", csv_text(curve.rows, c.friction->state_law() != nullptr, c.friction->state_law() && c.friction->state_law()->film));
  out.write("pin_on_disk_summary.csv", summary_csv_text(c, curve));
  std::vector<std::string> written = {"pin_on_disk.csv", "pin_on_disk_summary.csv"};
  if (!sweep.empty()) {
    const auto [curves, table] = sweep_csv_text(sweep);
    out.write("pin_on_disk_mu0.csv", curves);
    out.write("pin_on_disk_mu0_summary.csv", table);
    written.insert(written.end(), {"pin_on_disk_mu0.csv", "pin_on_disk_mu0_summary.csv"});
  }
  if (no_plot) return written;
  plot("plot_curves.py",
       {out.file("pin_on_disk.csv").string(), out.file("pin_on_disk.png").string(), "--title", c.title});
  written.push_back("pin_on_disk.png");
  if (!sweep.empty()) {
    plot("plot_curves.py", {"--overlay", out.file("pin_on_disk_mu0.csv").string(),
                            out.file("pin_on_disk_mu0.png").string(), "--title", c.title + ": mu0 sweep"});
    written.push_back("pin_on_disk_mu0.png");
  }
  return written;
}

void print_dynamics(const PinOnDiskCase &c, const Curve &curve) {
  const auto &s = curve.summary;
  const auto &p = c.parameters;
  const auto &first = curve.rows.front(), &last = curve.rows.back();
  fmt::print("  friction          {}\n", c.friction->description());
  fmt::print("  applied torque    {:.6g} N m ({}), ramp {:g} s\n", p.applied_torque, c.torque_origin, p.ramp_time);
  fmt::print("  static limit      {:.6g} N m (mu_static = {:.6g})\n", c.friction->static_coefficient() *
                                                                          p.normal_load * p.track_radius,
             c.friction->static_coefficient());
  fmt::print("  break-away        {}\n", or_none(s.breakaway_time));
  fmt::print("  peak friction     {:.6g} N at t = {:.6g} s\n", s.peak_friction_force, s.peak_time);
  fmt::print("  steady state      {} (friction force and speed within {:g} % of final values from then on)\n",
             or_none(s.steady_time), 100 * continuum::PinOnDiskSummary::steady_tolerance);
  fmt::print("  steady mu         {:.6g} = F / W; law part without the speed term {:.6g} (at s = 0: {:.6g})\n",
             s.steady_mu, s.steady_mu_law, first.s.mu_law);
  fmt::print("  final speed       {:.6g} m/s, sliding distance {:.6g} m at t = {:g} s\n", s.final_speed,
             last.s.distance, last.s.t);
}

// The state law's lines; returns the scale-separation warning (empty if none).
std::string print_state_law(const PinOnDiskCase &c, const Curve &curve) {
  const auto *law = c.friction->state_law();
  const auto &first = curve.rows.front(), &last = curve.rows.back();
  const auto &d = *curve.disk;
  fmt::print("  state law         {} (p {:.4g} .. {:.4g} Pa, h 0 .. {:.4g} m)\n", law->path,
             law->law->pressure().front(), law->law->pressure().back(), law->law->worn_depth().back());
  fmt::print("  mu_eff            {:.6g} -> {:.6g} (pressure-weighted over the rings); static limit {:.6g} ({})\n",
             first.mu_eff, last.mu_eff, law->held_static,
             law->mu_static ? "friction.mu_static" : "the law's peak over h at the initial pressures");
  fmt::print("  pin wear          h mean {:.4g} m, max {:.4g} m, volume {:.6g} m^3 (law wear_rate), {} wear steps\n",
             last.h_mean, last.h_max, last.wear_volume, curve.wear_steps);
  if (const auto &film = law->film) {
    fmt::print("  film              contact coverage {:.4g} -> {:.4g} (load-weighted), f {:.4g} covered / {:.4g} bare; "
               "pin s_r {:.4g} m, k_g {:.4g} 1/s\n",
               first.film_coverage, last.film_coverage, film->f_film, film->f_base, film->removal_distance,
               film->growth_rate);
    if (const auto &cf = film->counterface)
      fmt::print("                    disk film s_r {:.4g} m, k_g {:.4g} 1/s, under the pin {:.4g} of the time; a "
                 "contact shears at the mean coverage of the two\n",
                 cf->removal_distance, cf->growth_rate, curve.counterface_duty);
  }
  fmt::print("  disk wear         {:.6g} m^3 (law counterface_wear_rate), track depth {:.4g} m over {:.4g} m x "
             "{:.4g} m\n",
             d.volume, d.depth, d.width, d.length);
  fmt::print("  law lookups       {}\n", continuum::describe(*curve.range_use, *law->law));
  if (c.wear_steps.adaptive) {
    const auto &sp = curve.split;
    if (c.parameters.drive == continuum::PinDrive::Speed)
      fmt::print("  wear steps        adaptive, tolerance {:g}: {} slow steps along the drive's s(t) ({} rejected)\n",
                 c.wear_steps.tolerance, sp.slow_steps, sp.rejected_steps);
    else
      fmt::print("  wear steps        adaptive, tolerance {:g}: {} slow steps ({} rejected); full dynamics over the "
                 "ramp and {} more stretches of {} output intervals where the pin may stick or lag V_ss\n",
                 c.wear_steps.tolerance, sp.slow_steps, sp.rejected_steps, sp.fallbacks,
                 c.wear_steps.dynamics_chunk);
    const auto r = run_in(curve);
    fmt::print("  run-in            mu = F/W within {:g} % of its steady value {:.6g} (mean over the last {:g} % of "
               "sliding) from s = {}\n",
               100 * r.tolerance, r.steady_mu, 100 * r.tail,
               r.distance < 0.0 ? std::string("never") : fmt::format("{:.6g} m", r.distance));
    const auto &a = *curve.archard;
    fmt::print("  Archard           worn volume / (K W s): pin {:.6g} (K = {:.4g} /Pa), disk {:.6g} (K = {:.4g} /Pa); "
               "K = the law's rate / p at p = {:.4g} Pa, h = 0\n",
               a.pin, a.k_pin, a.disk, a.k_disk, law->law->pressure().front());
    fmt::print("  wall time         {:.3g} s (the run, without output)\n", curve.wall_seconds);
  }
  const auto cell = coupling::cell_scale(*law->law);
  if (!cell) return {};
  const coupling::ScaleSeparation sep{*cell, 2.0 * first.contact_radius, curve.smallest_node_area};
  fmt::print("  scale separation  {}\n", coupling::describe(sep));
  return coupling::scale_separation_warning(sep);
}

void print_disk_track(const PinOnDiskCase &c, const Curve &curve) {
  const auto &d = *curve.disk;
  const auto &w = *c.contact->disk_wear;
  const auto &last = curve.rows.back();
  const bool thesis = w.form() == tribo::ArchardForm::thesis;
  fmt::print("  disk wear         {:.6g} m^3 (Archard k_d W s / {}H_d = {:.6g}), k_d = {:g}, H_d = {:.4g} Pa ({})\n",
             d.volume, thesis ? "3" : "", w.volume(c.parameters.normal_load, last.s.distance), w.coefficient(),
             w.hardness(), c.contact->disk_hardness_origin);
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

// The contact and wear lines; returns the scale-separation warning of a state law (empty if none).
std::string print_contact(const PinOnDiskCase &c, const Curve &curve) {
  const auto &k = *c.contact;
  const auto &first = curve.rows.front(), &last = curve.rows.back();
  if (k.flat)
    fmt::print("  contact           flat end a = {:g} m at the uniform nominal pressure W / (pi a^2) = {:.4g} Pa, "
               "{} rings\n",
               k.flat_radius, first.mean_pressure, k.rings);
  else
    fmt::print("  contact           tip R = {:g} m, E* = {:.4g} Pa, {} rings to {:.4g} m\n", k.tip_radius,
               k.effective_modulus(), k.rings, curve.grid_radius);
  fmt::print("  contact radius    {:.4g} m -> {:.4g} m\n", first.contact_radius, last.contact_radius);
  fmt::print("  pressure          peak {:.4g} -> {:.4g} Pa, mean {:.4g} -> {:.4g} Pa\n", first.peak_pressure,
             last.peak_pressure, first.mean_pressure, last.mean_pressure);
  if (k.wear)
    fmt::print("  wear volume       {:.6g} m^3 (Archard k W s / {}H = {:.6g}), {} adaptive wear steps\n",
               last.wear_volume, k.wear->form() == tribo::ArchardForm::thesis ? "3" : "",
               k.wear->volume(c.parameters.normal_load, last.s.distance), curve.wear_steps);
  if (c.friction->state_law()) return print_state_law(c, curve);
  if (curve.disk) print_disk_track(c, curve);
  return {};
}

// The subsurface stress lines; the yield warnings go to `warnings`.
void print_stress(const PinOnDiskCase &c, const std::vector<StressFrame> &stress, std::vector<std::string> &warnings) {
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
  if (stress.empty()) return;
  // The frictionless Hertz field for reference (0.62 p0 at 0.48 a for nu = 0.3).
  const auto &k = *c.contact;
  const auto &h = stress.front().stress;
  const auto f0 = continuum::hertz_contact_stress(h.peak_pressure, h.contact_radius, 0.0, k.pin, k.disk);
  fmt::print("    frictionless: disk peak von Mises {:.4g} Pa at depth {:.3g} m, pin {:.4g} Pa at depth {:.3g} m\n",
             f0.disk.peak.von_mises, f0.disk.peak.z, f0.pin.peak.von_mises, f0.pin.peak.z);
}

// The out-of-range and groove warnings.
void add_warnings(const PinOnDiskCase &c, const Curve &curve, std::vector<std::string> &warnings) {
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
}

void print_sweep(const std::vector<SweepRun> &sweep) {
  if (sweep.empty()) return;
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
  const auto started = std::chrono::steady_clock::now();
  Curve curve = run_case(c, true);
  curve.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
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
  const std::vector<std::string> written = write_curves(out, c, curve, sweep, o.no_plot, plot);
  std::string vtk_index, stress_index;
#ifdef RUNIN_HAVE_VTK
  if (!curve.frames.empty()) vtk_index = out.destination_of(write_frames(curve.frames, out.staging()).back()).string();
  if (!stress.empty()) stress_index = out.destination_of(write_stress(stress, out.staging()).back()).string();
#endif
  out.commit();

  fmt::print("runin pin-on-disk: {}\n  {}\n", o.case_path, c.title);
  print_dynamics(c, curve);
  std::vector<std::string> warnings;
  if (c.contact)
    if (auto w = print_contact(c, curve); !w.empty()) warnings.push_back(std::move(w));
  print_stress(c, stress, warnings);
  add_warnings(c, curve, warnings);
  for (const auto &w : warnings) fmt::print("  {}\n", w);
  fmt::print("  CVODE             {} steps, {} break-away, {} re-stick events\n", curve.report.steps,
             curve.report.breakaway_times.size(), curve.report.restick_times.size());
  print_sweep(sweep);
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  if (!vtk_index.empty()) fmt::print(", {} ({} frames)", vtk_index, curve.frames.size());
  if (!stress_index.empty()) fmt::print(", {} (subsurface stress, {} frames)", stress_index, stress.size());
  fmt::print("\n");
  return 0;
}

}  // namespace runin::cli
