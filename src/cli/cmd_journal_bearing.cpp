#include "cli/cmd_journal_bearing.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/case_file.h"
#include "cli/journal_bearing_case.h"
#include "cli/line_stress_report.h"
#include "cli/lubricated_bearing.h"
#include "cli/run_summary.h"
#include "cli/staged_file.h"
#include "continuum/journal_bearing.h"
#include "coupling/scale_separation.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

namespace fs = std::filesystem;
using continuum::JournalBearingFrame;
using continuum::JournalBearingSample;

struct Options {
  std::string case_path, output_dir;
  std::optional<std::string> law_path;
  bool no_plot = false;
  bool stribeck = false;  // lubricated cases only
  long max_wear_updates = 20000;  // each re-solves the contact: ~1 ms on 512 nodes, so ~20 s
};

// Thrown from the sample observer to stop a run that would exceed the wear-update cap.
struct WearCapReached {
  double t, distance;
};

struct Curve {
  std::vector<JournalBearingSample> samples;
  std::vector<JournalBearingFrame> frames;
  continuum::JournalBearingReport report;
  continuum::JournalBearingSummary summary;
};

RunSummary key_numbers(const continuum::JournalBearingSummary &s) {
  return {s.peak_friction_force, s.peak_time, s.breakaway_time, s.steady_time, s.steady_mu, s.wear_volume};
}

double wear_step(const JournalBearingCase &c, const continuum::JournalBearingSystem &system) {
  if (c.run.fixed_wear_step > 0.0) return c.run.fixed_wear_step;
  if (c.friction->state_law()) return HUGE_VAL;  // the law's step depends on the pressures: no cap estimate
  return c.run.wear_step_fraction *
         system.wear_law().stable_slip_step(system.contact().contact_stiffness_per_area());
}

// Each wear update re-solves the conformal contact, so the number of updates sets the run time.
// The journal follows the drive (lagging by the bounded coupling wind-up), so R theta_drive(t_end)
// estimates the sliding distance before the run; the observer enforces the cap during it.
Curve run_case(const JournalBearingCase &c, const continuum::SlidingFriction &friction, bool frames,
               long max_wear_updates) {
  const continuum::JournalBearingSystem system = [&] {
    try {
      return continuum::JournalBearingSystem(c.parameters, friction);
    } catch (const std::invalid_argument &e) {  // e.g. the arc too long for a positive-definite compliance
      throw InputError(c.path + ": key 'contact.arc_half_angle': " + e.what());
    }
  }();
  const auto &p = c.parameters;
  const double step = wear_step(c, system);
  const bool wearing = p.wear_coefficient > 0.0 && std::isfinite(step) && step > 0.0;
  const auto cap_message = [&](const std::string &how_many) {
    return fmt::format("journal bearing: {} wear updates (wear step {:.4g} m{}) exceed the cap of {} "
                       "(--max-wear-updates): lower wear.coefficient or raise the cap",
                       how_many, step, c.run.fixed_wear_step > 0.0 ? ", fixed" : " = step_fraction x 2H/(k k_c)",
                       max_wear_updates);
  };
  const double drive_distance = p.bore.shaft_radius * std::abs(p.drive_angle(c.run.t_end));
  // The journal cannot break away while the coupling torque k theta_d + c w_d stays below
  // mu_static W R (N >= W): then there is no wear to count.
  const double max_coupling_torque =
      p.coupling_stiffness * std::abs(p.drive_angle(c.run.t_end)) +
      p.coupling_damping * std::max(std::abs(p.ramp_angle / p.ramp_time), std::abs(p.run_speed));
  const bool fixed_static_limit = c.friction_model == "constant" || c.friction_model == "static_kinetic";
  const double total_load = p.load + (p.halves == 2 ? p.half_load(1) : 0.0);
  const bool may_slip =
      !fixed_static_limit || max_coupling_torque >= friction.static_coefficient() * total_load * p.bore.shaft_radius;
  if (wearing && may_slip && drive_distance / step > static_cast<double>(max_wear_updates))
    throw std::runtime_error(cap_message(fmt::format("about {:.3g}", drive_distance / step)) +
                             fmt::format(" (sliding distance ~ R theta_drive = {:.4g} m)", drive_distance));
  const double distance_cap = wearing ? step * static_cast<double>(max_wear_updates) : HUGE_VAL;

  Curve curve;
  const auto *law = friction.state_law();
  try {
    curve.report = continuum::simulate(
        system, c.run,
        [&](const JournalBearingSample &s) {
          if (s.distance > distance_cap) throw WearCapReached{s.t, s.distance};
          curve.samples.push_back(s);
        },
        frames ? continuum::JournalBearingFrameObserver([&](const JournalBearingFrame &f) { curve.frames.push_back(f); })
               : nullptr);
  } catch (const WearCapReached &stop) {
    throw std::runtime_error(cap_message(fmt::format("more than {}", max_wear_updates)) +
                             fmt::format(" (stopped at t = {:.6g} s, s = {:.4g} m)", stop.t, stop.distance));
  } catch (const std::out_of_range &e) {
    if (!law) throw;
    throw std::runtime_error(fmt::format("state law at t = {:g} s: {}{}",
                                         curve.samples.empty() ? 0.0 : curve.samples.back().t, e.what(),
                                         law->policy == coupling::OutOfRange::Error
                                             ? " (friction.out_of_range = \"archard\" takes friction at the nearest grid pressure, "
                                               "keeps wear proportional to p and counts it)"
                                             : ""));
  }
  if (!curve.report.ok())
    throw std::runtime_error(std::string(continuum::to_string(curve.report.status)) + ": " + curve.report.message);
  curve.summary = continuum::summarise(curve.samples);
  return curve;
}

