#include "cli/lubricated_bearing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/case_file.h"
#include "cli/case_reader.h"
#include "cli/staged_file.h"
#include "continuum/mixed_journal_bearing.h"
#include "continuum/node_state_law.h"   // describe(RangeUse)
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

const Schema kSchema = {
    {"", {"title", "bearing", "lubrication", "friction", "wear", "run", "stribeck"}},
    {"bearing", {"shaft_radius", "clearance", "length", "youngs_modulus", "poisson_ratio", "load"}},
    {"lubrication", {"viscosity", "supply_pressure", "groove_angle", "speed", "speed_time", "speed_value", "grid",
                     "flow_factors", "gamma", "counterface"}},
    {"friction", {"model", "law", "out_of_range"}},
    {"wear", {"step_fraction", "worn_surface"}},
    {"run", {"t_end", "output_interval", "frame_times"}},
    {"stribeck", {"speed_min", "speed_max", "points"}},
};

struct LubricatedCase {
  std::string path, title, law_path;
  continuum::MixedJournalBearingParameters parameters;
  continuum::MixedRunSettings run;
  bool stribeck = false;
  double speed_min = 0.0, speed_max = 0.0;
  int points = 50;
};

// [lubrication]: the oil, its supply, the sliding speed (constant or a table) and the film grid.
void read_lubrication(const CaseReader &reader, continuum::MixedJournalBearingParameters &p) {
  p.viscosity = reader.positive("lubrication.viscosity");
  p.supply_pressure = reader.non_negative("lubrication.supply_pressure", 0.0);
  p.groove_angle = reader.number("lubrication.groove_angle", M_PI);
  if (reader.has("lubrication.speed_time") || reader.has("lubrication.speed_value")) {
    if (reader.has("lubrication.speed"))
      reader.fail("lubrication.speed", "give either speed or the table speed_time / speed_value");
    p.speed_time = reader.numbers("lubrication.speed_time");
    p.speed_value = reader.numbers("lubrication.speed_value");
    if (p.speed_time.size() != p.speed_value.size() || p.speed_time.size() < 2)
      reader.fail("lubrication.speed_value", "needs one speed per time in lubrication.speed_time (>= 2 points)");
    for (std::size_t k = 0; k < p.speed_time.size(); ++k) {
      if (k > 0 && !(p.speed_time[k] > p.speed_time[k - 1]))
        reader.fail("lubrication.speed_time", "must increase strictly");
      if (!(p.speed_value[k] > 0.0))
        reader.fail("lubrication.speed_value", "element " + std::to_string(k) + ": must be positive, got " +
                                                   CaseReader::format(p.speed_value[k]));
    }
  } else {
    p.speed = reader.positive("lubrication.speed");
  }
  if (reader.has("lubrication.grid")) {
    const auto grid = reader.numbers("lubrication.grid");
    if (grid.size() != 2 || grid[0] != std::floor(grid[0]) || grid[1] != std::floor(grid[1]) || grid[0] < 8 ||
        grid[1] < 3 || grid[0] > 2000 || grid[1] > 400)
      reader.fail("lubrication.grid", "must be [n_theta, n_axial], integers, 8 <= n_theta <= 2000, 3 <= n_axial <= 400");
    p.n_theta = static_cast<int>(grid[0]);
    p.n_axial = static_cast<int>(grid[1]);
  }
}

// [friction]: the state law (the only model) and its asperity statistics.
void read_law(const CaseReader &reader, const LubricatedOptions &o, LubricatedCase &c) {
  auto &p = c.parameters;
  const std::string model = reader.choice("friction.model", {"state_law"});
  (void)model;
  const std::string file = o.law_path ? *o.law_path : reader.text("friction.law", "");
  if (file.empty()) reader.fail("friction.law", "missing (required): the state law file (runin homogenise), or --law FILE");
  c.law_path = o.law_path ? *o.law_path : find_case_file(reader, "friction.law", file).string();
  try {
    p.law = std::make_shared<const coupling::StateLaw>(coupling::StateLaw::read_file(c.law_path));
  } catch (const coupling::InputFormatError &e) {
    reader.fail("friction.law", e.what());
  }
  try {
    continuum::asperity_statistics_from_law(*p.law, p.summit_density, p.summit_radius);
  } catch (const std::invalid_argument &e) {
    reader.fail("friction.law", e.what());
  }
  const std::string policy = reader.choice("friction.out_of_range", {"error", "clamp", "archard"}, std::string("archard"));
  p.policy = policy == "clamp" ? coupling::OutOfRange::Clamp
             : policy == "error" ? coupling::OutOfRange::Error
                                 : coupling::OutOfRange::Archard;
}

