// VTK output of asperity populations (written with the VTK library; opens in ParaView).
#pragma once

#include "coupling/lammps_dump.h"

#include <string>
#include <vector>

namespace runin::coupling {

// One .vtp per snapshot (points at x y z; every other dump column as a point-data array)
// and a .pvd collection indexed by timestep. Files are written to a temporary name and renamed.
// Returns the paths written, the .pvd last.
std::vector<std::string> write_vtk_series(const std::vector<DumpSnapshot> &snapshots, const std::string &dump_path,
                                          const std::string &output_dir, const std::string &stem);

}  // namespace runin::coupling
