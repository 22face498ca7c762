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
#include "cli/line_stress_report.h"
#include "cli/piston_ring_case.h"
#include "cli/cmd_piston_ring_lubricated.h"
#include "cli/lubricated_ring_case.h"
#include "cli/run_summary.h"
#include "cli/staged_file.h"
#include "continuum/piston_ring.h"
#include "continuum/piston_ring_wear.h"
#include "continuum/state_law_splitting.h"
#include "coupling/scale_separation.h"
#include "continuum/ring_liner_wear.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

// The event guard names its key: a real case with more events raises run.max_events.
std::string events_hint(continuum::SolveStatus status) {
  return status == continuum::SolveStatus::TooManyEvents ? " (run.max_events)" : std::string();
}


namespace fs = std::filesystem;
using continuum::PistonRingSample;
constexpr double kPi = 3.14159265358979323846;

struct Options {
  std::string case_path, output_dir;
  std::optional<std::string> law_path;
  bool no_plot = false;
};

using WearRow = continuum::RingWearRow;
using WearSnapshot = continuum::RingWearSnapshot;
using WearPass = continuum::RingWearPass;

struct Curve {
  std::vector<PistonRingSample> samples;
  continuum::SolveReport report;
  continuum::PistonRingSummary summary;
};

continuum::PistonRingSystem ring_system(const PistonRingCase &c, const PistonRingOfPack &ring,
                                        const continuum::SlidingFriction &friction) {
  try {
    return continuum::PistonRingSystem(ring.parameters, friction);
  } catch (const std::invalid_argument &e) {
    throw InputError(c.path + ": key '" + (c.rings.size() > 1 ? "ring_pack" : "ring") + "': " + e.what());
  }
}

Curve run_dynamics(const PistonRingCase &c, const PistonRingOfPack &ring, const continuum::SlidingFriction &friction) {
  const auto system = ring_system(c, ring, friction);
  Curve curve;
  curve.report = continuum::simulate(system, c.run, [&](const PistonRingSample &s) { curve.samples.push_back(s); });
  if (!curve.report.ok())
    throw std::runtime_error((c.rings.size() > 1 ? "ring " + ring.name + ": " : std::string()) +
                             continuum::to_string(curve.report.status) + ": " + curve.report.message +
                             events_hint(curve.report.status));
  curve.summary = continuum::summarise(system, curve.samples);
  for (auto &sample : curve.samples) sample.ring_position += ring.position;  // groove centre on the piston
  return curve;
}

const char *kColumns =
    "t_s,crank_angle_deg,piston_position_m,piston_velocity_m_s,ring_position_m,speed_m_s,sliding_distance_m,"
    "friction_force_N,land_force_N,normal_load_N,mu,mu_law,state_slip,wear_ring_m3,wear_liner_m3,wear_volume_m3,"
    "contact_width_m,peak_pressure_Pa,mean_pressure_Pa,roughness";

std::string csv_text(const std::vector<PistonRingSample> &samples, const std::vector<WearRow> &wear,
                     bool state_law = false, bool film = false) {
  std::string text = std::string(kColumns) + (state_law ? ",mu_eff,h_mean_m,h_max_m" : "") +
                     (film ? ",film_coverage\n" : "\n");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto &s = samples[i];
    const auto &w = wear[i];
    text += fmt::format(
        "{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{},{:.12g},"
        "{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n",
        s.t, s.crank_angle * 180.0 / kPi, s.piston_position, s.piston_velocity, s.ring_position, s.speed, s.distance,
        s.friction_force, s.land_force, s.normal_load, s.mu, s.mu_law, s.state == continuum::ContactState::Slip ? 1 : 0,
        w.ring, w.liner, w.ring + w.liner, w.width, w.peak, w.mean, s.roughness);
    if (state_law) {
      text.pop_back();
      text += fmt::format(",{:.12g},{:.12g},{:.12g}\n", w.mu_eff, w.h_mean, w.h_max);
    }
    if (film) {
      text.pop_back();
      text += fmt::format(",{:.12g}\n", w.film_coverage);
    }
  }
  return text;
}

