// `runin fit-law --input FILE --distance-column NAME --mu-column NAME --output law.json [--distance-unit U]`:
// tabulates mu(s) from LAMMPS fix ave/time output and fits the run-in form (coupling/friction_law.h).
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_fit_law_command(CLI::App &app);

}  // namespace runin::cli