const char *kColumns =
    "t_s,drive_angle_rad,drive_speed_rad_s,journal_speed_rad_s,coupling_torque_N_m,friction_torque_N_m,friction_force_N,normal_force_N,"
    "mu,mu_law,sliding_speed_m_s,sliding_distance_m,wear_volume_m3,contact_half_angle_rad,peak_pressure_Pa,"
    "mean_pressure_Pa,state_slip,roughness";

// Per-half columns, appended with two bearing halves.
const char *kHalfColumns[] = {"friction_torque_N_m", "normal_force_N", "mu", "roughness", "wear_volume_m3",
                              "contact_half_angle_rad", "peak_pressure_Pa"};

// State law (doc/state_law_continuum.md): per half, after the per-half columns.
const char *kStateLawColumns[] = {"mu_eff", "h_mean_m", "h_max_m", "counterface_volume_m3"};

std::string columns(int halves, bool state_law = false, bool film = false) {
  std::string text = kColumns;
  if (halves == 2)
    for (const char *half : {"lower_", "upper_"})
      for (const char *name : kHalfColumns) text += std::string(",") + half + name;
  if (state_law) {
    text += ",mu_eff";
    for (int h = 0; h < halves; ++h)
      for (const char *name : kStateLawColumns) text += std::string(",") + (h ? "upper_" : "lower_") + name;
  }
  if (film)
    for (int h = 0; h < halves; ++h) text += std::string(",") + (h ? "upper_" : "lower_") + "film_coverage";
  return text;
}

std::string state_law_row(const JournalBearingSample &s, bool film) {
  std::string text = fmt::format(",{:.12g}", s.mu_eff);
  for (int h = 0; h < s.halves; ++h)
    text += fmt::format(",{:.12g},{:.12g},{:.12g},{:.12g}", s.half[h].mu_eff, s.half[h].h_mean, s.half[h].h_max,
                        s.half[h].counterface_volume);
  if (film)
    for (int h = 0; h < s.halves; ++h) text += fmt::format(",{:.12g}", s.half[h].film_coverage);
  return text;
}

std::string row(const JournalBearingSample &s) {
  std::string halves;
  if (s.halves == 2)
    for (const auto &h : s.half)
      halves += fmt::format(",{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}", h.friction_torque, h.normal_force,
                            h.mu, h.roughness, h.wear_volume, h.contact_half_angle, h.peak_pressure);
  return fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},"
                     "{:.12g},{:.12g},{:.12g},{},{:.12g}",
                     s.t, s.drive_angle, s.drive_speed, s.journal_speed, s.coupling_torque, s.friction_torque, s.friction_force,
                     s.normal_force, s.mu, s.mu_law, s.sliding_speed, s.distance, s.wear_volume, s.contact_half_angle,
                     s.peak_pressure, s.mean_pressure, s.state == continuum::ContactState::Slip ? 1 : 0, s.roughness) +
         halves;
}

