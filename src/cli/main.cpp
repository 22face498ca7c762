// runin: command-line driver of the continuum side.
//   runin fit-law --input FILE --distance-column NAME --mu-column NAME --output law.json
//   runin fit-feedback DATA.csv --t-column NAME --mu-column NAME --r-column NAME --output CASE.toml [--t-scale X]
// A case file is TOML, or JSON when its name ends in .json (same keys).
//   runin pin-on-disk CASE.toml [--law law.json] --output-dir DIR [--no-plot]
//   runin feedback CASE.toml --output-dir DIR [--no-plot]
//   runin journal-bearing CASE.toml [--law law.json] --output-dir DIR [--no-plot]
//   runin piston-ring CASE.toml [--law law.json] --output-dir DIR [--no-plot]
//   runin sweep ELEMENT CASE.toml --output-dir DIR [--key KEY]... [--span 10] [--points 3] [--no-plot]
//   runin homogenise CASE.toml [--output law.json | --output-dir DIR] [--cache-dir DIR] [--np N] [--lmp PATH] [--deck PATH]
//   runin --version
// Exit codes: 0 success, 1 numerical/plot/I/O failure, 2 bad input.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <csignal>
#include <cerrno>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>

#include "cli/case_file.h"
#include "cli/cmd_fit_feedback.h"
#include "cli/cmd_pin_on_disk.h"
#include "cli/cmd_journal_bearing.h"
#include "cli/cmd_homogenise.h"
#include "cli/cmd_piston_ring.h"
#include "cli/cmd_sweep.h"
#include "cli/runin_version.h"
#include "cli/staged_file.h"
#include "continuum/feedback_system.h"
#include "continuum/pin_on_disk.h"
#include "coupling/ave_time_reader.h"
#include "coupling/friction_law.h"
#include "coupling/lammps_dump.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

extern char **environ;