LubricatedCase read_case(const LubricatedOptions &o) {
  const CaseReader reader(o.case_path, parse_toml(o.case_path), kSchema);
  reader.reject_unknown_keys();
  LubricatedCase c;
  c.path = o.case_path;
  c.title = reader.text("title", o.case_path);
  auto &p = c.parameters;
  p.radius = reader.positive("bearing.shaft_radius");
  p.clearance = reader.positive("bearing.clearance");
  p.length = reader.positive("bearing.length");
  p.load = reader.positive("bearing.load");
  const double E = reader.positive("bearing.youngs_modulus");
  const double nu = reader.number("bearing.poisson_ratio");
  if (!(nu > -1.0 && nu < 0.5)) reader.fail("bearing.poisson_ratio", "must be in (-1, 0.5), got " + CaseReader::format(nu));
  p.effective_modulus = E / (2.0 * (1.0 - nu * nu));   // bore and journal of the same steel

  read_lubrication(reader, p);
  p.flow_factors = reader.choice("lubrication.flow_factors", {"on", "off"}, std::string("on")) == "on";
  p.gamma = reader.positive("lubrication.gamma", 1.0);
  if (p.gamma < 1.0 / 9.0 || p.gamma > 9.0) reader.fail("lubrication.gamma", "must be in [1/9, 9] (Patir & Cheng's fits)");
  p.counterface_rough = reader.choice("lubrication.counterface", {"rough", "smooth"}, std::string("rough")) == "rough";

  read_law(reader, o, c);

  c.run.depth_step_fraction = reader.number("wear.step_fraction", 0.5);
  p.worn_surface = reader.choice("wear.worn_surface", {"law_rq", "truncated"}, std::string("law_rq")) == "truncated"
                       ? continuum::WornSurface::TruncatedSummits
                       : continuum::WornSurface::LawRq;
  // below 0.01 the run takes 50x the shipped case's steps per unit wear (1e-9 ran for hours before too many steps)
  if (!(c.run.depth_step_fraction >= 0.01 && c.run.depth_step_fraction <= 1.0))
    reader.fail("wear.step_fraction", "must be in [0.01, 1] (the worn-depth increment per step over the law's depth "
                                      "spacing), got " + CaseReader::format(c.run.depth_step_fraction));
  c.run.t_end = reader.positive("run.t_end");
  c.run.output_interval = reader.positive("run.output_interval", c.run.t_end / 200.0);
  if (c.run.t_end / c.run.output_interval > 1e6) reader.fail("run.output_interval", "gives more than 1e6 samples");
  c.run.frame_times = reader.has("run.frame_times") ? reader.times_within("run.frame_times", c.run.t_end)
                                                    : std::vector<double>{0.0, c.run.t_end};

  c.stribeck = o.stribeck || reader.has("stribeck");
  const double u_ref = p.speed_time.empty() ? p.speed : p.speed_value.front();
  c.speed_min = reader.positive("stribeck.speed_min", u_ref * 1e-3);
  c.speed_max = reader.positive("stribeck.speed_max", u_ref * 1e3);
  if (!(c.speed_max > c.speed_min)) reader.fail("stribeck.speed_max", "must be above stribeck.speed_min");
  c.points = static_cast<int>(reader.positive_integer("stribeck.points", 50, 2000));
  if (c.points < 2) reader.fail("stribeck.points", "must be >= 2");
  try {
    p.validate();
  } catch (const std::exception &e) {
    reader.fail("lubrication", e.what());   // every field is checked above; a safety net
  }
  return c;
}

const char *kColumns =
    "t_s,distance_m,speed_m_s,eccentricity,attitude_rad,h_min_m,lambda,asperity_share,mu,mu_viscous,mu_boundary,"
    "R_m,h_max_m,h_mean_m,worn_volume_m3,shaft_depth_m,peak_film_pressure_Pa,peak_asperity_pressure_Pa,sommerfeld,"
    "steps";

