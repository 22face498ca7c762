// Reader for LAMMPS text dumps of style custom (one or more snapshots).
#pragma once

#include "coupling/ave_time_reader.h"  // InputFormatError

#include <string>
#include <vector>

namespace runin::coupling {

struct DumpSnapshot {
  long long timestep = 0;
  std::vector<std::string> columns;        // from the "ITEM: ATOMS ..." line
  std::vector<std::vector<double>> values; // values[column][atom]

  // Index of a column by name; throws InputFormatError naming the file if absent.
  std::size_t column(const std::string &name, const std::string &file) const;
};

// All snapshots in the file; a malformed file throws InputFormatError with file:line.
std::vector<DumpSnapshot> read_custom_dump(const std::string &path);

}  // namespace runin::coupling