#ifdef RUNIN_HAVE_VTK
// The liner (shared by the rings: ring A's snapshots hold it) and each ring face ("ring_face" for
// ring A, "ring_face_B" and on for the others).
std::vector<std::string> write_frames(const std::vector<continuum::RingLinerWear> &wears,
                                      const std::vector<WearPass> &passes, const std::vector<PistonRingOfPack> &rings,
                                      int around, const fs::path &dir) {
  const auto &ws = wears.front().settings();
  const double radius = 0.5 * ws.bore;
  std::vector<coupling::SurfaceFrame> liner;
  std::vector<std::vector<coupling::SurfaceFrame>> faces(wears.size());
  for (std::size_t f = 0; f < passes.front().snapshots.size(); ++f) {
    {
      const auto &snap = passes.front().snapshots[f];
      coupling::SurfaceFrame lf;
      lf.time = snap.time;
      lf.nu = ws.liner_cells;
      lf.nv = around;
      std::vector<double> lw, lp(snap.liner_pressure.size(), 0.0);
      for (const auto &pass : passes)  // liner pressure: all rings
        for (std::size_t j = 0; j < lp.size(); ++j) lp[j] += pass.snapshots[f].liner_pressure[j];
      std::vector<double> lpp;
      for (int j = 0; j < around; ++j) {
        const double phi = 2.0 * kPi * j / around;
        for (int i = 0; i < ws.liner_cells; ++i) {
          lf.points.push_back({radius * std::cos(phi), radius * std::sin(phi), wears.front().liner_cell_centre(i)});
          lw.push_back(snap.liner_wear[i]);
          lpp.push_back(lp[i]);
        }
      }
      lf.fields = {{"pressure", lpp}, {"wear_depth", lw}};
      liner.push_back(std::move(lf));
    }
    for (std::size_t k = 0; k < wears.size(); ++k) {
      const auto &snap = passes[k].snapshots[f];
      const auto &wk = wears[k];
      coupling::SurfaceFrame rf;
      rf.time = snap.time;
      rf.nu = wk.settings().ring_cells;
      rf.nv = around;
      std::vector<double> rw, rp, rmu;
      for (int j = 0; j < around; ++j) {
        const double phi = 2.0 * kPi * j / around;
        for (int i = 0; i < rf.nu; ++i) {
          rf.points.push_back({radius * std::cos(phi), radius * std::sin(phi), snap.ring_position + wk.ring_cell_centre(i)});
          rw.push_back(snap.ring_wear[i]);
          rp.push_back(snap.ring_pressure[i]);
          if (!snap.ring_mu.empty()) rmu.push_back(snap.ring_mu[i]);
        }
      }
      rf.fields = {{"pressure", rp}, {"wear_depth", rw}};
      if (!rmu.empty()) {  // state law
        rf.fields.push_back({"h", rw});
        rf.fields.push_back({"mu", rmu});
      }
      faces[k].push_back(std::move(rf));
    }
  }
  auto written = coupling::write_surface_series(liner, (dir / "vtk").string(), "liner");
  for (std::size_t k = 0; k < wears.size(); ++k) {
    const auto more =
        coupling::write_surface_series(faces[k], (dir / "vtk").string(), k == 0 ? "ring_face" : "ring_face_" + rings[k].name);
    written.insert(written.end(), more.begin(), more.end());
  }
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

struct PackRun {
  std::vector<Curve> rings;                          // per ring, own samples and summary
  std::vector<std::vector<PistonRingSample>> grid;   // per ring on the common grid
  std::vector<PistonRingSample> pack;                // sums
  continuum::PistonRingSummary summary;              // of the sums
  long cvode_steps = 0;
  std::size_t breakaways = 0, resticks = 0;
};

// The pack from its rings' own curves: counters, the common output grid, the summed samples and their summary.
void assemble_pack(PackRun &r, const PistonRingCase &c, const continuum::SlidingFriction &friction) {
  std::vector<const std::vector<PistonRingSample> *> own;
  for (const auto &curve : r.rings) {
    own.push_back(&curve.samples);
    r.cvode_steps += curve.report.steps;
    r.breakaways += curve.report.breakaway_times.size();
    r.resticks += curve.report.restick_times.size();
  }
  r.grid = continuum::common_grid(own);
  r.pack = continuum::pack_samples(r.grid);
  if (c.rings.size() == 1) {
    r.summary = r.rings.front().summary;
  } else {
    const continuum::PistonRingSystem system(c.parameters, friction);  // motion and cycle of the summary
    r.summary = continuum::summarise(system, r.pack);
  }
}

PackRun run_pack(const PistonRingCase &c, const continuum::SlidingFriction &friction) {
  PackRun r;
  for (const auto &ring : c.rings) r.rings.push_back(run_dynamics(c, ring, friction));
  assemble_pack(r, c, friction);
  return r;
}

// friction.model = "state_law" (doc/state_law_continuum.md): each ring's dynamics and its face/liner wear advance
// together through the library's splitting driver (continuum::simulate_state_law). The rings of a pack run one after
// the other on the shared liner: ring B sees the liner as ring A left it at the end of the run, not at the same time
// (the liner is the counter body: it changes the faces' pressure only through its own small wear).
struct StateLawPack {
  PackRun run;
  std::vector<WearPass> passes;
  coupling::RangeUse use;
  std::vector<double> mu_static;  // per ring
};

// A ring's failed split as one line (`which` names the ring in a pack).
std::string split_error(const continuum::SplitReport &r, const continuum::StateLawFriction &law,
                        const std::string &which) {
  switch (r.status) {
    case continuum::SplitStatus::FastFailure:
      return which + continuum::to_string(r.fast.status) + ": " + r.fast.message + events_hint(r.fast.status);
    case continuum::SplitStatus::LawOutOfRange:
      return fmt::format("{}state law at t = {:g} s: {}{}", which, r.time, r.message,
                         law.policy == coupling::OutOfRange::Error
                             ? " (friction.out_of_range = \"archard\" takes friction at the nearest grid pressure, keeps "
                               "wear proportional to p and counts it)"
                             : "");
    case continuum::SplitStatus::InvalidState: return r.message;
    default: return which + r.message + " (not a run-in any more)";
  }
}

// Wear rows on the common grid: each ring's row of its last own sample at or before the grid time.
std::vector<WearRow> rows_on_grid(const std::vector<PistonRingSample> &own, const std::vector<WearRow> &own_rows,
                                  const std::vector<PistonRingSample> &grid) {
  std::vector<WearRow> rows;
  std::size_t j = 0;
  for (const auto &g : grid) {
    while (j + 1 < own.size() && own[j + 1].t <= g.t) ++j;
    rows.push_back(own_rows[j]);
  }
  return rows;
}

StateLawPack run_pack_state_law(const PistonRingCase &c, std::vector<continuum::RingLinerWear> &wear) {
  StateLawPack out;
  const auto *law = c.friction->state_law();
  for (std::size_t k = 0; k < c.rings.size(); ++k) {
    const auto &ring = c.rings[k];
    auto held = std::make_shared<continuum::StateLawFriction>(*law);  // this ring's own held values
    const auto system =
        ring_system(c, ring, continuum::SlidingFriction::state_law(held, c.friction->speed_coefficient()));
    auto split = continuum::simulate_state_law(system, c.run, wear[k], *held, ring.position, c.vtk_times);
    if (!split.report.ok())
      throw std::runtime_error(split_error(split.report, *law, c.rings.size() > 1 ? "ring " + ring.name + ": " : ""));
    out.mu_static.push_back(split.mu_static);
    Curve curve;
    curve.report = split.report.fast;
    curve.samples = std::move(split.samples);
    std::vector<PistonRingSample> unshifted = curve.samples;  // summarise() expects the ring's own coordinate
    for (auto &sample : unshifted) sample.ring_position -= ring.position;
    curve.summary = continuum::summarise(system, unshifted);
    out.run.rings.push_back(std::move(curve));
    out.passes.push_back(std::move(split.pass));
    const auto &use = wear[k].state_law()->use();
    out.use.lookups += use.lookups;
    out.use.below_pressure += use.below_pressure;
    out.use.above_pressure += use.above_pressure;
    out.use.beyond_depth += use.beyond_depth;
  }
  assemble_pack(out.run, c, *c.friction);
  for (std::size_t k = 0; k < c.rings.size(); ++k)
    out.passes[k].rows = rows_on_grid(out.run.rings[k].samples, out.passes[k].rows, out.run.grid[k]);
  return out;
}

std::string pack_csv_text(const PistonRingCase &c, const PackRun &run, const std::vector<WearPass> &passes) {
  std::string text =
      "t_s,crank_angle_deg,piston_position_m,piston_velocity_m_s,speed_m_s,friction_force_N,land_force_N,"
      "normal_load_N,mu,state_slip,wear_ring_m3,wear_liner_m3,wear_volume_m3";
  for (const auto &ring : c.rings)
    text += fmt::format(",friction_{0}_N,normal_load_{0}_N,state_slip_{0},ring_position_{0}_m,sliding_distance_{0}_m,"
                        "peak_pressure_{0}_Pa",
                        ring.name);
  text += "\n";
  for (std::size_t i = 0; i < run.pack.size(); ++i) {
    const auto &s = run.pack[i];
    double ring_volume = 0.0, liner_volume = 0.0;
    for (const auto &pass : passes) {
      ring_volume += pass.rows[i].ring;
      liner_volume += pass.rows[i].liner;
    }
    text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{},{:.12g},{:.12g},{:.12g}",
                        s.t, s.crank_angle * 180.0 / kPi, s.piston_position, s.piston_velocity, s.speed,
                        s.friction_force, s.land_force, s.normal_load, s.mu,
                        s.state == continuum::ContactState::Slip ? 1 : 0, ring_volume, liner_volume,
                        ring_volume + liner_volume);
    for (std::size_t k = 0; k < run.grid.size(); ++k) {
      const auto &r = run.grid[k][i];
      text += fmt::format(",{:.12g},{:.12g},{},{:.12g},{:.12g},{:.12g}", r.friction_force, r.normal_load,
                          r.state == continuum::ContactState::Slip ? 1 : 0, r.ring_position, r.distance,
                          passes[k].rows[i].peak);
    }
    text += "\n";
  }
  return text;
}

