// `runin piston-ring CASE.toml --output-dir DIR [--law FILE] [--no-plot]` (thesis ch. 6).
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_piston_ring_command(CLI::App &app, PlotRunner plot);

}  // namespace runin::cli
