// `runin journal-bearing CASE.toml --output-dir DIR [--law FILE] [--no-plot]` (thesis ch. 5).
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_journal_bearing_command(CLI::App &app, PlotRunner plot);

}  // namespace runin::cli