std::string row(const continuum::MixedSample &s) {
  return fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},"
                     "{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{}",
                     s.t, s.distance, s.speed, s.eccentricity, s.attitude, s.h_min, s.lambda, s.asperity_share, s.mu,
                     s.mu_viscous, s.mu_boundary, s.sigma_contact, s.h_max, s.h_mean, s.bore_volume, s.shaft_depth,
                     s.peak_film_pressure, s.peak_asperity_pressure, s.sommerfeld, s.steps);
}

std::string regime(double lambda) {
  return lambda < 1.0 ? "boundary" : lambda < 3.0 ? "mixed" : "full film";
}

#ifdef RUNIN_HAVE_VTK
// The bore surface (radius R + c + worn depth) over the circumference (closed: the first column repeated) x length;
// bore angle 0 on the load line (pointing down, -y).
std::vector<coupling::SurfaceFrame> surface_frames(const continuum::MixedJournalBearingParameters &p,
                                                   const std::vector<continuum::MixedFrame> &frames) {
  const int n = p.n_theta, ny = p.n_axial, nu = n + 1;
  std::vector<coupling::SurfaceFrame> out;
  for (const auto &f : frames) {
    coupling::SurfaceFrame s;
    s.time = f.t;
    s.nu = nu;
    s.nv = ny;
    std::vector<double> gap(nu * ny), pressure(nu * ny), fill(nu * ny), worn(nu * ny), asperity(nu * ny);
    for (int j = 0; j < ny; ++j) {
      const double z = p.length * (j / double(ny - 1) - 0.5);
      for (int a = 0; a < nu; ++a) {
        const int i = a % n;
        const double alpha = a * 2.0 * M_PI / n, r = p.radius + p.clearance + f.worn_depth[i];
        s.points.push_back({r * std::sin(alpha), -r * std::cos(alpha), z});
        const int k = a + nu * j;
        gap[k] = f.gap[i];
        pressure[k] = f.pressure[i + n * j];
        fill[k] = f.fill[i + n * j];
        worn[k] = f.worn_depth[i];
        asperity[k] = f.asperity_pressure[i];
      }
    }
    s.fields = {{"film_thickness", gap}, {"pressure", pressure}, {"fill_fraction", fill}, {"worn_depth", worn},
                {"asperity_pressure", asperity}};
    out.push_back(std::move(s));
  }
  return out;
}
#endif

}  // namespace

bool is_lubricated_case(const std::string &path) {
  const toml::table root = parse_toml(path);
  return root.contains("lubrication");
}

namespace {

// The run-in with progress on stderr (a 1 h run takes tens of seconds): every 10 % of the simulated time.
continuum::MixedRunReport bearing_run_in(const LubricatedCase &c, const continuum::MixedJournalBearingSystem &system,
                                         std::vector<continuum::MixedSample> &samples,
                                         std::vector<continuum::MixedFrame> &frames) {
  const auto start = std::chrono::steady_clock::now();
  int next_tenth = 1;
  const auto report = continuum::run_in(
      system, c.run,
      [&](const continuum::MixedSample &s) {
        samples.push_back(s);
        if (s.t >= next_tenth * 0.1 * c.run.t_end * (1.0 - 1e-9)) {
          while (s.t >= next_tenth * 0.1 * c.run.t_end * (1.0 - 1e-9)) ++next_tenth;
          const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          if (wall > 2.0)
            fmt::print(stderr, "runin journal-bearing: t = {:.4g} of {:.4g} s, lambda {:.3g}, mu {:.4g} ({:.1f} s)\n", s.t,
                       c.run.t_end, s.lambda, s.mu, wall);
        }
      },
      [&](const continuum::MixedFrame &f) { frames.push_back(f); });
  if (report.ok()) return report;
  if (report.status == continuum::MixedRunStatus::EquilibriumFailed && samples.empty() &&
      report.equilibrium_status == continuum::MixedStatus::GapCloses)
    throw InputError(c.path + ": key 'bearing.load': the film and asperities cannot carry it before the gap closes "
                     "(eccentricity would reach 1): " + report.equilibrium_message +
                     "; lower the load or raise the speed or viscosity");
  if (report.status == continuum::MixedRunStatus::EquilibriumFailed && samples.empty()) {
    // no wear yet: the inputs alone put the bearing outside the solver's range (speed 1e300 m/s, W = 1e-300 N, ...)
    const auto &p = c.parameters;
    const double u = p.speed_time.empty() ? p.speed : p.speed_value.front();
    const double sommerfeld = std::pow(p.radius / p.clearance, 2) * p.viscosity * (u / (2.0 * M_PI * p.radius)) /
                              (p.load / (2.0 * p.radius * p.length));
    throw InputError(fmt::format("{}: key 'bearing.load': no equilibrium of film and asperities at the start ({}); "
                                 "Sommerfeld number {:.3g}: check bearing.load, bearing.clearance, bearing.youngs_modulus, "
                                 "lubrication.viscosity and lubrication.speed", c.path, report.equilibrium_message.empty() ? report.message
                                 : report.equilibrium_message, sommerfeld));
  }
  throw std::runtime_error(std::string("lubricated journal bearing: ") + continuum::to_string(report.status) + ": " +
                           report.message);
}

std::string stribeck_text(const continuum::StribeckResult &stribeck) {
  std::string t = "speed_m_s,hersey,sommerfeld,mu,mu_viscous,mu_boundary,lambda,asperity_share,eccentricity,"
                  "attitude_rad,h_min_m\n";
  for (const auto &q : stribeck.points)
    t += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", q.speed,
                     q.hersey, q.sommerfeld, q.mu, q.mu_viscous, q.mu_boundary, q.lambda, q.asperity_share,
                     q.eccentricity, q.attitude, q.h_min);
  return t;
}

