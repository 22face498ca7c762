#include "cli/cmd_piston_ring.h"

#include <cstdio>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/case_file.h"
#include "cli/piston_ring_case.h"
#include "cli/staged_file.h"
#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

namespace fs = std::filesystem;
using continuum::PistonRingSample;
constexpr double kPi = 3.14159265358979323846;

struct Options {
  std::string case_path, output_dir;
  std::optional<std::string> law_path;
  bool no_plot = false;
};

struct WearRow {
  double ring = 0.0, liner = 0.0, width = 0.0, peak = 0.0, mean = 0.0;
};

// Profiles and pressures at one output time, for the VTK frames.
struct WearSnapshot {
  double time = 0.0, ring_position = 0.0;
  std::vector<double> liner_wear, liner_pressure, ring_wear, ring_pressure;
};

struct Curve {
  std::vector<PistonRingSample> samples;
  continuum::SolveReport report;
  continuum::PistonRingSummary summary;
};

Curve run_dynamics(const PistonRingCase &c, const continuum::SlidingFriction &friction) {
  const continuum::PistonRingSystem system = [&] {
    try {
      return continuum::PistonRingSystem(c.parameters, friction);
    } catch (const std::invalid_argument &e) {
      throw InputError(c.path + ": key 'ring': " + e.what());
    }
  }();
  Curve curve;
  curve.report = continuum::simulate(system, c.run, [&](const PistonRingSample &s) { curve.samples.push_back(s); });
  if (!curve.report.ok())
    throw std::runtime_error(std::string(continuum::to_string(curve.report.status)) + ": " + curve.report.message);
  curve.summary = continuum::summarise(system, curve.samples);
  return curve;
}

// Wear along the computed trajectory (wear changes the pressure distribution, not W or mu, so it
// does not feed back into the dynamics).
struct WearPass {
  std::vector<WearRow> rows;
  std::vector<WearSnapshot> snapshots;
  double initial_peak = 0.0;
};

WearSnapshot snapshot(const continuum::RingLinerWear &wear, const PistonRingSample &s) {
  WearSnapshot snap;
  snap.time = s.t;
  snap.ring_position = s.ring_position;
  snap.liner_wear = wear.liner_wear();
  snap.liner_pressure = wear.liner_pressure(s.ring_position, s.normal_load);
  snap.ring_wear = wear.ring_wear();
  snap.ring_pressure = wear.pressure(s.ring_position, s.normal_load).pressure;
  return snap;
}

WearPass run_wear(continuum::RingLinerWear &wear, const std::vector<PistonRingSample> &samples,
                  const std::vector<double> &vtk_times) {
  WearPass pass;
  std::vector<double> times = vtk_times;
  std::sort(times.begin(), times.end());
  std::size_t next_frame = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto &s = samples[i];
    if (i > 0) {
      const auto &prev = samples[i - 1];
      bool ok = true;
      try {
        ok = wear.slide(prev.ring_position, s.ring_position, prev.normal_load, s.normal_load);
      } catch (const std::out_of_range &e) {
        throw std::runtime_error(fmt::format("wear at t = {:.6g} s: {}", s.t, e.what()));
      }
      if (!ok)
        throw std::runtime_error(fmt::format("{} at t = {:.6g} s: {} (wear.k = {:g}; not a run-in any more)",
                                             continuum::to_string(wear.status()), s.t, wear.message(),
                                             wear.archard().coefficient()));
    }
    const auto contact = wear.pressure(s.ring_position, s.normal_load);
    if (i == 0) pass.initial_peak = contact.peak;
    pass.rows.push_back({wear.ring_volume(), wear.liner_volume(), contact.width, contact.peak, contact.mean});
    while (next_frame < times.size() && s.t >= times[next_frame] - 1e-12 * std::max(1.0, s.t)) {
      pass.snapshots.push_back(snapshot(wear, s));
      ++next_frame;
    }
  }
  return pass;
}

const char *kColumns =
    "t_s,crank_angle_deg,piston_position_m,piston_velocity_m_s,ring_position_m,speed_m_s,sliding_distance_m,"
    "friction_force_N,land_force_N,normal_load_N,mu,mu_law,state_slip,wear_ring_m3,wear_liner_m3,wear_volume_m3,"
    "contact_width_m,peak_pressure_Pa,mean_pressure_Pa,roughness";

std::string csv_text(const std::vector<PistonRingSample> &samples, const std::vector<WearRow> &wear) {
  std::string text = std::string(kColumns) + "\n";
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto &s = samples[i];
    const auto &w = wear[i];
    text += fmt::format(
        "{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{},{:.12g},"
        "{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n",
        s.t, s.crank_angle * 180.0 / kPi, s.piston_position, s.piston_velocity, s.ring_position, s.speed, s.distance,
        s.friction_force, s.land_force, s.normal_load, s.mu, s.mu_law, s.state == continuum::ContactState::Slip ? 1 : 0,
        w.ring, w.liner, w.ring + w.liner, w.width, w.peak, w.mean, s.roughness);
  }
  return text;
}