// Subsurface stress below each ring face (doc/subsurface_stress.md): the library's start and end frames
// (continuum::ring_face_start_end_stress), named for the summary and the VTK series.
std::vector<LineStressReport> subsurface_stress(const PistonRingCase &c, const PackRun &run,
                                                const std::vector<continuum::RingLinerWear> &wear,
                                                const std::vector<WearPass> &passes) {
  std::vector<LineStressReport> reports;
  bool tabor_liner = false, tabor_ring = false;
  continuum::verdict_yield_strength(c.liner_material, &tabor_liner);
  continuum::verdict_yield_strength(c.ring_material, &tabor_ring);
  const tribo::Material liner = verdict_material(c.liner_material), ring = verdict_material(c.ring_material);
  for (std::size_t k = 0; k < c.rings.size(); ++k) {
    const auto &samples = run.grid[k];
    const auto &pass = passes[k];
    if (samples.empty() || pass.initial_pressure.empty() || pass.final_pressure.empty()) continue;
    const auto stress = continuum::ring_face_start_end_stress(wear[k], samples, run.rings[k].summary.start_friction_force,
                                                              pass.initial_pressure, pass.final_pressure, liner, ring);
    LineStressReport r;
    r.contact = c.rings.size() > 1 ? "ring " + c.rings[k].name + " face" : "ring face";
    r.label_a = body_label("liner", c.liner_material_name);
    r.label_b = body_label("ring", c.ring_material_name);
    r.field_a = "liner", r.field_b = "ring";
    r.materials_hint = "material.materials";
    r.tabor_a = tabor_liner, r.tabor_b = tabor_ring;
    if (stress.hertz_peak > 0.0)
      r.cross_check = fmt::format("solved unworn pressure: p0 = {:.4g} Pa ({:+.2f} % from Hertz): start from the {}",
                                  stress.solved_peak, 100.0 * (stress.solved_peak / stress.hertz_peak - 1.0),
                                  stress.closed_form ? "closed form" : "influence tier");
    else
      r.cross_check = "the unworn face is not Hertzian (no crown, or the Hertz width reaches the face width): start "
                      "from the influence tier";
    r.frames.push_back({samples.front().t, stress.start});
    r.frames.push_back({samples.back().t, stress.end});
    reports.push_back(std::move(r));
  }
  return reports;
}

