// `runin pin-on-disk`: the pin-on-disk run-in (thesis ch. 4) with contact, wear, VTK and mu0 sweep.
#pragma once

#include <optional>
#include <string>

#include "cli/subcommand.h"

namespace runin::cli {

struct PinOnDiskOptions {
  std::string case_path, output_dir;
  std::optional<std::string> law_path;
  bool no_plot = false;
};

CLI::App *add_pin_on_disk_command(CLI::App &app, PinOnDiskOptions &options);
// Bad input throws InputError (exit 2); numerical or I/O failure std::runtime_error (exit 1).
int run_pin_on_disk(const PinOnDiskOptions &options, const PlotRunner &plot);

}  // namespace runin::cli
