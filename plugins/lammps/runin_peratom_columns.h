// Per-atom column store of the LAMMPS RunIn fixes: the store both hosts share (plugins/common/peratom_columns.h:
// grow/copy/set, exchange, the restart record, attach()) and LAMMPS's forward communication of the columns a
// fix chooses to ghosts. A fix derives from it and keeps its physics.
#ifndef LMP_RUNIN_PERATOM_COLUMNS_H
#define LMP_RUNIN_PERATOM_COLUMNS_H

#include "atom.h"
#include "fix.h"
#include "memory.h"
#include "peratom_columns.h"

#include <vector>

namespace LAMMPS_NS {

static_assert(Atom::GROW == 0 && Atom::RESTART == 1, "runin_host::PeratomColumns registers callbacks 0 and 1");

class RuninPeratomColumns : public runin_host::PeratomColumns<Fix> {
 public:
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

 protected:
  using runin_host::PeratomColumns<Fix>::PeratomColumns;

  // The columns sent to ghosts, in this order per atom; the fix sets comm_forward to the most it ever sends.
  std::vector<int> forwarded;
};

}    // namespace LAMMPS_NS

#endif