// The one-way wear pass of the library, its failures as one line naming the ring.
std::vector<WearPass> wear_pass(const PistonRingCase &c, std::vector<continuum::RingLinerWear> &wear, const PackRun &run) {
  try {
    return continuum::ring_wear_pass(wear, run.grid, c.vtk_times);
  } catch (const continuum::RingWearError &e) {
    const std::string which = c.rings.size() > 1 ? "ring " + c.rings[e.ring].name + ": " : std::string();
    if (e.kind == continuum::RingWearError::Kind::LeftTheLiner)
      throw std::runtime_error(fmt::format("{}wear at t = {:.6g} s: {}", which, e.time, e.what()));
    const auto &w = wear[e.ring];
    throw std::runtime_error(fmt::format("{}{} at t = {:.6g} s: {} (wear.k = {:g}; not a run-in any more)", which,
                                         continuum::to_string(w.status()), e.time, w.message(),
                                         w.archard().coefficient()));
  }
}

struct SweepRow {
  double mu0;
  PackRun run;
};

// Everything a case computes: the rings' wear models, the main run (split on a state law), the wear passes, the sweep.
struct Computed {
  std::vector<continuum::RingLinerWear> wear;
  std::optional<StateLawPack> coupled;
  PackRun main;
  std::vector<WearPass> passes;
  std::vector<SweepRow> sweep;
};

Computed compute(const PistonRingCase &c) {
  const auto *law = c.friction->state_law();
  Computed r;
  r.wear.reserve(c.rings.size());
  for (const auto &ring : c.rings) r.wear.emplace_back(ring.wear_settings, *c.archard);
  for (std::size_t k = 1; k < r.wear.size(); ++k) r.wear[k].share_liner(r.wear.front());
  if (law) {
    for (auto &w : r.wear) w.attach_state_law(law->law, law->policy, law->film);
    r.coupled = run_pack_state_law(c, r.wear);
  }
  r.main = law ? r.coupled->run : run_pack(c, *c.friction);
  if (!law) announce_large_wear_pass(c, r.main.pack.size() * c.rings.size());
  r.passes = law ? r.coupled->passes : wear_pass(c, r.wear, r.main);
  for (double mu0 : c.sweep_mu0) r.sweep.push_back({mu0, run_pack(c, piston_ring_friction_with_mu0(c, mu0))});
  return r;
}

std::string summary_csv_text(const Computed &r) {
  double wear_volume = 0.0;  // ring faces and liner at the end of the run
  for (const auto &pass : r.passes) wear_volume += pass.rows.back().ring + pass.rows.back().liner;
  const auto &m = r.main.summary;
  return std::string(kRunSummaryHeader) + "\n" +
         run_summary_row({m.peak_friction_force, m.peak_time, m.breakaway_time, m.steady_time, m.steady_mu,
                          wear_volume}) +
         "\n";
}

