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

#include "cli/case_file.h"
#include "cli/cmd_dump_to_vtk.h"
#include "cli/cmd_feedback.h"
#include "cli/cmd_fit_feedback.h"
#include "cli/cmd_fit_law.h"
#include "cli/cmd_pin_on_disk.h"
#include "cli/cmd_journal_bearing.h"
#include "cli/cmd_homogenise.h"
#include "cli/cmd_piston_ring.h"
#include "cli/cmd_sweep.h"
#include "cli/python_plot.h"
#include "cli/runin_version.h"

namespace runin::cli {
namespace {

namespace fs = std::filesystem;

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

  const Subcommand fit_law = add_fit_law_command(app);
  const Subcommand fit_feedback = add_fit_feedback_command(app, run_python_plot);

  PinOnDiskOptions pod;
  auto *pod_cmd = add_pin_on_disk_command(app, pod);

  const Subcommand feedback = add_feedback_command(app, run_python_plot);
  const Subcommand dump_to_vtk = add_dump_to_vtk_command(app);

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
    if (fit_law.app->parsed()) return fit_law.run();
    if (fit_feedback.app->parsed()) return fit_feedback.run();
    if (feedback.app->parsed()) return feedback.run();
    if (dump_to_vtk.app->parsed()) return dump_to_vtk.run();
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
