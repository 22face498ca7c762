#include "cli/cmd_fit_law.h"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

#include "cli/case_file.h"  // InputError
#include "cli/staged_file.h"
#include "coupling/ave_time_reader.h"
#include "coupling/friction_law.h"

namespace runin::cli {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

Subcommand add_fit_law_command(CLI::App &app) {
  auto o = std::make_shared<FitLawOptions>();
  auto *cmd = app.add_subcommand("fit-law", "Fit mu(s) to LAMMPS fix ave/time (mode scalar) output");
  cmd->add_option("--input", o->input, "fix ave/time output file")->required();
  cmd->add_option("--distance-column", o->distance_column, "column with the sliding distance, e.g. v_slide")
      ->required();
  cmd->add_option("--mu-column", o->mu_column,
                  "column with the friction coefficient, e.g. c_fric[16] (mu_body of compute runin/friction)")
      ->required();
  cmd->add_option("--output", o->output, "law file to write (JSON)")->required();
  cmd->add_option("--distance-unit", o->distance_unit, "unit of the distance column: m, mm, um, nm, angstrom")
      ->capture_default_str();
  return {cmd, [o] { return fit_law(*o); }};
}

}  // namespace runin::cli