std::string rings_csv_text(const PistonRingCase &c) {
  std::string text =
      "ring,groove_position_m,groove_diameter_m,land_width_m,land_stiffness_land_N_m,land_stiffness_ring_N_m,"
      "land_stiffness_N_m,land_damping_N_s_m,mass_kg,elastic_pressure_Pa,normal_load_N,crown_height_m\n";
  for (const auto &ring : c.rings) {
    const auto &rp = ring.parameters;
    text += fmt::format("{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n",
                        ring.name, ring.position, ring.groove_diameter, ring.land_width,
                        ring.land ? ring.land->land : 0.0, ring.land ? ring.land->ring : 0.0, rp.land_stiffness,
                        rp.land_damping, rp.ring_mass, rp.elastic_pressure, rp.elastic_pressure * rp.contact_area(),
                        ring.wear_settings.crown_height);
  }
  return text;
}

std::string liner_csv_text(const PistonRingCase &c, const continuum::RingLinerWear &wear) {
  const double tdc = c.parameters.crank.top_dead_centre();
  std::string text = "x_m,distance_from_tdc_m,wear_depth_m\n";
  for (int j = 0; j < c.wear_settings.liner_cells; ++j) {
    const double x = wear.liner_cell_centre(j);
    text += fmt::format("{:.12g},{:.12g},{:.12g}\n", x, tdc - x, wear.liner_wear()[j]);
  }
  return text;
}

std::string face_csv_text(const PistonRingCase &c, const continuum::RingLinerWear &w, const PistonRingSample &last) {
  const auto contact = w.pressure(last.ring_position, last.normal_load);
  std::string text = "z_m,crown_m,wear_depth_m,final_pressure_Pa\n";
  for (int i = 0; i < w.settings().ring_cells; ++i) {
    const double z = w.ring_cell_centre(i), u = 2.0 * z / c.parameters.ring_width;
    text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g}\n", z, w.settings().crown_height * u * u, w.ring_wear()[i],
                        contact.pressure[i]);
  }
  return text;
}

std::string sweep_csv_text(const std::vector<SweepRow> &sweep) {
  std::string text = "mu0,t_s,friction_force_N,land_force_N,speed_m_s,state_slip\n";
  for (const auto &row : sweep)
    for (const auto &s : row.run.pack)
      text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{}\n", row.mu0, s.t, s.friction_force,
                          s.land_force, s.speed, s.state == continuum::ContactState::Slip ? 1 : 0);
  return text;
}

// The CSV files, staged; returns their names in order.
std::vector<std::string> write_csv(StagedOutput &out, const PistonRingCase &c, const Computed &r) {
  const bool pack = c.rings.size() > 1, law = c.friction->state_law() != nullptr;
  const bool film = law && c.friction->state_law()->film;
  std::vector<std::string> written;
  const auto write = [&](const std::string &name, const std::string &text) {
    out.write(name, text);
    written.push_back(name);
  };
  if (pack) {
    write("piston_ring.csv", pack_csv_text(c, r.main, r.passes));
    for (std::size_t k = 0; k < c.rings.size(); ++k)
      write("piston_ring_" + c.rings[k].name + ".csv", csv_text(r.main.grid[k], r.passes[k].rows, law, film));
  } else {
    write("piston_ring.csv", csv_text(r.main.grid.front(), r.passes.front().rows, law, film));
  }
  write("piston_ring_summary.csv", summary_csv_text(r));
  write("piston_ring_rings.csv", rings_csv_text(c));
  write("piston_ring_liner.csv", liner_csv_text(c, r.wear.front()));
  for (std::size_t k = 0; k < c.rings.size(); ++k)
    write(k == 0 ? "piston_ring_face.csv" : "piston_ring_face_" + c.rings[k].name + ".csv",
          face_csv_text(c, r.wear[k], r.main.grid[k].back()));
  if (!r.sweep.empty()) write("piston_ring_mu0.csv", sweep_csv_text(r.sweep));
  return written;
}

void plot_curves(const PistonRingCase &c, const Computed &r, StagedOutput &out, const PlotRunner &plot,
                 std::vector<std::string> &written) {
  // The six panels show ring A (its own CSV in a pack) with the shared liner.
  const bool pack = c.rings.size() > 1;
  const std::string curve_csv = pack ? "piston_ring_A.csv" : "piston_ring.csv";
  plot("plot_piston_ring.py", {"curve", out.file(curve_csv).string(), out.file("piston_ring_liner.csv").string(),
                               out.file("piston_ring_face.csv").string(), out.file("piston_ring.png").string(),
                               "--title", c.title + (pack ? " - ring A" : "")});
  written.push_back("piston_ring.png");
  if (r.sweep.empty()) return;
  plot("plot_piston_ring.py", {"sweep", out.file("piston_ring_mu0.csv").string(),
                               out.file("piston_ring_mu0.png").string(), "--title",
                               c.title + (pack ? " - ring pack (sum)" : "")});
  written.push_back("piston_ring_mu0.png");
}