std::string or_none(double t) { return t < 0.0 ? std::string("not reached") : fmt::format("{:.6g} s", t); }

#ifdef RUNIN_HAVE_VTK
// Bore surface (worn radius) over the arc x axial width, theta = 0 at the loaded bottom (lower half)
// or at the top (upper half, pressed down onto the shaft).
std::vector<coupling::SurfaceFrame> surface_frames(const JournalBearingCase &c, const continuum::ConformalContact &contact,
                                                   const std::vector<JournalBearingFrame> &frames, bool upper = false) {
  const auto &b = c.parameters.bore;
  const int nu = contact.nodes(), nv = c.axial_points;
  std::vector<coupling::SurfaceFrame> out;
  for (const auto &f : frames) {
    coupling::SurfaceFrame s;
    s.time = f.t;
    s.nu = nu;
    s.nv = nv;
    std::vector<double> pressure(nu * nv), wear(nu * nv);
    for (int j = 0; j < nv; ++j) {
      const double z = b.axial_width * (j / double(nv - 1) - 0.5);
      for (int i = 0; i < nu; ++i) {
        const auto &depth = upper ? f.upper_wear_depth : f.wear_depth;
        const auto &p = upper ? f.upper_pressure : f.pressure;
        const double theta = contact.node_angle(i), r = b.shaft_radius + b.clearance + depth[i];
        s.points.push_back({r * std::sin(theta), (upper ? r : -r) * std::cos(theta), z});
        pressure[i + nu * j] = p[i];
        wear[i + nu * j] = depth[i];
      }
    }
    s.fields = {{"pressure", pressure}, {"wear_depth", wear}};
    const auto &mu = upper ? f.upper_mu : f.mu;
    if (!mu.empty()) {  // state law: h_i = wear depth, mu(p_i, h_i)
      std::vector<double> mu_field(nu * nv);
      for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) mu_field[i + nu * j] = mu[i];
      s.fields.push_back({"h", wear});
      s.fields.push_back({"mu", mu_field});
    }
    out.push_back(std::move(s));
  }
  return out;
}
#endif

// Subsurface stress below each bearing half (doc/subsurface_stress.md): the library's start and end frames
// (continuum::bore_start_end_stress), named for the summary and the VTK series.
std::vector<LineStressReport> subsurface_stress(const JournalBearingCase &c, const Curve &curve) {
  std::vector<LineStressReport> reports;
  bool tabor_bearing = false, tabor_shaft = false;
  continuum::verdict_yield_strength(c.bearing_material, &tabor_bearing);
  continuum::verdict_yield_strength(c.shaft_material, &tabor_shaft);
  const tribo::Material bearing = verdict_material(c.bearing_material), shaft = verdict_material(c.shaft_material);
  const auto halves = continuum::bore_start_end_stress(c.parameters, curve.samples, curve.summary.start_friction_force,
                                                       curve.report, bearing, shaft);
  for (std::size_t h = 0; h < halves.size(); ++h) {
    const auto &stress = halves[h];
    LineStressReport r;
    r.contact = c.parameters.halves == 2 ? (h == 0 ? "lower half" : "upper half") : "bearing";
    r.label_a = body_label("bearing", c.bearing_material_name);
    r.label_b = body_label("shaft", c.shaft_material_name);
    r.field_a = "bearing", r.field_b = "shaft";
    r.materials_hint = "contact.materials";
    r.tabor_a = tabor_bearing, r.tabor_b = tabor_shaft;
    r.cross_check = fmt::format("solved unworn pressure: p0 = {:.4g} Pa ({:+.2f} % from Hertz): start from the {}",
                                stress.solved_peak, 100.0 * (stress.solved_peak / stress.hertz_peak - 1.0),
                                stress.closed_form ? "closed form" : "influence tier");
    r.frames.push_back({curve.samples.front().t, stress.start});
    r.frames.push_back({curve.samples.back().t, stress.end});
    reports.push_back(std::move(r));
  }
  return reports;
}

// The main run, the mu0 sweep and (two halves) the same case with one contact.
struct Computed {
  Curve main;
  std::vector<Curve> sweep;
  std::optional<Curve> one_contact;
};