// The CSV files and the plots, staged; returns their names in order.
std::vector<std::string> write_bearing_csv(StagedOutput &out, const LubricatedOptions &o, const LubricatedCase &c,
                                           const std::vector<continuum::MixedSample> &samples,
                                           const continuum::StribeckResult &stribeck, const PlotRunner &plot) {
  std::string text = std::string(kColumns) + "\n";
  for (const auto &s : samples) text += row(s) + "\n";
  out.write("lubricated.csv", text);
  std::vector<std::string> written = {"lubricated.csv"};
  if (c.stribeck) {
    out.write("stribeck.csv", stribeck_text(stribeck));
    written.push_back("stribeck.csv");
  }
  if (o.no_plot) return written;
  plot("plot_lubricated_bearing.py",
       {"runin", out.file("lubricated.csv").string(), out.file("lubricated.png").string(), "--title", c.title});
  written.push_back("lubricated.png");
  if (c.stribeck) {
    plot("plot_lubricated_bearing.py",
         {"stribeck", out.file("stribeck.csv").string(), out.file("stribeck.png").string(), "--title", c.title});
    written.push_back("stribeck.png");
  }
  return written;
}

void print_bearing(const LubricatedCase &c, const std::vector<continuum::MixedSample> &samples) {
  const auto &p = c.parameters;
  const auto &first = samples.front(), &last = samples.back();
  const auto &law = *p.law;
  double peak_film = 0.0, peak_asperity = 0.0;
  for (const auto &s : samples) {
    peak_film = std::max(peak_film, s.peak_film_pressure);
    peak_asperity = std::max(peak_asperity, s.peak_asperity_pressure);
  }
  fmt::print("  bearing           R = {:g} mm, c = {:g} um, L = {:g} mm, W = {:g} N (P = {:.4g} MPa); grid {} x {}\n",
             1e3 * p.radius, 1e6 * p.clearance, 1e3 * p.length, p.load, 1e-6 * p.mean_pressure(), p.n_theta, p.n_axial);
  fmt::print("  lubricant         viscosity {:g} Pa s, supply {:g} Pa at bore angle {:.4g} rad; speed {}\n", p.viscosity,
             p.supply_pressure, p.groove_angle,
             p.speed_time.empty() ? fmt::format("{:g} m/s", p.speed) : fmt::format("table of {} points", p.speed_time.size()));
  fmt::print("  asperities        Greenwood-Tripp, eta = {:.4g} 1/m^2, beta = {:g} m, E* = {:.4g} GPa; {} ({} "
             "counterface)\n",
             p.summit_density, p.summit_radius, 1e-9 * p.effective_modulus,
             p.worn_surface == continuum::WornSurface::TruncatedSummits
                 ? "worn summits: the unworn law's rq, cut at the top the worn volume sets"
                 : "sigma from the law's rq at the worn depth",
             p.counterface_rough ? "rough" : "smooth");
  fmt::print("  regime            initial lambda {:.4g} ({}), peak film pressure {:.4g} MPa, peak asperity pressure "
             "{:.4g} MPa\n",
             first.lambda, regime(first.lambda), 1e-6 * peak_film, 1e-6 * peak_asperity);
  fmt::print("  start             eps {:.5g}, attitude {:.4g} rad, h_min {:.4g} um, asperity share {:.4g}, mu {:.5g} "
             "(viscous {:.4g}, boundary {:.4g}), R {:.4g} nm\n",
             first.eccentricity, first.attitude, 1e6 * first.h_min, first.asperity_share, first.mu, first.mu_viscous,
             first.mu_boundary, 1e9 * first.sigma_contact);
  fmt::print("  end               t = {:.6g} s, s = {:.6g} m: eps {:.5g}, attitude {:.4g} rad, h_min {:.4g} um, lambda "
             "{:.4g} ({}), asperity share {:.4g}, mu {:.5g} (viscous {:.4g}, boundary {:.4g}), R {:.4g} nm\n",
             last.t, last.distance, last.eccentricity, last.attitude, 1e6 * last.h_min, last.lambda, regime(last.lambda),
             last.asperity_share, last.mu, last.mu_viscous, last.mu_boundary, 1e9 * last.sigma_contact);
  fmt::print("  wear              bore: max {:.4g} nm, mean {:.4g} nm, volume {:.6g} mm^3 (law's depth grid ends at "
             "{:.4g} nm{}); journal mean depth {:.4g} nm\n",
             1e9 * last.h_max, 1e9 * last.h_mean, 1e9 * last.bore_volume, 1e9 * law.worn_depth().back(),
             last.h_max > law.worn_depth().back() ? ": beyond it the law's last row holds" : "", 1e9 * last.shaft_depth);
}

}  // namespace