struct VtkWritten {
  std::vector<std::string> frames, stress;  // staged names; stress: the destination of each series' index
};

VtkWritten write_vtk(const PistonRingCase &c, const Computed &r, const std::vector<LineStressReport> &stress,
                     StagedOutput &out) {
  VtkWritten v;
#ifdef RUNIN_HAVE_VTK
  v.frames = write_frames(r.wear, r.passes, c.rings, c.circumferential_points, out.staging());
  for (std::size_t k = 0; k < stress.size(); ++k) {
    const auto more = write_line_stress(stress[k], out.staging() / "vtk", k == 0 ? "subsurface" : "subsurface_" + c.rings[k].name);
    v.stress.push_back(out.destination_of(more.back()).string());
  }
#else
  (void)c, (void)r, (void)stress, (void)out;
#endif
  return v;
}

void print_kinematics(const PistonRingCase &c, const Computed &r) {
  const auto &p = c.parameters;
  const double stroke = 2.0 * p.crank.crank_radius;
  if (p.motion == continuum::PistonMotion::Ramp)
    fmt::print("  kinematics        ramp: x from eq. 6.1 at {:g} deg before TDC to TDC ({:.6g} mm) in {:g} s; "
               "r = {:g} mm, l = {:g} mm\n",
               p.start_angle * 180.0 / kPi, 1e3 * (p.crank.top_dead_centre() - p.crank.position(p.start_angle)),
               p.ramp_time, 1e3 * p.crank.crank_radius, 1e3 * p.crank.link_length);
  else
    fmt::print("  kinematics        crank: eq. 6.1 at {:.6g} rpm from {:g} deg before TDC; r = {:g} mm, l = {:g} mm, "
               "stroke {:g} mm, {:.4g} revolutions\n",
               p.crank_speed * 60.0 / (2.0 * kPi), p.start_angle * 180.0 / kPi, 1e3 * p.crank.crank_radius,
               1e3 * p.crank.link_length, 1e3 * stroke,
               r.main.pack.back().t * p.crank_speed / (2.0 * kPi));
  fmt::print("  ring face         {}\n",
             c.wear_settings.contact == continuum::FaceContact::HalfPlane
                 ? fmt::format("elastic half-plane line contact (BEM, E* = {:.4g} GPa)", 1e-9 * c.wear_settings.contact_modulus)
                 : fmt::format("Winkler layer k_c = {:.4g} Pa/m", c.wear_settings.foundation_modulus));
  fmt::print("  ring model        {}\n", c.rings.size() > 1 ? fmt::format("ring pack of {} rings; friction = their sum", c.rings.size())
                                                        : std::string("one ring"));
  for (const auto &ring : c.rings) {
    const auto &rp = ring.parameters;
    const double natural = std::sqrt(rp.land_stiffness / rp.ring_mass) / (2.0 * kPi);
    const std::string land =
        ring.land ? fmt::format("land k = {:.4g} N/m from geometry (land plate {:.4g}, ring section {:.4g}; groove "
                                "{:g} mm, land {:g} mm)",
                                rp.land_stiffness, ring.land->land, ring.land->ring, 1e3 * ring.groove_diameter,
                                1e3 * ring.land_width)
                  : fmt::format("land k = {:.4g} N/m (set by hand)", rp.land_stiffness);
    fmt::print("  ring {}            W = {:.6g} N from {:.4g} MPa ring tension{}; m = {:.4g} kg, {}, zeta = {:g} "
               "({:.4g} Hz); at {:g} mm; crown {:g} um\n",
               ring.name, rp.elastic_pressure * rp.contact_area(),
               1e-6 * rp.elastic_pressure, p.gas.empty() ? "" : " + gas table", rp.ring_mass, land,
               c.land_damping_ratio, natural, 1e3 * ring.position, 1e6 * ring.wear_settings.crown_height);
  }
}