Computed compute(const Options &o, const JournalBearingCase &c) {
  Computed r;
  r.main = run_case(c, *c.friction, true, o.max_wear_updates);
  for (double mu0 : c.sweep_mu0) r.sweep.push_back(run_case(c, friction_with_mu0(c, mu0), false, o.max_wear_updates));
  // What the second bearing half changes: the same case with one contact (bearing.halves = 1).
  if (c.parameters.halves == 2 && c.one_contact_comparison) {
    JournalBearingCase single = c;
    single.parameters.halves = 1;
    single.parameters.second_half_load = 0.0;
    r.one_contact = run_case(single, *c.friction, false, o.max_wear_updates);
  }
  return r;
}

// The CSV files and the plots, staged; returns their names in order.
std::vector<std::string> write_curves(StagedOutput &out, const Options &o, const JournalBearingCase &c,
                                      const Computed &r, const PlotRunner &plot) {
  const int halves = c.parameters.halves;
  const bool law = c.friction->state_law() != nullptr;
  const bool film = law && c.friction->state_law()->film;
  std::string text = columns(halves, law, film) + "\n";
  for (const auto &s : r.main.samples) text += row(s) + (law ? state_law_row(s, film) : std::string()) + "\n";
  out.write("journal_bearing.csv", text);
  out.write("journal_bearing_summary.csv",
            std::string(kRunSummaryHeader) + "\n" + run_summary_row(key_numbers(r.main.summary)) + "\n");
  std::vector<std::string> written = {"journal_bearing.csv", "journal_bearing_summary.csv"};
  if (!r.sweep.empty()) {
    std::string t = "mu0," + columns(halves) + "\n";
    std::string summary = std::string("mu0,") + kRunSummaryHeader + "\n";
    for (std::size_t k = 0; k < r.sweep.size(); ++k) {
      for (const auto &s : r.sweep[k].samples) t += fmt::format("{:.12g},", c.sweep_mu0[k]) + row(s) + "\n";
      summary += fmt::format("{:.12g},", c.sweep_mu0[k]) + run_summary_row(key_numbers(r.sweep[k].summary)) + "\n";
    }
    out.write("journal_bearing_sweep.csv", t);
    out.write("journal_bearing_sweep_summary.csv", summary);
    written.push_back("journal_bearing_sweep.csv");  // (insert of an initializer list: a GCC 12 -Wuse-after-free false positive)
    written.push_back("journal_bearing_sweep_summary.csv");
  }
  if (o.no_plot) return written;
  plot("plot_journal_bearing.py", {"curve", out.file("journal_bearing.csv").string(), out.file("journal_bearing.png").string(), "--title",
            c.title});
  written.push_back("journal_bearing.png");
  if (!r.sweep.empty()) {
    plot("plot_journal_bearing.py", {"sweep", out.file("journal_bearing_sweep.csv").string(), out.file("journal_bearing_mu0.png").string(),
              "--title", c.title});
    written.push_back("journal_bearing_mu0.png");
  }
  return written;
}

// The bore frames and the subsurface stress series; returns the summary's VTK note.
std::string write_vtk(StagedOutput &out, const JournalBearingCase &c, const Curve &main,
                      const std::vector<LineStressReport> &stress) {
  std::string vtk_note = "none (built without VTK)";
#ifdef RUNIN_HAVE_VTK
  const continuum::ConformalContact contact(c.parameters.bore);
  const auto vtk_written = coupling::write_surface_series(surface_frames(c, contact, main.frames),
                                                          (out.staging() / "vtk").string(), "bore");
  vtk_note = fmt::format("{} ({} frame(s))", out.destination_of(vtk_written.back()).string(), main.frames.size());
  if (c.parameters.halves == 2) {
    const auto upper_written = coupling::write_surface_series(surface_frames(c, contact, main.frames, true),
                                                              (out.staging() / "vtk").string(), "bore_upper");
    vtk_note += fmt::format(", upper half {}", out.destination_of(upper_written.back()).string());
  }
  for (std::size_t h = 0; h < stress.size(); ++h) {
    const auto written_stress = write_line_stress(stress[h], out.staging() / "vtk", h == 0 ? "subsurface" : "subsurface_upper");
    vtk_note += fmt::format("; subsurface stress{} {} ({} frames)", h == 0 ? "" : " (upper half)",
                            out.destination_of(written_stress.back()).string(), stress[h].frames.size());
  }
#else
  (void)out, (void)c, (void)main, (void)stress;
#endif
  return vtk_note;
}