int run_lubricated_bearing(const LubricatedOptions &o, const PlotRunner &plot) {
  const LubricatedCase c = read_case(o);
  const auto &p = c.parameters;
  const continuum::MixedJournalBearingSystem system(p);
  std::vector<continuum::MixedSample> samples;
  std::vector<continuum::MixedFrame> frames;
  const auto start = std::chrono::steady_clock::now();
  const auto report = bearing_run_in(c, system, samples, frames);
  const double run_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  continuum::StribeckResult stribeck;
  double stribeck_seconds = 0.0;
  if (c.stribeck) {
    const auto t0 = std::chrono::steady_clock::now();
    stribeck = continuum::stribeck_sweep(system, system.initial_state(), c.speed_min, c.speed_max, c.points);
    stribeck_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!stribeck.ok())
      throw std::runtime_error(std::string("Stribeck sweep: ") + continuum::to_string(stribeck.status) + ": " +
                               stribeck.message);
  }

  StagedOutput out(o.output_dir, {"lubricated.csv", "stribeck.csv", "lubricated.png", "stribeck.png",
                                  "vtk/bore_film.pvd", "vtk/bore_film_*.vts"});
  const std::vector<std::string> written = write_bearing_csv(out, o, c, samples, stribeck, plot);
  std::string vtk_note = "none (built without VTK)";
#ifdef RUNIN_HAVE_VTK
  const auto vtk_written = coupling::write_surface_series(surface_frames(p, frames), (out.staging() / "vtk").string(),
                                                          "bore_film");
  vtk_note = fmt::format("{} ({} frame(s): film_thickness, pressure, fill_fraction, worn_depth, asperity_pressure)",
                         out.destination_of(vtk_written.back()).string(), frames.size());
#endif
  out.commit();

  fmt::print("runin journal-bearing (lubricated): {}\n  {}\n", c.path, c.title);
  print_bearing(c, samples);
  fmt::print("  steps             {} wear steps, {} film solves, {:.3g} s\n", report.steps, report.film_solves, run_seconds);
  fmt::print("  law lookups       {}\n", continuum::describe(report.range_use, *p.law));
  if (c.stribeck) {
    const auto best = std::min_element(stribeck.points.begin(), stribeck.points.end(),
                                       [](const auto &a, const auto &b) { return a.mu < b.mu; });
    fmt::print("  Stribeck          {} speeds {:.4g} .. {:.4g} m/s ({:.3g} s): friction minimum mu {:.5g} at lambda {:.4g}, "
               "U {:.4g} m/s\n",
               stribeck.points.size(), c.speed_min, c.speed_max, stribeck_seconds, best->mu, best->lambda, best->speed);
  }
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i) fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  fmt::print("\n  VTK               {}\n", vtk_note);
  return 0;
}

}  // namespace runin::cli