#ifdef RUNIN_HAVE_VTK
std::vector<std::string> write_frames(const continuum::RingLinerWear &wear, const std::vector<WearSnapshot> &snaps,
                                      int around, const fs::path &dir) {
  const auto &ws = wear.settings();
  const double radius = 0.5 * ws.bore;
  std::vector<coupling::SurfaceFrame> liner, ring;
  for (const auto &snap : snaps) {
    coupling::SurfaceFrame lf, rf;
    lf.time = rf.time = snap.time;
    lf.nu = ws.liner_cells;
    rf.nu = ws.ring_cells;
    lf.nv = rf.nv = around;
    std::vector<double> lw, lp, rw, rp;
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * kPi * j / around;
      for (int i = 0; i < ws.liner_cells; ++i) {
        lf.points.push_back({radius * std::cos(phi), radius * std::sin(phi), wear.liner_cell_centre(i)});
        lw.push_back(snap.liner_wear[i]);
        lp.push_back(snap.liner_pressure[i]);
      }
      for (int i = 0; i < ws.ring_cells; ++i) {
        rf.points.push_back(
            {radius * std::cos(phi), radius * std::sin(phi), snap.ring_position + wear.ring_cell_centre(i)});
        rw.push_back(snap.ring_wear[i]);
        rp.push_back(snap.ring_pressure[i]);
      }
    }
    lf.fields = {{"pressure", lp}, {"wear_depth", lw}};
    rf.fields = {{"pressure", rp}, {"wear_depth", rw}};
    liner.push_back(std::move(lf));
    ring.push_back(std::move(rf));
  }
  auto written = coupling::write_surface_series(liner, (dir / "vtk").string(), "liner");
  const auto more = coupling::write_surface_series(ring, (dir / "vtk").string(), "ring_face");
  written.insert(written.end(), more.begin(), more.end());
  return written;
}
#endif

// The wear pass visits every ring and liner cell at every sample, and each VTK frame holds every cell around
// the bore: announced before a run that takes long or needs much memory. The rates were measured on a 2-core
// VM (doc/hardening.md): 30-90 ns per cell and sample, 40 bytes per VTK point (3 coordinates, 2 fields).
void announce_large_wear_pass(const PistonRingCase &c, std::size_t samples) {
  constexpr double kSecondsPerCellSample = 60e-9, kBytesPerPoint = 40.0;
  const auto &w = c.wear_settings;
  const double cells = static_cast<double>(w.ring_cells) + static_cast<double>(w.liner_cells);
  const double seconds = kSecondsPerCellSample * cells * static_cast<double>(samples);
  const double megabytes =
      kBytesPerPoint * cells * c.circumferential_points * static_cast<double>(c.vtk_times.size()) / 1e6;
  if (seconds > 5.0 || megabytes > 500.0)
    fmt::print("  note: large wear pass: {} samples x {} cells (ring {}, liner {}), {} VTK frames x {} points around: "
               "about {:.0f} s and {:.0f} MB of memory and disk (estimate)\n",
               samples, cells, w.ring_cells, w.liner_cells, c.vtk_times.size(), c.circumferential_points,
               std::ceil(seconds), megabytes);
  std::fflush(stdout);  // seen before the long part starts, also through a pipe
}

std::string or_none(double t) { return t < 0.0 ? std::string("none") : fmt::format("{:.6g} s", t); }

// Wear run-in (crank motion): per cycle the largest peak contact pressure; settled from the first
// cycle after which every cycle's value is within 1 % of the last full cycle's. -1: not settled.
double pressure_settling_time(const continuum::PistonRingParameters &p, const std::vector<PistonRingSample> &samples,
                              const std::vector<WearRow> &rows) {
  if (p.motion != continuum::PistonMotion::Crank) return -1.0;
  const double period = (p.gas.empty() ? 2.0 * kPi : p.gas.cycle) / p.crank_speed;
  const long cycles = static_cast<long>(std::floor(samples.back().t / period + 1e-9));
  if (cycles < 3) return -1.0;
  std::vector<double> peak(cycles, 0.0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const long cycle = static_cast<long>(std::floor(samples[i].t / period));
    if (cycle < cycles) peak[cycle] = std::max(peak[cycle], rows[i].peak);
  }
  long first = cycles - 1;
  while (first > 0 && std::abs(peak[first - 1] - peak.back()) <= 0.01 * peak.back()) --first;
  return first < cycles - 1 ? first * period : -1.0;
}

