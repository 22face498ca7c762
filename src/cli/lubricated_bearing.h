// The lubricated (mixed-lubrication) mode of `runin journal-bearing`: a case with a [lubrication] table
// (doc/lubricated_journal_bearing.md). Reads the case, runs continuum::run_in and the Stribeck sweep, writes.
#pragma once

#include <optional>
#include <string>

#include "cli/subcommand.h"

namespace runin::cli {

// True when the case file has a [lubrication] table (the dry reader is not used then).
bool is_lubricated_case(const std::string &path);

struct LubricatedOptions {
  std::string case_path, output_dir;
  std::optional<std::string> law_path;
  bool no_plot = false;
  bool stribeck = false;   // --stribeck: run the sweep even without a [stribeck] table
};

int run_lubricated_bearing(const LubricatedOptions &options, const PlotRunner &plot);

}  // namespace runin::cli