void print_set_up(const JournalBearingCase &c) {
  const auto &p = c.parameters;
  fmt::print("  friction          {}\n", c.friction->description());
  fmt::print("  bearing           R = {:g} mm, c = {:g} um, L = {:g} mm, W = {:g} N; arc +-{:g} rad on {} nodes\n",
             1e3 * p.bore.shaft_radius, 1e6 * p.bore.clearance, 1e3 * p.bore.axial_width, p.load,
             p.bore.arc_half_angle, p.bore.nodes);
  if (p.halves == 2)
    fmt::print("  bearing halves    2, pressed on the shaft in opposite directions with W = {:g} N (lower) and {:g} N "
               "(upper): two contacts, each its own pressure, wear and friction state\n",
               p.half_load(0), p.half_load(1));
  else
    fmt::print("  bearing halves    1 (single-contact model; the thesis loads two halves: bearing.halves = 2)\n");
  fmt::print("  drive             {:g} rad linear over {:g} s, then {:g} rad/s; coupling k = {:.6g} N m/rad, c = {:.3g} N m s/rad\n",
             p.ramp_angle, p.ramp_time, p.run_speed, p.coupling_stiffness, p.coupling_damping);
  fmt::print("  drive stiffness   {} shaft torsion G J / L = {:.6g} N m/rad (d = {:g} mm, L = {:g} mm, "
             "G = E / (2 (1 + nu)), J = pi d^4 / 32)\n",
             c.stiffness_overridden ? "drive.stiffness overrides the" : "from the", c.shaft_stiffness,
             1e3 * c.shaft_diameter, 1e3 * c.shaft_length);
}

void print_results(const JournalBearingCase &c, const Curve &main) {
  const auto &s = main.summary;
  const auto &p = c.parameters;
  const auto &r = main.report;
  const auto &first = main.samples.front(), &last = main.samples.back();
  fmt::print("  break-away        {}{}\n", or_none(s.breakaway_time),
             s.breakaway_time == 0.0 && std::abs(first.coupling_torque) > std::abs(first.friction_torque)
                 ? fmt::format(" (at once: the coupling torque at the start, the damper's c w_d = {:.4g} N m, exceeds "
                               "the static limit {:.4g} N m; spring alone: mu_s N R / (k w_d) = {:.3g} s)",
                               std::abs(first.coupling_torque), std::abs(first.friction_torque),
                               std::abs(first.friction_torque) / (p.coupling_stiffness * std::abs(p.drive_speed(0.0))))
                 : std::string());
  fmt::print("  peak friction     {:.6g} N at t = {:.6g} s\n", s.peak_friction_force, s.peak_time);
  fmt::print("  start friction    {:.6g} N (largest |F| up to the first slip sample)\n", s.start_friction_force);
  fmt::print("  steady state      {} (friction force and journal speed within {:g} % of final values from then on)\n",
             or_none(s.steady_time), 100 * continuum::JournalBearingSummary::steady_tolerance);
  fmt::print("  steady mu         {:.6g} = F / N (N = {:.6g} N, pressure integral); F = {:.6g} N\n", s.steady_mu,
             last.normal_force, s.steady_friction_force);
  fmt::print("  contact           half-angle {:.4g} -> {:.4g} rad, peak pressure {:.4g} -> {:.4g} MPa\n",
             s.initial_half_angle, s.final_half_angle, 1e-6 * s.initial_peak_pressure, 1e-6 * s.final_peak_pressure);
  fmt::print("  wear              {:.6g} mm^3 over s = {:.6g} m; {} wear updates, stable step {} = {:.4g} m\n",
             1e9 * s.wear_volume, last.distance, r.wear_updates,
             c.friction->state_law() ? "2/(k_c max w/p)" : "2H/(k k_c)", r.stable_wear_step);
  fmt::print("  CVODE             {} steps, {} break-away, {} re-stick events\n", r.steps, r.breakaway_times.size(),
             r.restick_times.size());
  if (p.halves == 2) {
    const auto &lower = last.half[0], &upper = last.half[1];
    fmt::print("  halves at end     lower: T_f = {:.6g} N m, N = {:.6g} N, wear {:.6g} mm^3, peak {:.4g} MPa; "
               "upper: T_f = {:.6g} N m, N = {:.6g} N, wear {:.6g} mm^3, peak {:.4g} MPa\n",
               lower.friction_torque, lower.normal_force, 1e9 * lower.wear_volume, 1e-6 * lower.peak_pressure,
               upper.friction_torque, upper.normal_force, 1e9 * upper.wear_volume, 1e-6 * upper.peak_pressure);
  }
}

