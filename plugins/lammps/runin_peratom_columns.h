// Per-atom column store of the RunIn fixes: an nmax x ncolumns block of doubles (one memory->grow block, so a
// row pointer or, for one column, columns[0] is raw access for the force loops) with LAMMPS's whole per-atom
// storage set: grow/copy/set, exchange between ranks, the restart record (buf[0] = ncolumns + 1, then the
// columns) and forward communication of chosen columns to ghosts. A fix derives from it and keeps its physics.
//
// The deriving constructor parses, fills its initial values (the owned rows start at `fill`), and calls attach()
// last, once nothing can fail: the grow and restart callbacks are registered there (in the fix's creation order,
// which fixes the order of the restart records) and removed by the destructor only if attach() ran.
#ifndef LMP_RUNIN_PERATOM_COLUMNS_H
#define LMP_RUNIN_PERATOM_COLUMNS_H

#include "fix.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class RuninPeratomColumns : public Fix {
 public:
  ~RuninPeratomColumns() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return ncolumns + 1; }
  int maxsize_restart() override { return ncolumns + 1; }
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 protected:
  // name: the block's name in memory errors
  RuninPeratomColumns(class LAMMPS *, int, char **, int ncolumns, const char *name);
  void attach();

  double **columns = nullptr;    // nmax rows of ncolumns (array_atom; vector_atom = columns[0] for one column)
  double fill = 0.0;             // every column of a newly created atom (set_arrays)
  // Restart records with fewer columns, down to this many (an older layout), are read with the rest at 0.
  int fewest_restart_columns;
  // The columns sent to ghosts, in this order per atom; the fix sets comm_forward to the most it ever sends.
  std::vector<int> forwarded;

 private:
  const int ncolumns;
  const std::string name;
  bool attached = false;
};

}    // namespace LAMMPS_NS

#endif