namespace runin::cli {
namespace {

namespace fs = std::filesystem;

// Numerical, plotting or file-system failure (exit code 1).
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FitLawOptions {
  std::string input, distance_column, mu_column, output, distance_unit = "m";
};

int fit_law(const FitLawOptions &o) {
  double metres = 0.0;
  try {
    metres = coupling::metres_per_unit(o.distance_unit);
  } catch (const std::invalid_argument &e) {
    throw InputError(std::string("--distance-unit: ") + e.what());
  }
  coupling::FitResult fit;
  const coupling::AveTimeTable table = [&] {
    try {
      return coupling::read_ave_time(o.input);
    } catch (const coupling::InputFormatError &e) {
      throw InputError(e.what());
    }
  }();
  coupling::FrictionLaw law = [&] {
    try {
      return coupling::build_law(table, o.distance_column, o.mu_column, o.distance_unit, &fit);
    } catch (const coupling::InputFormatError &e) {
      throw InputError(e.what());
    }
  }();
  StagedFile out(fs::absolute(o.output));
  out.write(coupling::law_to_json_text(law));
  out.commit();

  const auto &u = o.distance_unit;
  fmt::print("runin fit-law: {} ({} rows) -> {}\n", o.input, table.rows(), o.output);
  fmt::print("  columns      distance '{}' [{} = {:g} m], mu '{}'\n", o.distance_column, u, metres, o.mu_column);
  fmt::print("  peak         mu = {:.6g} at s = {:.6g} {}\n", law.table.mu()[law.table.peak_index()],
             law.peak_distance(), u);
  if (law.fit) {
    const auto &f = *law.fit;
    fmt::print("  fit          mu(s) = mu_ss + (mu_0 - mu_ss) exp(-(s - s_peak)/s0) for s >= s_peak\n");
    fmt::print("               mu_0 = {:.6g}, mu_ss = {:.6g}, s0 = {:.6g} {}, s_peak = {:.6g} {}\n", f.mu_0, f.mu_ss,
               f.s0, u, f.s_peak, u);
    fmt::print("               rms residual = {:.3g} over {} points (Levenberg-Marquardt)\n", f.rms_residual, f.points);
  } else {
    fmt::print("  fit          none ({}: {}); the law file holds the table only\n", coupling::to_string(fit.status),
               fit.message);
  }
  return 0;
}

// Runs tools/<script_name> with /usr/bin/python3 (or $RUNIN_PYTHON) and `script_args`.
void run_python_plot(const std::string &script_name, const std::vector<std::string> &script_args) {
  const char *python_env = std::getenv("RUNIN_PYTHON");
  const std::string python = python_env && *python_env ? python_env : RUNIN_DEFAULT_PYTHON;
  const std::string script = std::string(RUNIN_SOURCE_DIR) + "/tools/" + script_name;
  std::vector<std::string> args = {python, script};
  args.insert(args.end(), script_args.begin(), script_args.end());
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // Its own process group, registered with SIGINT/SIGTERM held back: a signal to runin stops the script (and
  // whatever it started) before the staging directory it writes into is removed.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, held, previous;
  sigemptyset(&none);
  sigemptyset(&held);
  sigaddset(&held, SIGINT);
  sigaddset(&held, SIGTERM);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  pthread_sigmask(SIG_BLOCK, &held, &previous);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, python.c_str(), nullptr, &attr, argv.data(), environ);
  if (started == 0) register_child(pid);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  posix_spawnattr_destroy(&attr);
  if (started != 0) throw RunError("cannot start " + python + " for the plot (set RUNIN_PYTHON or use --no-plot)");
  int status = 0;
  pid_t waited = 0;
  while ((waited = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
  }
  unregister_child();
  if (waited < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw RunError("plotting failed: " + python + " " + script + " (use --no-plot to skip)");
}

std::string g17(double x) { return fmt::format("{:.17g}", x); }

struct FeedbackCurve {
  std::vector<continuum::FeedbackSample> samples;
  continuum::FeedbackReport report;
};

FeedbackCurve run_feedback(const tribo::FeedbackModel &model, const continuum::FeedbackRun &run) {
  FeedbackCurve curve;
  curve.report = continuum::simulate(continuum::FeedbackSystem(model), run,
                                     [&](const auto &s) { curve.samples.push_back(s); });
  if (!curve.report.ok())
    throw RunError(std::string(continuum::to_string(curve.report.status)) + ": " + curve.report.message);
  return curve;
}

int feedback(const std::string &case_path, const std::string &output_dir, bool plot) {
  const FeedbackCase c = read_feedback_case(case_path);
  const tribo::FeedbackModel &m = *c.model;
  const FeedbackCurve curve = run_feedback(m, c.run);
  const auto &samples = curve.samples;
  const double rs = m.stationary_roughness();
  const double settle = continuum::settling_time(samples, rs, 0.01);

  // Sweep: one run per value, everything else as in the case.
  struct SweepRow {
    double value, r_star, mu_star, k_star, settle, settle_exact;
  };
  std::vector<SweepRow> rows;
  std::string sweep_curves = "value,t,R,mu\n";
  if (c.sweep) {
    for (double value : c.sweep->values) {
      auto coefficients = c.coefficients;
      auto run = c.run;
      set_feedback_parameter(coefficients, run.initial_roughness, c.sweep->parameter, value);
      const tribo::FeedbackModel model(coefficients, m.kind());
      const auto sweep_curve = run_feedback(model, run);
      const double r = model.stationary_roughness();
      rows.push_back({value, r, model.mu(r), model.k(r), continuum::settling_time(sweep_curve.samples, r, 0.01),
                      model.exact_settling_time(run.initial_roughness, 0.01)});
      for (const auto &s : sweep_curve.samples)
        sweep_curves += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g}\n", value, s.t, s.roughness, s.mu);
    }
  }

  // Everything is computed; the output set is staged and moved in only when complete.
  StagedOutput out(output_dir, {"feedback.csv", "feedback.png", "feedback_sweep.csv", "feedback_sweep.png"});
  std::string text = "t,R,mu,k,wear\n";
  for (const auto &s : samples)
    text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", s.t, s.roughness, s.mu, s.wear_rate, s.wear);
  out.write("feedback.csv", text);
  std::vector<std::string> written = {"feedback.csv"};
  if (c.sweep) {
    std::string sweep_text = c.sweep->parameter + ",R_star,mu_R_star,k_R_star,time_to_1pct,time_to_1pct_exact\n";
    for (const auto &r : rows)
      sweep_text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{},{:.12g}\n", r.value, r.r_star, r.mu_star, r.k_star,
                                r.settle < 0.0 ? std::string() : fmt::format("{:.12g}", r.settle),  // empty: not within t_end
                                r.settle_exact);
    out.write("feedback_sweep.csv", sweep_text);
    written.push_back("feedback_sweep.csv");
  }
  if (plot) {
    run_python_plot("plot_feedback.py",
                    {"curve", out.file("feedback.csv").string(), out.file("feedback.png").string(), "--title",
                     c.title, "--r-star", g17(rs), "--r-min-wear", g17(m.min_wear_roughness()), "--r-min-friction",
                     g17(m.min_friction_roughness()), "--mu-min", g17(m.min_mu())});
    written.push_back("feedback.png");
    if (c.sweep) {
      const fs::path curves_csv = out.scratch("feedback_sweep_curves.csv");  // plot input only
      {
        std::ofstream curves(curves_csv, std::ios::binary);
        curves << sweep_curves;
        if (!curves) throw RunError("cannot write " + curves_csv.string());
      }
      run_python_plot("plot_feedback.py", {"sweep", curves_csv.string(), out.file("feedback_sweep.csv").string(),
                                           out.file("feedback_sweep.png").string(), "--title", c.title,
                                           "--parameter", c.sweep->parameter});
      written.push_back("feedback_sweep.png");
    }
  }
  out.commit();

