// `runin piston-ring CASE` in the lubricated mode ([lubrication]): reads the case, runs the mixed-lubrication
// run-in and the Stribeck sweep of src/continuum/mixed_piston_ring.h, writes the outputs atomically.
#include "cli/cmd_piston_ring_lubricated.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <fmt/core.h>

#include "cli/case_file.h"
#include "cli/lubricated_ring_case.h"
#include "cli/staged_file.h"
#include "continuum/node_state_law.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string cycle_csv(const std::vector<continuum::CycleSample> &rows) {
  std::string text =
      "cycle,cycles_jumped,time_s,sliding_distance_m,friction_force_N,mu,power_loss_W,fmep_Pa,min_film_m,min_lambda,"
      "asperity_share,R_m,sigma_m,max_worn_depth_m,mean_worn_depth_m,worn_volume_m3,cycle_wear_volume_m3,"
      "peak_film_pressure_Pa,peak_asperity_pressure_Pa\n";
  for (const auto &s : rows)
    text += fmt::format("{},{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},"
                        "{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n",
                        s.cycle, s.jump, s.time, s.sliding_distance, s.mean_friction_force, s.mu, s.power_loss, s.fmep,
                        s.min_h, s.min_lambda, s.asperity_share, s.rq, s.sigma, s.max_worn_depth, s.mean_worn_depth,
                        s.worn_volume, s.cycle_wear_volume, s.peak_film_pressure, s.peak_asperity_pressure);
  return text;
}

std::string crank_csv(const continuum::RunInReport &r, long first_cycle, long last_cycle) {
  std::string text =
      "which,cycle,crank_angle_deg,t_s,speed_m_s,load_N,h_min_m,friction_force_N,mu,asperity_share,lambda,"
      "peak_film_pressure_Pa,peak_asperity_pressure_Pa\n";
  auto add = [&](const char *which, long cycle, const continuum::CycleResult &c) {
    for (const auto &s : c.curve)
      text += fmt::format("{},{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n",
                          which, cycle, s.crank_angle * 180.0 / kPi, s.t, s.speed, s.load, s.h_min, s.friction_force,
                          s.mu, s.asperity_share, s.lambda, s.peak_film_pressure, s.peak_asperity_pressure);
  };
  add("first", first_cycle, r.first);
  add("last", last_cycle, r.last);
  return text;
}

std::string stribeck_csv(const std::vector<continuum::RingStribeckPoint> &points) {
  std::string text = "speed_m_s,duty_parameter,h_min_m,lambda,mu,asperity_share,viscous_friction_N_m,"
                     "boundary_friction_N_m\n";
  for (const auto &s : points)
    text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", s.speed, s.duty, s.h_min,
                        s.lambda, s.mu, s.asperity_share, s.viscous_friction, s.boundary_friction);
  return text;
}

#ifdef RUNIN_HAVE_VTK
// The face as a band around the bore at the ring's axial position: film thickness, pressures, fill, worn depth.
std::vector<std::string> write_face_series(const continuum::MixedPistonRing &ring,
                                           const std::vector<continuum::FaceFrame> &frames, double t0,
                                           const std::filesystem::path &dir, const std::string &stem) {
  constexpr int around = 48;
  const auto &p = ring.parameters();
  const double radius = 0.5 * p.bore;
  std::vector<coupling::SurfaceFrame> out;
  for (const auto &f : frames) {
    coupling::SurfaceFrame sf;
    sf.time = t0 + f.t;
    sf.nu = ring.nodes();
    sf.nv = around;
    const double z0 = p.crank.position(f.crank_angle) - 0.5 * p.face_width;
    std::vector<double> gap, pressure, fill, asperity, worn;
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * kPi * j / around;
      for (int i = 0; i < sf.nu; ++i) {
        sf.points.push_back({radius * std::cos(phi), radius * std::sin(phi), z0 + ring.x(i)});
        gap.push_back(f.gap[i]);
        pressure.push_back(f.pressure[i]);
        fill.push_back(f.fill[i]);
        asperity.push_back(f.asperity_pressure[i]);
        worn.push_back(f.worn_depth[i]);
      }
    }
    sf.fields = {{"film_thickness", gap}, {"pressure", pressure}, {"fill_fraction", fill},
                 {"asperity_pressure", asperity}, {"worn_depth", worn}};
    out.push_back(std::move(sf));
  }
  return coupling::write_surface_series(out, (dir / "vtk").string(), stem);
}
#endif

}  // namespace

