// `runin dump-to-vtk DUMP --output-dir DIR [--stem NAME]`: a LAMMPS custom dump as VTK (.vtp per snapshot + .pvd),
// the per-atom wear state under readable names.
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_dump_to_vtk_command(CLI::App &app);

}  // namespace runin::cli
