// VTK output of asperity populations (written with the VTK library; opens in ParaView).
#pragma once

#include "coupling/lammps_dump.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace runin::coupling {

// One .vtp per snapshot (points at x y z; every other dump column as a point-data array)
// and a .pvd collection indexed by timestep. Files are written to a temporary name and renamed.
// Returns the paths written, the .pvd last.
std::vector<std::string> write_vtk_series(const std::vector<DumpSnapshot> &snapshots, const std::string &dump_path,
                                          const std::string &output_dir, const std::string &stem);

// A contact surface at one time: an nu x nv structured grid of points (index u fastest), e.g. the
// revolved pin profile, the bore arc x axial width, or the liner stroke x circumference, with
// point fields such as pressure and wear depth.
struct SurfaceFrame {
  double time = 0.0;
  int nu = 0, nv = 0;
  std::vector<std::array<double, 3>> points;                       // nu * nv, point (i, j) at i + nu j
  std::vector<std::pair<std::string, std::vector<double>>> fields;  // name, nu * nv values

  void validate() const;  // throws std::invalid_argument on size mismatches
};

// One .vts per frame (stem_NNNN.vts) and a .pvd collection indexed by time, written atomically.
// Returns the paths written, the .pvd last.
std::vector<std::string> write_surface_series(const std::vector<SurfaceFrame> &frames, const std::string &output_dir,
                                              const std::string &stem);

}  // namespace runin::coupling