namespace {

// Stribeck curve of the unworn ring (steady sliding at fixed load); empty without [stribeck].
std::vector<continuum::RingStribeckPoint> ring_stribeck(const LubricatedRingCase &c, const continuum::MixedPistonRing &ring) {
  std::vector<continuum::RingStribeckPoint> stribeck;
  if (!c.stribeck) return stribeck;
  coupling::RangeUse stribeck_use;
  stribeck = continuum::stribeck_sweep(ring, c.stribeck->load, c.stribeck->speed_min, c.stribeck->speed_max,
                                       c.stribeck->points, &stribeck_use);
  for (const auto &s : stribeck) {
    // the balance searches h from 1e-3 sigma to 0.1 x ring.width: a load it cannot bracket is the inputs' (exit 2)
    if (s.status == continuum::RingFilmStatus::LoadNotBracketed)
      throw InputError(fmt::format("{}: key 'stribeck.load': load balance not bracketed at U = {:.6g} m/s: W' = {:g} N/m "
                                   "is carried by no film between 1e-3 sigma and 0.1 x ring.width; check stribeck.load "
                                   "(default ring.elastic_pressure x ring.width), lubrication.viscosity, "
                                   "material.youngs_modulus and the stribeck speeds",
                                   c.path, s.speed, c.stribeck->load));
    if (s.status != continuum::RingFilmStatus::Ok)
      throw std::runtime_error(fmt::format("stribeck: {} at U = {:.6g} m/s", continuum::to_string(s.status), s.speed));
  }
  return stribeck;
}

// The run-in with progress lines (every 10 % of the cycles or 5 s).
continuum::RunInReport ring_run_in(const LubricatedRingCase &c, continuum::MixedPistonRing &ring,
                                       std::vector<continuum::CycleSample> &rows) {
  auto last_print = std::chrono::steady_clock::now();
  long next_tenth = 1;
  auto report = continuum::run_in(ring, c.run, [&](const continuum::CycleSample &s) {
    rows.push_back(s);
    const long done = s.cycle + s.jump;
    const auto now = std::chrono::steady_clock::now();
    if (done * 10 >= next_tenth * c.run.cycles || std::chrono::duration<double>(now - last_print).count() > 5.0) {
      while (done * 10 >= next_tenth * c.run.cycles) ++next_tenth;
      fmt::print("  progress          cycle {} of {} ({} computed), mu {:.4g}, asperity share {:.3g}\n", done,
                 c.run.cycles, rows.size(), s.mu, s.asperity_share);
      std::fflush(stdout);
      last_print = now;
    }
  });
  if (!report.ok()) throw std::runtime_error("lubricated run-in: " + report.message);
  return report;
}

// The CSV files, the plots and the VTK face series, staged; returns the names written and the VTK files.
std::pair<std::vector<std::string>, std::vector<std::string>> write_ring_outputs(
    StagedOutput &out, const LubricatedRingCase &c, const continuum::MixedPistonRing &ring,
    const continuum::RunInReport &report, const std::vector<continuum::CycleSample> &rows,
    const std::vector<continuum::RingStribeckPoint> &stribeck, bool no_plot, const PlotRunner &plot) {
  std::vector<std::string> written;
  out.write("lubricated.csv", cycle_csv(rows));
  written.push_back("lubricated.csv");
  out.write("lubricated_cycle.csv", crank_csv(report, rows.front().cycle, rows.back().cycle));
  written.push_back("lubricated_cycle.csv");
  if (c.stribeck) {
    out.write("stribeck.csv", stribeck_csv(stribeck));
    written.push_back("stribeck.csv");
  }
  if (!no_plot) {
    plot("plot_lubricated_ring.py", {"runin", out.file("lubricated.csv").string(),
                                     out.file("lubricated_cycle.csv").string(), out.file("lubricated.png").string(),
                                     "--title", c.title});
    written.push_back("lubricated.png");
    if (c.stribeck) {
      plot("plot_lubricated_ring.py",
           {"stribeck", out.file("stribeck.csv").string(), out.file("stribeck.png").string(), "--title", c.title});
      written.push_back("stribeck.png");
    }
  }
  std::vector<std::string> vtk_files;
#ifdef RUNIN_HAVE_VTK
  // the first cycle's frames hold the unworn face, the last cycle's the face at its start
  auto first = write_face_series(ring, report.first.frames, rows.front().time, out.staging(), "lubricated_first");
  auto last = write_face_series(ring, report.last.frames, rows.back().time, out.staging(), "lubricated_last");
  vtk_files.insert(vtk_files.end(), first.begin(), first.end());
  vtk_files.insert(vtk_files.end(), last.begin(), last.end());
#else
  (void)ring;
#endif
  return {written, vtk_files};
}

void print_ring_set_up(const LubricatedRingCase &c, const continuum::CycleSample &first) {
  const auto &p = c.parameters;
  const double circ = p.circumference();
  fmt::print("  ring              D = {:g} mm, face width {:g} mm, crown {:g} um, {:g} MPa ring tension "
             "(W = {:.4g} N){}; {} face nodes\n",
             1e3 * p.bore, 1e3 * p.face_width, 1e6 * p.crown_height, 1e-6 * p.elastic_pressure,
             p.elastic_pressure * p.face_width * circ, p.gas.empty() ? "" : " + gas table", p.nodes);
  fmt::print("  kinematics        {:g} rpm, r = {:g} mm, l = {:g} mm; cycle {:g} deg in {} crank steps ({:.4g} ms)\n",
             p.crank_speed * 60.0 / (2.0 * kPi), 1e3 * p.crank.crank_radius, 1e3 * p.crank.link_length,
             p.cycle_angle() * 180.0 / kPi, p.steps_per_cycle, 1e3 * p.period());
  fmt::print("  oil               viscosity {:g} Pa s, inlet {}\n", p.viscosity,
             p.supply == continuum::OilSupply::Flooded ? std::string("flooded")
                                                        : fmt::format("starved (oil film {:g} um)", 1e6 * p.oil_film));
  fmt::print("  roughness         GT: eta = {:.4g} /m^2, beta = {:g} um from the law's surface; E* = {:.4g} GPa; sigma = "
             "{} (initial {:.4g} nm)\n",
             p.summits.density, 1e6 * p.summits.radius, 1e-9 * p.effective_modulus,
             p.liner == continuum::LinerRoughness::Law ? "sqrt(2) rq(p, h) (liner runs in like the ring)"
                                                       : fmt::format("sqrt(rq(p, h)^2 + {:g} nm^2)", 1e9 * p.liner_sigma),
             1e9 * first.sigma);
  if (p.worn_surface == continuum::WornSurface::TruncatedSummits)
    fmt::print("  worn summits      rq taken at h = 0 and the summits cut at the top the face's worn volume sets\n");
}

void print_ring_run_in(const LubricatedRingCase &c, const continuum::MixedPistonRing &ring,
                       const continuum::RunInReport &report, const std::vector<continuum::CycleSample> &rows) {
  const auto &first = rows.front(), &last = rows.back();
  const auto &law = *c.law;
  fmt::print("  regime            initial: min lambda over the cycle {:.3g}, asperity share {:.3g}, peak film "
             "pressure {:.4g} MPa, peak asperity pressure {:.4g} MPa\n",
             first.min_lambda, first.asperity_share, 1e-6 * first.peak_film_pressure,
             1e-6 * first.peak_asperity_pressure);
  fmt::print("  run-in            {} cycles ({} computed, cycle jumping), {:.4g} m sliding\n", report.cycles,
             report.computed_cycles, last.sliding_distance + (last.sliding_distance > 0.0 && last.cycle > 0
                                                                  ? last.sliding_distance / last.cycle
                                                                  : 0.0));
  fmt::print("  friction          mu {:.4g} -> {:.4g}, friction force {:.4g} -> {:.4g} N, power loss {:.4g} -> {:.4g} W, "
             "FMEP {:.4g} -> {:.4g} kPa\n",
             first.mu, last.mu, first.mean_friction_force, last.mean_friction_force, first.power_loss, last.power_loss,
             1e-3 * first.fmep, 1e-3 * last.fmep);
  fmt::print("  asperities        share {:.4g} -> {:.4g}, min lambda {:.4g} -> {:.4g}, R {:.4g} -> {:.4g} nm\n",
             first.asperity_share, last.asperity_share, first.min_lambda, last.min_lambda, 1e9 * first.rq,
             1e9 * last.rq);
  const auto &h = ring.worn_depth();
  double h_max = 0.0;
  for (double v : h) h_max = std::max(h_max, v);
  fmt::print("  wear              ring face max {:.4g} nm (the law's depth table ends at {:.4g} nm{}), volume {:.4g} m^3 "
             "(booked {:.4g})\n",
             1e9 * h_max, 1e9 * law.worn_depth().back(), h_max > law.worn_depth().back() ? ": held beyond" : "",
             ring.worn_volume(), report.booked_wear_volume);
  fmt::print("  law lookups       {} (friction.out_of_range = \"{}\")\n", continuum::describe(report.use, law),
             coupling::to_string(c.policy));
}

void print_ring_stribeck(const LubricatedRingCase &c, const std::vector<continuum::RingStribeckPoint> &stribeck) {
  if (!c.stribeck) return;
  std::size_t best = 0;
  for (std::size_t k = 1; k < stribeck.size(); ++k)
    if (stribeck[k].mu < stribeck[best].mu) best = k;
  fmt::print("  stribeck          {} speeds {:g} .. {:g} m/s at W' = {:g} N/m: mu {:.4g} (share {:.3g}) -> min {:.4g} "
             "at lambda {:.3g} (U {:.4g} m/s) -> {:.4g} (lambda {:.3g})\n",
             stribeck.size(), c.stribeck->speed_min, c.stribeck->speed_max, c.stribeck->load, stribeck.front().mu,
             stribeck.front().asperity_share, stribeck[best].mu, stribeck[best].lambda, stribeck[best].speed,
             stribeck.back().mu, stribeck.back().lambda);
}

}  // namespace