int run(const Options &o, const PlotRunner &plot) {
  const PistonRingCase c = read_piston_ring_case(o.case_path, o.law_path);
  const auto &p = c.parameters;
  const Curve curve = run_dynamics(c, *c.friction);
  announce_large_wear_pass(c, curve.samples.size());
  continuum::RingLinerWear wear(c.wear_settings, *c.archard);
  const WearPass wear_pass = run_wear(wear, curve.samples, c.vtk_times);

  struct SweepRow {
    double mu0;
    Curve curve;
  };
  std::vector<SweepRow> sweep;
  for (double mu0 : c.sweep_mu0) sweep.push_back({mu0, run_dynamics(c, piston_ring_friction_with_mu0(c, mu0))});

  // Everything is computed; the output set is staged and moved in only when complete.
  StagedOutput out(o.output_dir, {"piston_ring.csv", "piston_ring_liner.csv", "piston_ring_face.csv",
                                  "piston_ring_mu0.csv", "piston_ring.png", "piston_ring_mu0.png", "vtk/liner.pvd",
                                  "vtk/liner_*.vts", "vtk/ring_face.pvd", "vtk/ring_face_*.vts"});
  out.write("piston_ring.csv", csv_text(curve.samples, wear_pass.rows));
  {
    const double tdc = p.crank.top_dead_centre();
    std::string text = "x_m,distance_from_tdc_m,wear_depth_m\n";
    for (int j = 0; j < c.wear_settings.liner_cells; ++j) {
      const double x = wear.liner_cell_centre(j);
      text += fmt::format("{:.12g},{:.12g},{:.12g}\n", x, tdc - x, wear.liner_wear()[j]);
    }
    out.write("piston_ring_liner.csv", text);
  }
  {
    const auto &last = curve.samples.back();
    const auto contact = wear.pressure(last.ring_position, last.normal_load);
    std::string text = "z_m,crown_m,wear_depth_m,final_pressure_Pa\n";
    for (int i = 0; i < c.wear_settings.ring_cells; ++i) {
      const double z = wear.ring_cell_centre(i), u = 2.0 * z / p.ring_width;
      text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g}\n", z, c.wear_settings.crown_height * u * u,
                          wear.ring_wear()[i], contact.pressure[i]);
    }
    out.write("piston_ring_face.csv", text);
  }
  std::vector<std::string> written = {"piston_ring.csv", "piston_ring_liner.csv", "piston_ring_face.csv"};
  if (!sweep.empty()) {
    std::string text = "mu0,t_s,friction_force_N,land_force_N,speed_m_s,state_slip\n";
    for (const auto &row : sweep)
      for (const auto &s : row.curve.samples)
        text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{}\n", row.mu0, s.t, s.friction_force,
                            s.land_force, s.speed, s.state == continuum::ContactState::Slip ? 1 : 0);
    out.write("piston_ring_mu0.csv", text);
    written.push_back("piston_ring_mu0.csv");
  }
  if (!o.no_plot) {
    plot("plot_piston_ring.py", {"curve", out.file("piston_ring.csv").string(), out.file("piston_ring_liner.csv").string(),
                                 out.file("piston_ring_face.csv").string(), out.file("piston_ring.png").string(),
                                 "--title", c.title});
    written.push_back("piston_ring.png");
    if (!sweep.empty()) {
      plot("plot_piston_ring.py", {"sweep", out.file("piston_ring_mu0.csv").string(),
                                   out.file("piston_ring_mu0.png").string(), "--title", c.title});
      written.push_back("piston_ring_mu0.png");
    }
  }
  std::vector<std::string> vtk_files;
#ifdef RUNIN_HAVE_VTK
  vtk_files = write_frames(wear, wear_pass.snapshots, c.circumferential_points, out.staging());
