// `runin homogenise CASE [--output law.json] [--cache-dir DIR] [--np N] [--lmp PATH] [--deck PATH]`: samples the
// rough-on-flat cell (inputs/in.rve_wall by default) over a log-spaced pressure grid with several seeds per
// pressure, all missing samples under one `mpirun -np N lmp_runin -partition Nx1` (a uloop over the samples), each
// cached under the SHA-256 of its inputs, and writes the state law (runin-state-law v1, doc/state_law.md).
// Usage, cache, failure rule and provenance: doc/homogenise.md.
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_homogenise_command(CLI::App &app);

}  // namespace runin::cli
