// Per-atom column store of the RunIn fixes on both hosts: an nmax x ncolumns block of doubles (one memory->grow
// block, so a row pointer or, for one column, columns[0] is raw access for the force loops) with the host's
// per-atom storage set: grow/copy/set, exchange between ranks and the restart record (buf[0] = ncolumns + 1, then
// the columns, found by the atom->extra walk over nth). `Fix` is the host's Fix class (LAMMPS or LIGGGHTS: the
// same members and virtuals for this set); forward communication differs by host and stays with the host's fixes.
//
// The deriving constructor parses, fills its initial values (the owned rows start at `fill`), and calls attach()
// last, once nothing can fail: the grow and restart callbacks are registered there (in the fix's creation order,
// which fixes the order of the restart records) and removed by the destructor only if attach() ran.
#pragma once

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace runin_host {

template <class Fix> class PeratomColumns : public Fix {
 public:
  ~PeratomColumns() override
  {
    if (attached) {
      this->atom->delete_callback(this->id, kGrowCallback);
      this->atom->delete_callback(this->id, kRestartCallback);
    }
    this->memory->destroy(columns);
  }

  void grow_arrays(int nmax) override
  {
    this->memory->grow(columns, nmax, ncolumns, name.c_str());
    this->array_atom = columns;
    if (ncolumns == 1) this->vector_atom = columns ? columns[0] : nullptr;    // the block is contiguous
  }
  void copy_arrays(int i, int j, int /*delflag*/) override
  {
    for (int c = 0; c < ncolumns; c++) columns[j][c] = columns[i][c];
  }
  void set_arrays(int i) override
  {
    for (int c = 0; c < ncolumns; c++) columns[i][c] = fill;
  }
  int pack_exchange(int i, double *buf) override
  {
    for (int c = 0; c < ncolumns; c++) buf[c] = columns[i][c];
    return ncolumns;
  }
  int unpack_exchange(int nlocal, double *buf) override
  {
    for (int c = 0; c < ncolumns; c++) columns[nlocal][c] = buf[c];
    return ncolumns;
  }
  int pack_restart(int i, double *buf) override
  {
    // first value: the length of this fix's record, by which the host's restart layout steps over it
    buf[0] = ncolumns + 1;
    for (int c = 0; c < ncolumns; c++) buf[c + 1] = columns[i][c];
    return ncolumns + 1;
  }
  void unpack_restart(int nlocal, int nth) override
  {
    double **extra = this->atom->extra;
    int m = 0;
    for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
    const int stored = static_cast<int>(extra[nlocal][m]) - 1;
    m++;
    const int kept = stored >= fewest_restart_columns && stored <= ncolumns ? stored : ncolumns;
    for (int c = 0; c < ncolumns; c++) columns[nlocal][c] = c < kept ? extra[nlocal][m++] : 0.0;
  }
  int size_restart(int) override { return ncolumns + 1; }
  int maxsize_restart() override { return ncolumns + 1; }
  double memory_usage() override { return static_cast<double>(this->atom->nmax) * ncolumns * sizeof(double); }

  // The sum of one column over the owned atoms of a group (this rank's share).
  double local_sum(int column, int groupbit) const
  {
    double sum = 0.0;
    const int *mask = this->atom->mask;
    for (int i = 0; i < this->atom->nlocal; i++)
      if (mask[i] & groupbit) sum += columns[i][column];
    return sum;
  }

 protected:
  // name: the block's name in memory errors
  PeratomColumns(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg, int ncolumns, const char *name) :
      Fix(lmp, narg, arg), fewest_restart_columns(ncolumns), ncolumns(ncolumns), name(name)
  {
    this->restart_peratom = 1;
    this->create_attribute = 1;
    PeratomColumns::grow_arrays(this->atom->nmax);
    for (int i = 0; i < this->atom->nlocal; i++) PeratomColumns::set_arrays(i);
  }
  void attach()
  {
    this->atom->add_callback(kGrowCallback);
    this->atom->add_callback(kRestartCallback);
    attached = true;
  }

  double **columns = nullptr;    // nmax rows of ncolumns (array_atom; vector_atom = columns[0] for one column)
  double fill = 0.0;             // every column of a newly created atom (set_arrays)
  // Restart records with fewer columns, down to this many (an older layout), are read with the rest at 0.
  int fewest_restart_columns;

 private:
  // Atom::GROW and Atom::RESTART of LAMMPS; LIGGGHTS's Atom takes the same numbers without names
  static constexpr int kGrowCallback = 0, kRestartCallback = 1;
  const int ncolumns;
  const std::string name;
  bool attached = false;
};

}    // namespace runin_host
