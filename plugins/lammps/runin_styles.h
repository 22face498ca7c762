// The RunIn styles, for registration into a LAMMPS instance (lmp_runin) or a plugin table.
#pragma once

#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace runin_lammps {

struct StyleEntry {
  const char *kind;    // "pair", "fix" or "compute", as LAMMPS's plugin table names them
  const char *name;
  const char *info;
  void *(*create_pair)(void *lmp);
  void *(*create_fix_or_compute)(void *lmp, int narg, char **arg);
};

const std::vector<StyleEntry> &styles();

// Insert every RunIn style into the instance's style maps, as the PLUGIN package does.
void register_styles(LAMMPS_NS::LAMMPS *lmp);

}    // namespace runin_lammps
