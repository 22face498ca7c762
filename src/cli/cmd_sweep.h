// `runin sweep ELEMENT CASE --output-dir DIR [--key KEY]... [--span 10] [--points 3] [--law FILE] [--no-plot]`:
// each free parameter of a machine-element case varied over a decade (log-spaced, the case's value in the
// middle), one run of the element per value (this runin as a child process on a case file kept in
// DIR/cases/), its key numbers in DIR/sweep.csv and a tornado plot.
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_sweep_command(CLI::App &app, PlotRunner plot);

}  // namespace runin::cli