int run_lubricated_piston_ring(const std::string &case_path, const std::string &output_dir,
                               const std::optional<std::string> &law_path, bool no_plot, const PlotRunner &plot) {
  const LubricatedRingCase c = read_lubricated_ring_case(case_path, law_path);
  continuum::MixedPistonRing ring(c.parameters, c.law, c.policy);
  const auto t_start = std::chrono::steady_clock::now();
  const auto stribeck = ring_stribeck(c, ring);
  std::vector<continuum::CycleSample> rows;
  fmt::print("runin piston-ring (lubricated): {}\n  {}\n", case_path, c.title);
  std::fflush(stdout);
  const auto report = ring_run_in(c, ring, rows);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();

  StagedOutput out(output_dir, {"lubricated.csv", "lubricated_cycle.csv", "stribeck.csv", "lubricated.png",
                                "stribeck.png", "vtk/lubricated_first.pvd", "vtk/lubricated_first_*.vts",
                                "vtk/lubricated_last.pvd", "vtk/lubricated_last_*.vts"});
  const auto [written, vtk_files] = write_ring_outputs(out, c, ring, report, rows, stribeck, no_plot, plot);
  out.commit();

  print_ring_set_up(c, rows.front());
  print_ring_run_in(c, ring, report, rows);
  print_ring_stribeck(c, stribeck);
  fmt::print("  run time          {:.3g} s\n", seconds);
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i) fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  if (!vtk_files.empty()) fmt::print(", {} VTK files ({})", vtk_files.size(), out.destination_of(vtk_files.back()).string());
  fmt::print("\n");
  return 0;
}

}  // namespace runin::cli
