// The lubricated mode of `runin piston-ring` (a case with [lubrication]): doc/lubricated_piston_ring.md.
#pragma once

#include <optional>
#include <string>

#include "cli/subcommand.h"

namespace runin::cli {

int run_lubricated_piston_ring(const std::string &case_path, const std::string &output_dir,
                               const std::optional<std::string> &law_path, bool no_plot, const PlotRunner &plot);

}  // namespace runin::cli