void print_state_law(const JournalBearingCase &c, const Curve &main, std::vector<std::string> &warnings) {
  const auto *law = c.friction->state_law();
  const auto &r = main.report;
  if (!law || !r.range_use) return;
  const auto &p = c.parameters;
  const auto &first = main.samples.front(), &last = main.samples.back();
  fmt::print("  state law         {} (p {:.4g} .. {:.4g} Pa, h 0 .. {:.4g} m); the bore is the rough body\n", law->path,
             law->law->pressure().front(), law->law->pressure().back(), law->law->worn_depth().back());
  fmt::print("  mu_eff            {:.6g} -> {:.6g} (pressure-weighted per half, N-weighted over the halves); static "
             "{:.6g} ({})\n",
             first.mu_eff, last.mu_eff, r.state_law_static,
             law->mu_static ? "friction.mu_static" : "the law's peak over h at the initial pressures");
  for (int h = 0; h < p.halves; ++h)
    fmt::print("  {} h         mean {:.4g} m, max {:.4g} m; shaft worn volume under it {:.6g} mm^3 "
               "(counterface_wear_rate)\n",
               h ? "upper" : "lower", last.half[h].h_mean, last.half[h].h_max, 1e9 * last.half[h].counterface_volume);
  if (const auto &film = law->film)
    for (int h = 0; h < p.halves; ++h)
      fmt::print("  {} film    coverage {:.4g} -> {:.4g} (load-weighted over the bore), f {:.4g} covered / {:.4g} "
                 "bare, s_r {:.4g} m, k_g {:.4g} 1/s\n",
                 h ? "upper" : "lower", first.half[h].film_coverage, last.half[h].film_coverage, film->f_film,
                 film->f_base, film->removal_distance, film->growth_rate);
  fmt::print("  law lookups       {}\n", continuum::describe(*r.range_use, *law->law));
  if (auto w = continuum::out_of_range_warning(*r.range_use, *law->law, law->policy); !w.empty())
    warnings.push_back(std::move(w));
  if (const auto cell = coupling::cell_scale(*law->law)) {
    // narrowest: the unworn contact; a node spans the bearing's length
    const coupling::ScaleSeparation sep{*cell, 2.0 * p.bore.shaft_radius * main.summary.initial_half_angle,
                                        p.bore.shaft_radius * 2.0 * p.bore.arc_half_angle / p.bore.nodes *
                                            p.bore.axial_width};
    fmt::print("  scale separation  {}\n", coupling::describe(sep));
    if (auto w = coupling::scale_separation_warning(sep); !w.empty()) warnings.push_back(std::move(w));
  }
}

void print_one_contact(const Curve &main, const Curve &one) {
  const auto &s = main.summary, &o1 = one.summary;
  const auto ratio = [](double a, double b) { return b != 0.0 ? fmt::format("x{:.4g}", a / b) : std::string("n/a"); };
  const auto initial_normal = [](const Curve &k) { return k.samples.front().normal_force; };
  fmt::print("  second half       vs one contact (same case, bearing.halves = 1): N {:.6g} -> {:.6g} N ({}), "
             "peak friction {:.6g} -> {:.6g} N ({}), break-away {} -> {}, steady state {} -> {}, "
             "steady mu {:.6g} -> {:.6g}, wear volume {:.6g} -> {:.6g} mm^3 ({}), re-sticks {} -> {}\n",
             initial_normal(one), initial_normal(main), ratio(initial_normal(main), initial_normal(one)),
             o1.peak_friction_force, s.peak_friction_force, ratio(s.peak_friction_force, o1.peak_friction_force),
             or_none(o1.breakaway_time), or_none(s.breakaway_time), or_none(o1.steady_time), or_none(s.steady_time),
             o1.steady_mu, s.steady_mu, 1e9 * o1.wear_volume, 1e9 * s.wear_volume, ratio(s.wear_volume, o1.wear_volume),
             one.report.restick_times.size(), main.report.restick_times.size());
}