#endif
  out.commit();

  // One-screen summary.
  const auto &s = curve.summary;
  const auto &last = curve.samples.back();
  const double stroke = 2.0 * p.crank.crank_radius;
  const double natural = std::sqrt(p.land_stiffness / p.ring_mass) / (2.0 * kPi);
  const auto max_liner = std::max_element(wear.liner_wear().begin(), wear.liner_wear().end());
  const int max_j = static_cast<int>(max_liner - wear.liner_wear().begin());
  fmt::print("runin piston-ring: {}\n  {}\n", o.case_path, c.title);
  fmt::print("  friction          {}\n", c.friction->description());
  if (p.motion == continuum::PistonMotion::Ramp)
    fmt::print("  kinematics        ramp: x from eq. 6.1 at {:g} deg before TDC to TDC ({:.6g} mm) in {:g} s; "
               "r = {:g} mm, l = {:g} mm\n",
               p.start_angle * 180.0 / kPi, 1e3 * (p.crank.top_dead_centre() - p.crank.position(p.start_angle)),
               p.ramp_time, 1e3 * p.crank.crank_radius, 1e3 * p.crank.link_length);
  else
    fmt::print("  kinematics        crank: eq. 6.1 at {:.6g} rpm from {:g} deg before TDC; r = {:g} mm, l = {:g} mm, "
               "stroke {:g} mm, {:.4g} revolutions\n",
               p.crank_speed * 60.0 / (2.0 * kPi), p.start_angle * 180.0 / kPi, 1e3 * p.crank.crank_radius,
               1e3 * p.crank.link_length, 1e3 * stroke, last.t * p.crank_speed / (2.0 * kPi));
  fmt::print("  ring              W = {:.6g} N from {:.4g} MPa ring tension{}; m = {:.4g} kg, land k = {:.4g} N/m, "
             "zeta = {:g} ({:.4g} Hz)\n",
             p.elastic_pressure * p.contact_area(), 1e-6 * p.elastic_pressure, p.gas.empty() ? "" : " + gas table",
             p.ring_mass, p.land_stiffness, c.land_damping_ratio, natural);
  fmt::print("  break-away        {}\n", or_none(s.breakaway_time));
  fmt::print("  peak friction     {:.6g} N at t = {:.6g} s (liner); peak land force {:.6g} N\n", s.peak_friction_force,
             s.peak_time, s.peak_land_force);
  fmt::print("  steady state      {} ({})\n", or_none(s.steady_time), s.steady_criterion);
  fmt::print("  start friction    {:.6g} N (largest |F| up to the first slip sample)\n", s.start_friction_force);
  fmt::print("  steady mu         {:.6g}, friction force {:.6g} N\n", s.steady_mu, s.steady_friction_force);
  if (p.motion == continuum::PistonMotion::Crank)
    fmt::print("  pressure run-in   {} (cycle-max peak contact pressure within 1 % of the last cycle's from then on)\n",
               or_none(pressure_settling_time(p, curve.samples, wear_pass.rows)));
  fmt::print("  sliding           {:.6g} m in {} break-away and {} re-stick events\n", last.distance,
             curve.report.breakaway_times.size(), curve.report.restick_times.size());
  fmt::print("  wear volume       {:.6g} m^3 (ring {:.6g}, liner {:.6g}); Archard k W s / H = {:.6g} m^3\n",
             wear.ring_volume() + wear.liner_volume(), wear.ring_volume(), wear.liner_volume(),
             wear.archard_volume());
  fmt::print("  liner wear        max {:.6g} um at {:.6g} mm from TDC\n", 1e6 * *max_liner,
             1e3 * (p.crank.top_dead_centre() - wear.liner_cell_centre(max_j)));
  fmt::print("  ring pressure     peak {:.6g} MPa at start -> {:.6g} MPa at end (crown {:g} um)\n",
             1e-6 * wear_pass.initial_peak, 1e-6 * wear_pass.rows.back().peak,
             1e6 * c.wear_settings.crown_height);
  fmt::print("  wear updates      {} (step {:.4g} m = {} x stable_slip_step)\n", wear.updates(), wear.step(),
             c.wear_settings.fixed_step > 0.0 ? std::string("fixed, not") : fmt::format("{:g}", c.wear_settings.step_safety));
  fmt::print("  CVODE             {} steps\n", curve.report.steps);
  if (!sweep.empty()) {
    fmt::print("  mu0 sweep         {:>6} {:>12} {:>12} {:>12} {:>10}\n", "mu0", "peak F (N)", "break-away", "steady",
               "steady mu");
    for (const auto &row : sweep)
      fmt::print("                    {:>6g} {:>12.6g} {:>12} {:>12} {:>10.4g}\n", row.mu0,
                 row.curve.summary.peak_friction_force, or_none(row.curve.summary.breakaway_time),
                 or_none(row.curve.summary.steady_time), row.curve.summary.steady_mu);
  }
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  if (!vtk_files.empty())
    fmt::print(", {} VTK files ({})", vtk_files.size(), out.destination_of(vtk_files.back()).string());
  fmt::print("\n");
  return 0;
}

}  // namespace

Subcommand add_piston_ring_command(CLI::App &app, PlotRunner plot) {
  auto options = std::make_shared<Options>();
  auto *cmd = app.add_subcommand("piston-ring", "Piston ring in a cylinder: run-in friction and wear (thesis ch. 6)");
  cmd->add_option("case", options->case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  cmd->add_option("--law", options->law_path, "law file from fit-law, for friction.model = \"law_file\"");
  cmd->add_option("--output-dir", options->output_dir,
                  "directory for piston_ring*.csv, piston_ring*.png and vtk/ (liner and ring-face frames)")
      ->required()
      ->check(non_empty_path());
  cmd->add_flag("--no-plot", options->no_plot, "write the CSV and VTK files only");
  return {cmd, [options, plot = std::move(plot)] { return run(*options, plot); }};
}

}  // namespace runin::cli
