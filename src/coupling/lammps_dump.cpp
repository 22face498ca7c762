#include "coupling/lammps_dump.h"

#include <fstream>
#include <sstream>

namespace runin::coupling {

namespace {
// 1e8 atoms x (id, type, x, y, z, ...) is several GB in memory and in VTK files: beyond it, split the dump.
constexpr long long kMaxDumpAtoms = 100000000;
}  // namespace

std::size_t DumpSnapshot::column(const std::string &name, const std::string &file) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return c;
  throw InputFormatError(file + ": dump has no column '" + name + "'");
}

std::vector<DumpSnapshot> read_custom_dump(const std::string &path) {
  std::ifstream in = open_input(path, "dump file");
  std::vector<DumpSnapshot> snapshots;
  std::string line;
  int lineno = 0;
  auto next = [&](const char *expect) {
    if (!std::getline(in, line)) throw InputFormatError(path + ":" + std::to_string(lineno) + ": truncated, expected " + expect);
    ++lineno;
  };
  auto bad = [&](const std::string &what) { return InputFormatError(path + ":" + std::to_string(lineno) + ": " + what); };

  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    if (line.rfind("ITEM: TIMESTEP", 0) != 0) throw bad("expected 'ITEM: TIMESTEP'");
    DumpSnapshot snap;
    next("the timestep");
    try { snap.timestep = std::stoll(line); } catch (...) { throw bad("timestep is not an integer"); }
    next("'ITEM: NUMBER OF ATOMS'");
    next("the atom count");
    long long natoms = 0;
    try { natoms = std::stoll(line); } catch (...) { throw bad("atom count is not an integer"); }
    if (natoms < 0) throw bad("negative atom count");
    if (natoms > kMaxDumpAtoms)
      throw bad("atom count " + std::to_string(natoms) + " above the limit of " + std::to_string(kMaxDumpAtoms) +
                " per snapshot (split the dump)");
    next("'ITEM: BOX BOUNDS'");
    for (int d = 0; d < 3; ++d) next("box bounds");
    next("'ITEM: ATOMS ...'");
    if (line.rfind("ITEM: ATOMS", 0) != 0) throw bad("expected 'ITEM: ATOMS'");
    std::istringstream header(line.substr(11));
    for (std::string name; header >> name;) snap.columns.push_back(name);
    if (snap.columns.empty()) throw bad("no columns in 'ITEM: ATOMS'");
    // grown row by row: a header that promises more atoms than the file holds ends as 'truncated', not as a
    // failed allocation
    snap.values.assign(snap.columns.size(), std::vector<double>());
    for (long long a = 0; a < natoms; ++a) {
      next("an atom line");
      std::istringstream row(line);
      for (auto &column : snap.values) {
        double value = 0.0;
        if (!(row >> value)) throw bad("expected " + std::to_string(snap.columns.size()) + " numbers");
        column.push_back(value);
      }
    }
    snapshots.push_back(std::move(snap));
  }
  if (snapshots.empty()) throw InputFormatError(path + ": no snapshot in dump file");
  return snapshots;
}

}  // namespace runin::coupling