void print_sweep(const JournalBearingCase &c, const std::vector<Curve> &sweep) {
  if (sweep.empty()) return;
  fmt::print("  mu0 sweep         {:>6} {:>12} {:>12} {:>12} {:>10}\n", "mu0", "peak F (N)", "break-away", "steady",
             "steady mu");
  for (std::size_t k = 0; k < sweep.size(); ++k) {
    const auto &m = sweep[k].summary;
    fmt::print("                    {:>6.3g} {:>12.6g} {:>12} {:>12} {:>10.4g}\n", c.sweep_mu0[k],
               m.peak_friction_force, or_none(m.breakaway_time), or_none(m.steady_time), m.steady_mu);
  }
}

int run(const Options &o, const PlotRunner &plot) {
  // A [lubrication] table selects the mixed-lubrication run-in (doc/lubricated_journal_bearing.md).
  if (is_lubricated_case(o.case_path))
    return run_lubricated_bearing({o.case_path, o.output_dir, o.law_path, o.no_plot, o.stribeck}, plot);
  if (o.stribeck) throw InputError("--stribeck: needs a lubricated case (a [lubrication] table in " + o.case_path + ")");
  const JournalBearingCase c = read_journal_bearing_case(o.case_path, o.law_path);
  const Computed r = compute(o, c);

  // Everything is computed; the output set is staged and moved in only when complete.
  StagedOutput out(o.output_dir, {"journal_bearing.csv", "journal_bearing_summary.csv", "journal_bearing.png", "journal_bearing_sweep.csv",
                                  "journal_bearing_sweep_summary.csv", "journal_bearing_mu0.png", "vtk/bore.pvd",
                                  "vtk/bore_*.vts", "vtk/bore_upper.pvd", "vtk/subsurface.pvd", "vtk/subsurface_*.vts",
                                  "vtk/subsurface_upper.pvd"});
  const std::vector<LineStressReport> stress = subsurface_stress(c, r.main);
  const std::vector<std::string> written = write_curves(out, o, c, r, plot);
  const std::string vtk_note = write_vtk(out, c, r.main, stress);
  out.commit();

  fmt::print("runin journal-bearing: {}\n  {}\n", c.path, c.title);
  print_set_up(c);
  print_results(c, r.main);
  std::vector<std::string> warnings;
  print_state_law(c, r.main, warnings);
  for (const auto &report : stress) print_line_stress(report, warnings);
  for (const auto &w : warnings) fmt::print("  {}\n", w);
  if (r.one_contact) print_one_contact(r.main, *r.one_contact);
  print_sweep(c, r.sweep);
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  fmt::print("\n  VTK               {}\n", vtk_note);
  return 0;
}

}  // namespace

Subcommand add_journal_bearing_command(CLI::App &app, PlotRunner plot) {
  auto options = std::make_shared<Options>();
  auto *cmd = app.add_subcommand(
      "journal-bearing",
      "Journal bearing run-in: dry (contact, friction torque, wear; thesis ch. 5), or lubricated with a [lubrication] "
      "table (mixed lubrication on a state law, Stribeck sweep)");
  cmd->add_option("case", options->case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  cmd->add_option("--law", options->law_path,
                  "law file: from fit-law (friction.model = \"law_file\"), or from homogenise (\"state_law\", overrides friction.law)");
  cmd->add_option("--output-dir", options->output_dir, "directory for journal_bearing.csv (lubricated: lubricated.csv), plots and vtk/")->required()
      ->check(output_directory());
  cmd->add_flag("--no-plot", options->no_plot, "write CSV and VTK only");
  cmd->add_flag("--stribeck", options->stribeck,
                "lubricated case: also run the Stribeck sweep (as a [stribeck] table does), write stribeck.csv");
  cmd->add_option("--max-wear-updates", options->max_wear_updates,
                  "stop with an error instead of running more wear updates (contact re-solves) than this")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  return {cmd, [options, plot = std::move(plot)] { return run(*options, plot); }};
}

}  // namespace runin::cli