  const auto &k = m.coefficients();
  const bool dry = m.kind() == tribo::FeedbackKind::dry;
  auto or_none = [](double t) { return t < 0.0 ? std::string("not reached") : fmt::format("{:.6g}", t); };
  const auto &first = samples.front(), &last = samples.back();
  fmt::print("runin feedback: {}\n  {}\n", case_path, c.title);
  if (c.fitted_from) fmt::print("  fitted from       {}\n", *c.fitted_from);
  fmt::print("  model             {} ({} smooths, {} roughens)\n", tribo::to_string(m.kind()),
             dry ? "deformation" : "viscous erosion", dry ? "adhesion" : "capillarity");
  fmt::print("  coefficients      C1 = {} = {:.6g}, C2 = {} = {:.6g}, K1 = {} = {:.6g}, K2 = {} = {:.6g}, A = {:.6g}, B = {:.6g}\n",
             m.thesis_name("C1"), k.C1, m.thesis_name("C2"), k.C2, m.thesis_name("K1"), k.K1, m.thesis_name("K2"), k.K2,
             k.A, k.B);
  fmt::print("  R*                {:.10g}  = sqrt(B K2 / (A K1)), eq. 3.7\n", rs);
  fmt::print("  R_min_wear        {:.10g}  = sqrt(K2 / K1), eq. 3.9; R* minimises wear: {} (A {} B)\n",
             m.min_wear_roughness(), m.stationary_minimises_wear() ? "yes" : "no",
             m.stationary_minimises_wear() ? "==" : "!=");
  fmt::print("  R_min_friction    {:.10g}  = sqrt(C2 / C1), eq. 3.10; R* minimises friction: {} (B K2/(A K1) {} C2/C1)\n",
             m.min_friction_roughness(), m.stationary_minimises_friction() ? "yes" : "no",
             m.stationary_minimises_friction() ? "==" : "!=");
  fmt::print("  mu_min            {:.10g}  = 2 sqrt(C1 C2); mu(R*) = {:.10g}\n", m.min_mu(), m.mu(rs));
  fmt::print("  k_min             {:.10g}  = 2 sqrt(K1 K2); k(R*) = {:.10g}\n", m.min_k(), m.k(rs));
  fmt::print("  run               R {:.6g} -> {:.10g}, mu {:.6g} -> {:.10g}, wear W = {:.6g} at t = {:g}\n",
             first.roughness, last.roughness, first.mu, last.mu, last.wear, last.t);
  fmt::print("  time to 1% of R*  {} (output grid {:g}); closed form {:.6g}\n", or_none(settle),
             c.run.output_interval, m.exact_settling_time(c.run.initial_roughness, 0.01));
  fmt::print("  CVODE             {} steps, rtol {:g}, atol {:g}\n", curve.report.steps, c.run.integrator.rtol,
             c.run.integrator.atol);
  if (c.sweep) {
    fmt::print("  sweep             {} over {} values:\n", c.sweep->parameter, rows.size());
    fmt::print("    {:>12} {:>12} {:>12} {:>12} {:>12}\n", c.sweep->parameter, "R*", "mu(R*)", "k(R*)", "t_1%");
    for (const auto &r : rows)
      fmt::print("    {:>12.6g} {:>12.6g} {:>12.6g} {:>12.6g} {:>12}\n", r.value, r.r_star, r.mu_star, r.k_star,
                 or_none(r.settle));
  }
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  fmt::print("\n");
  return 0;
}

int dump_to_vtk(const std::string &dump_path, const std::string &output_dir, const std::string &stem) {
#ifdef RUNIN_HAVE_VTK
  std::vector<coupling::DumpSnapshot> snapshots;
  try {
    snapshots = coupling::read_custom_dump(dump_path);
  } catch (const coupling::InputFormatError &e) {
    throw InputError(e.what());
  }
  // The per-atom wear state's columns (fix RUNIN/WEAR_STATE, ID RUNIN_WEAR_STATE) under the names of what they
  // hold, so that ParaView lists worn_depth rather than f_RUNIN_WEAR_STATE[3]
  static const std::map<std::string, std::string> readable = {
      {"f_RUNIN_WEAR_STATE[1]", "volume_lost"},   {"f_RUNIN_WEAR_STATE[2]", "volume_gained"},
      {"f_RUNIN_WEAR_STATE[3]", "worn_depth"},    {"f_RUNIN_WEAR_STATE[4]", "flat_radius"},
      {"f_RUNIN_WEAR_STATE[5]", "volume_flattened"}};
  for (auto &snapshot : snapshots)
    for (auto &column : snapshot.columns)
      if (const auto name = readable.find(column); name != readable.end()) column = name->second;
  StagedOutput out(output_dir, {stem + ".pvd", stem + "_*.vtp"});
  const auto written = coupling::write_vtk_series(snapshots, dump_path, out.staging().string(), stem);
  out.commit();
  fmt::print("runin dump-to-vtk: {} snapshot(s) of {} -> {}\n", snapshots.size(), dump_path,
             out.destination_of(written.back()).string());
  return 0;
#else
  (void)dump_path, (void)output_dir, (void)stem;
  throw RunError("this runin was built without VTK (configure with -DRUNIN_WITH_VTK=ON)");
#endif
}

// Edit distance of a and b ('_' and '-' count as equal: pin_on_disk means pin-on-disk).
std::size_t edit_distance(const std::string &a, const std::string &b) {
  auto same = [](char x, char y) { return x == y || ((x == '_' || x == '-') && (y == '_' || y == '-')); };
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// "unknown subcommand 'X'" with the nearest name when it is close (at most a third of its letters differ).
std::string unknown_subcommand(const CLI::App &app, const std::string &given) {
  std::string best, names;
  std::size_t best_distance = std::string::npos;
  for (const CLI::App *sub : app.get_subcommands({})) {
    const std::string &name = sub->get_name();
    names += (names.empty() ? "" : ", ") + name;
    const std::size_t d = edit_distance(given, name);
    if (d < best_distance) best_distance = d, best = name;
  }
  std::string message = "unknown subcommand '" + given + "'";
  if (!best.empty() && best_distance <= std::max<std::size_t>(2, best.size() / 3))
    return message + "; did you mean '" + best + "'?";
  return message + "; the subcommands are " + names + " (runin --help)";
}

std::string version_text() {
  const std::string git = runin_git_describe();
  return std::string("runin ") + runin_version() + (git == "unknown" ? "" : " (git " + git + ")");
}

}  // namespace
}  // namespace runin::cli

