#include "cli/cmd_dump_to_vtk.h"

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/case_file.h"  // InputError
#include "cli/staged_file.h"
#include "coupling/lammps_dump.h"
#ifdef RUNIN_HAVE_VTK
#include "coupling/vtk_export.h"
#endif

namespace runin::cli {
namespace {

int dump_to_vtk(const std::string &dump_path, const std::string &output_dir, const std::string &stem) {
#ifdef RUNIN_HAVE_VTK
  std::vector<coupling::DumpSnapshot> snapshots;
  try {
    snapshots = coupling::read_custom_dump(dump_path);
  } catch (const coupling::InputFormatError &e) {
    throw InputError(e.what());
  }
  // The per-atom wear state's columns (fix RUNIN/WEAR_STATE, ID RUNIN_WEAR_STATE) and the film coverage (fix
  // RUNIN/FILM, ID RUNIN_FILM) under the names of what they
  // hold, so that ParaView lists worn_depth rather than f_RUNIN_WEAR_STATE[3]
  static const std::map<std::string, std::string> readable = {
      {"f_RUNIN_WEAR_STATE[1]", "volume_lost"},   {"f_RUNIN_WEAR_STATE[2]", "volume_gained"},
      {"f_RUNIN_WEAR_STATE[3]", "worn_depth"},    {"f_RUNIN_WEAR_STATE[4]", "flat_radius"},
      {"f_RUNIN_WEAR_STATE[5]", "volume_flattened"}, {"f_RUNIN_WEAR_STATE[6]", "surface_rise"},
      {"f_RUNIN_FILM", "film_coverage"}};
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
  throw std::runtime_error("this runin was built without VTK (configure with -DRUNIN_WITH_VTK=ON)");
#endif
}

}  // namespace

Subcommand add_dump_to_vtk_command(CLI::App &app) {
  struct Options {
    std::string dump_path, output_dir, stem = "asperities";
  };
  auto o = std::make_shared<Options>();
  auto *cmd = app.add_subcommand("dump-to-vtk", "Convert a LAMMPS custom dump to VTK (.vtp per snapshot + .pvd)");
  cmd->add_option("dump", o->dump_path, "LAMMPS dump file (style custom with x y z columns)")->required();
  cmd->add_option("--output-dir", o->output_dir, "directory for the .vtp files and the .pvd collection")
      ->required()
      ->check(output_directory());
  cmd->add_option("--stem", o->stem, "file name stem")->capture_default_str();
  return {cmd, [o] { return dump_to_vtk(o->dump_path, o->output_dir, o->stem); }};
}

}  // namespace runin::cli