void print_friction_and_wear(const PistonRingCase &c, const Computed &r) {
  const auto &p = c.parameters;
  const auto &s = r.main.summary;
  const bool pack = c.rings.size() > 1;
  fmt::print("  break-away        {}\n", or_none(s.breakaway_time));
  fmt::print("  peak friction     {:.6g} N at t = {:.6g} s (liner{}); peak land force {:.6g} N\n", s.peak_friction_force,
             s.peak_time, pack ? ", sum of the rings" : "", s.peak_land_force);
  fmt::print("  steady state      {} ({})\n", or_none(s.steady_time), s.steady_criterion);
  fmt::print("  start friction    {:.6g} N (largest |F| up to the first slip sample)\n", s.start_friction_force);
  fmt::print("  steady mu         {:.6g}, friction force {:.6g} N\n", s.steady_mu, s.steady_friction_force);
  if (p.motion == continuum::PistonMotion::Crank)
    fmt::print("  pressure run-in   {} (cycle-max peak contact pressure within 1 % of the last cycle's from then on)\n",
               or_none(continuum::pressure_settling_time(p, r.main.grid.front(), r.passes.front().rows)));
  fmt::print("  sliding           {:.6g} m (ring A) in {} break-away and {} re-stick events\n",
             r.main.grid.front().back().distance, r.main.breakaways, r.main.resticks);
  double ring_volume = 0.0, liner_volume = 0.0, archard = 0.0;
  for (const auto &w : r.wear) {
    ring_volume += w.ring_volume();
    liner_volume += w.liner_volume();
    archard += w.archard_volume();
  }
  if (c.friction->state_law())
    fmt::print("  wear volume       {:.6g} m^3 (ring{} {:.6g} by the law's wear_rate, liner {:.6g} by its "
               "counterface_wear_rate)\n",
               ring_volume + liner_volume, pack ? "s" : "", ring_volume, liner_volume);
  else
    fmt::print("  wear volume       {:.6g} m^3 (ring{} {:.6g}, liner {:.6g}); Archard k W s / H = {:.6g} m^3\n",
               ring_volume + liner_volume, pack ? "s" : "", ring_volume, liner_volume, archard);
  const auto &liner_wear = r.wear.front().liner_wear();
  const auto max_liner = std::max_element(liner_wear.begin(), liner_wear.end());
  fmt::print("  liner wear        max {:.6g} um at {:.6g} mm from TDC\n", 1e6 * *max_liner,
             1e3 * (p.crank.top_dead_centre() -
                    r.wear.front().liner_cell_centre(static_cast<int>(max_liner - liner_wear.begin()))));
  for (std::size_t k = 0; k < c.rings.size(); ++k)
    fmt::print("  ring {} pressure   peak {:.6g} MPa at start -> {:.6g} MPa at end, contact width {:.4g} -> {:.4g} mm\n",
               c.rings[k].name, 1e-6 * r.passes[k].initial_peak, 1e-6 * r.passes[k].rows.back().peak,
               1e3 * r.passes[k].rows.front().width, 1e3 * r.passes[k].rows.back().width);
}

void print_state_law(const PistonRingCase &c, const Computed &r, std::vector<std::string> &warnings) {
  const auto *law = c.friction->state_law();
  fmt::print("  state law         {} (p {:.4g} .. {:.4g} Pa, h 0 .. {:.4g} m); the ring face is the rough body, the "
             "liner the counterface\n",
             law->path, law->law->pressure().front(), law->law->pressure().back(), law->law->worn_depth().back());
  for (std::size_t k = 0; k < c.rings.size(); ++k) {
    const auto &rows = r.passes[k].rows;
    fmt::print("  ring {} mu_eff     {:.6g} -> {:.6g} (pressure-weighted over the face cells); static {:.6g} ({}); "
               "h mean {:.4g} m, max {:.4g} m\n",
               c.rings[k].name, rows.front().mu_eff, rows.back().mu_eff, r.coupled->mu_static[k],
               law->mu_static ? "friction.mu_static" : "the law's peak at the initial pressures", rows.back().h_mean,
               rows.back().h_max);
  }
  if (const auto &film = law->film)
    for (std::size_t k = 0; k < c.rings.size(); ++k)
      fmt::print("  ring {} film       coverage {:.4g} -> {:.4g} (load-weighted over the face), f {:.4g} covered / "
                 "{:.4g} bare, s_r {:.4g} m, k_g {:.4g} 1/s\n",
                 c.rings[k].name, r.passes[k].rows.front().film_coverage, r.passes[k].rows.back().film_coverage,
                 film->f_film, film->f_base, film->removal_distance, film->growth_rate);
  fmt::print("  law lookups       {}\n", continuum::describe(r.coupled->use, *law->law));
  if (auto w = continuum::out_of_range_warning(r.coupled->use, *law->law, law->policy); !w.empty())
    warnings.push_back(std::move(w));
  if (const auto cell = coupling::cell_scale(*law->law)) {
    // narrowest: the unworn crowned face's contact; a face cell spans the bore's circumference
    double width = r.passes.front().rows.front().width, node = 0.0;
    for (std::size_t k = 0; k < c.rings.size(); ++k) {
      width = std::min(width, r.passes[k].rows.front().width);
      const double area = r.wear[k].ring_cell_width() * std::acos(-1.0) * c.rings[k].wear_settings.bore;
      node = k == 0 ? area : std::min(node, area);
    }
    const coupling::ScaleSeparation sep{*cell, width, node};
    fmt::print("  scale separation  {}\n", coupling::describe(sep));
    if (auto w = coupling::scale_separation_warning(sep); !w.empty()) warnings.push_back(std::move(w));
  }
}