int main(int argc, char **argv) {
  using namespace runin::cli;
  CLI::App app{"RunIn: multiscale run-in tribology toolkit (continuum side)", "runin"};
  app.require_subcommand(1);
  // Option errors on one line like every other error (CLI11 adds "Run with --help ..."); set before the
  // subcommands are added, which copy it.
  app.failure_message([](const CLI::App *, const CLI::Error &e) { return "runin: error: " + std::string(e.what()) + "\n"; });

  FitLawOptions fit;
  auto *fit_cmd = app.add_subcommand("fit-law", "Fit mu(s) to LAMMPS fix ave/time (mode scalar) output");
  fit_cmd->add_option("--input", fit.input, "fix ave/time output file")->required();
  fit_cmd->add_option("--distance-column", fit.distance_column, "column with the sliding distance, e.g. v_slide")
      ->required();
  fit_cmd->add_option("--mu-column", fit.mu_column, "column with the friction coefficient, e.g. c_fric[16] (mu_body of compute runin/friction)")
      ->required();
  fit_cmd->add_option("--output", fit.output, "law file to write (JSON)")->required();
  fit_cmd->add_option("--distance-unit", fit.distance_unit, "unit of the distance column: m, mm, um, nm, angstrom")
      ->capture_default_str();

  const Subcommand fit_feedback = add_fit_feedback_command(app, run_python_plot);

  PinOnDiskOptions pod;
  auto *pod_cmd = add_pin_on_disk_command(app, pod);

  std::string fb_case, fb_dir;
  bool fb_no_plot = false;
  auto *fb_cmd = app.add_subcommand("feedback", "Two-mechanism roughness-feedback model R(t), mu(t) (thesis ch. 3)");
  fb_cmd->add_option("case", fb_case, "case file (TOML, or JSON if it ends in .json)")->required();
  fb_cmd->add_option("--output-dir", fb_dir, "directory for feedback.csv and feedback.png (+ sweep files)")->required()
      ->check(output_directory());
  fb_cmd->add_flag("--no-plot", fb_no_plot, "write the CSV(s) only");

  std::string dump_path, vtk_dir, vtk_stem = "asperities";
  auto *vtk_cmd = app.add_subcommand("dump-to-vtk", "Convert a LAMMPS custom dump to VTK (.vtp per snapshot + .pvd)");
  vtk_cmd->add_option("dump", dump_path, "LAMMPS dump file (style custom with x y z columns)")->required();
  vtk_cmd->add_option("--output-dir", vtk_dir, "directory for the .vtp files and the .pvd collection")->required()
      ->check(output_directory());
  vtk_cmd->add_option("--stem", vtk_stem, "file name stem")->capture_default_str();

  const Subcommand journal_bearing = add_journal_bearing_command(app, run_python_plot);
  const Subcommand piston_ring = add_piston_ring_command(app, run_python_plot);
  const Subcommand sweep = add_sweep_command(app, run_python_plot);
  const Subcommand homogenise = add_homogenise_command(app);

  app.set_version_flag("--version", version_text(), "print the version and exit");
  // Before CLI11, whose answer to each of these is only "A subcommand is required".
  if (argc < 2) {
    std::cerr << app.help();
    return 2;
  }
  const std::string first = argv[1];
  if (first == "--version") {
    std::cout << version_text() << "\n";
    return 0;
  }
  const auto subcommands = app.get_subcommands({});
  if (!first.empty() && first[0] != '-' &&
      std::none_of(subcommands.begin(), subcommands.end(), [&](const CLI::App *s) { return s->check_name(first); })) {
    std::cerr << "runin: error: " << unknown_subcommand(app, first) << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError &e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (fit_cmd->parsed()) return fit_law(fit);
    if (fit_feedback.app->parsed()) return fit_feedback.run();
    if (fb_cmd->parsed()) return feedback(fb_case, fb_dir, !fb_no_plot);
    if (vtk_cmd->parsed()) return dump_to_vtk(dump_path, vtk_dir, vtk_stem);
    if (journal_bearing.app->parsed()) return journal_bearing.run();
    if (piston_ring.app->parsed()) return piston_ring.run();
    if (sweep.app->parsed()) return sweep.run();
    if (homogenise.app->parsed()) return homogenise.run();
    if (pod_cmd->parsed()) return run_pin_on_disk(pod, run_python_plot);
    return 2;
  } catch (const InputError &e) {
    std::cerr << "runin: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception &e) {
    std::cerr << "runin: error: " << e.what() << "\n";
    return 1;
  }
}