void print_sweep(const PistonRingCase &c, const std::vector<SweepRow> &sweep) {
  if (sweep.empty()) return;
  fmt::print("  mu0 sweep{}    {:>6} {:>12} {:>12} {:>12} {:>10}\n", c.rings.size() > 1 ? " (sum)" : "      ", "mu0",
             "peak F (N)", "break-away", "steady", "steady mu");
  for (const auto &row : sweep)
    fmt::print("                    {:>6g} {:>12.6g} {:>12} {:>12} {:>10.4g}\n", row.mu0,
               row.run.summary.peak_friction_force, or_none(row.run.summary.breakaway_time),
               or_none(row.run.summary.steady_time), row.run.summary.steady_mu);
}

// One-screen summary.
void print_summary(const Options &o, const PistonRingCase &c, const Computed &r,
                   const std::vector<LineStressReport> &stress) {
  fmt::print("runin piston-ring: {}\n  {}\n", o.case_path, c.title);
  fmt::print("  friction          {}\n", c.friction->description());
  print_kinematics(c, r);
  print_friction_and_wear(c, r);
  std::vector<std::string> warnings;
  if (c.friction->state_law()) print_state_law(c, r, warnings);
  for (const auto &report : stress) print_line_stress(report, warnings);
  for (const auto &w : warnings) fmt::print("  {}\n", w);
  long updates = 0;
  for (const auto &w : r.wear) updates += w.updates();
  fmt::print("  wear updates      {} (step {:.4g} m = {} x stable_slip_step)\n", updates, r.wear.front().step(),
             c.wear_settings.fixed_step > 0.0 ? std::string("fixed, not") : fmt::format("{:g}", c.wear_settings.step_safety));
  fmt::print("  CVODE             {} steps\n", r.main.cvode_steps);
  print_sweep(c, r.sweep);
}

void print_written(const StagedOutput &out, const std::vector<std::string> &written, const VtkWritten &vtk) {
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  if (!vtk.frames.empty())
    fmt::print(", {} VTK files ({})", vtk.frames.size(), out.destination_of(vtk.frames.back()).string());
  for (const auto &f : vtk.stress) fmt::print(", {} (subsurface stress, 2 frames)", f);
  fmt::print("\n");
}

int run(const Options &o, const PlotRunner &plot) {
  if (is_lubricated_ring_case(o.case_path))   // [lubrication]: the mixed-lubrication run-in
    return run_lubricated_piston_ring(o.case_path, o.output_dir, o.law_path, o.no_plot, plot);
  const PistonRingCase c = read_piston_ring_case(o.case_path, o.law_path);
  const Computed r = compute(c);

  // Everything is computed; the output set is staged and moved in only when complete.
  StagedOutput out(o.output_dir, {"piston_ring.csv", "piston_ring_summary.csv", "piston_ring_?.csv", "piston_ring_rings.csv",
                                  "piston_ring_liner.csv", "piston_ring_face.csv", "piston_ring_face_?.csv",
                                  "piston_ring_mu0.csv", "piston_ring.png", "piston_ring_mu0.png", "vtk/liner.pvd",
                                  "vtk/liner_*.vts", "vtk/ring_face.pvd", "vtk/ring_face_*.vts", "vtk/ring_face_?.pvd",
                                  "vtk/subsurface.pvd", "vtk/subsurface_*.vts", "vtk/subsurface_?.pvd"});
  const std::vector<LineStressReport> stress = subsurface_stress(c, r.main, r.wear, r.passes);
  std::vector<std::string> written = write_csv(out, c, r);
  if (!o.no_plot) plot_curves(c, r, out, plot, written);
  const VtkWritten vtk = write_vtk(c, r, stress, out);
  out.commit();
  print_summary(o, c, r, stress);
  print_written(out, written, vtk);
  return 0;
}

}  // namespace

Subcommand add_piston_ring_command(CLI::App &app, PlotRunner plot) {
  auto options = std::make_shared<Options>();
  auto *cmd = app.add_subcommand("piston-ring", "Piston ring in a cylinder: run-in friction and wear (thesis ch. 6)");
  cmd->add_option("case", options->case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  cmd->add_option("--law", options->law_path,
                  "law file: from fit-law (friction.model = \"law_file\"), or from homogenise (\"state_law\", overrides friction.law)");
  cmd->add_option("--output-dir", options->output_dir,
                  "directory for piston_ring*.csv, piston_ring*.png and vtk/ (liner and ring-face frames)")
      ->required()
      ->check(output_directory());
  cmd->add_flag("--no-plot", options->no_plot, "write the CSV and VTK files only");
  return {cmd, [options, plot = std::move(plot)] { return run(*options, plot); }};
}

}  // namespace runin::cli
