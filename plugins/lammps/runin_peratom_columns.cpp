#include "runin_peratom_columns.h"

#include "atom.h"
#include "memory.h"

using namespace LAMMPS_NS;

RuninPeratomColumns::RuninPeratomColumns(LAMMPS *lmp, int narg, char **arg, int ncolumns, const char *name) :
    Fix(lmp, narg, arg), fewest_restart_columns(ncolumns), ncolumns(ncolumns), name(name)
{
  restart_peratom = 1;
  create_attribute = 1;
  RuninPeratomColumns::grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nlocal; i++) RuninPeratomColumns::set_arrays(i);
}

// A constructor that failed before attach() leaves no callback behind (deleting one would be an error).
RuninPeratomColumns::~RuninPeratomColumns()
{
  if (attached) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(columns);
}

void RuninPeratomColumns::attach()
{
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  attached = true;
}

void RuninPeratomColumns::grow_arrays(int nmax)
{
  memory->grow(columns, nmax, ncolumns, name.c_str());
  array_atom = columns;
  if (ncolumns == 1) vector_atom = columns ? columns[0] : nullptr;    // the block is contiguous
}

void RuninPeratomColumns::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int c = 0; c < ncolumns; c++) columns[j][c] = columns[i][c];
}

void RuninPeratomColumns::set_arrays(int i)
{
  for (int c = 0; c < ncolumns; c++) columns[i][c] = fill;
}

int RuninPeratomColumns::pack_exchange(int i, double *buf)
{
  for (int c = 0; c < ncolumns; c++) buf[c] = columns[i][c];
  return ncolumns;
}

int RuninPeratomColumns::unpack_exchange(int nlocal, double *buf)
{
  for (int c = 0; c < ncolumns; c++) columns[nlocal][c] = buf[c];
  return ncolumns;
}

int RuninPeratomColumns::pack_restart(int i, double *buf)
{
  // first value: the length of this fix's record, by which Atom's restart layout steps over it
  buf[0] = ncolumns + 1;
  for (int c = 0; c < ncolumns; c++) buf[c + 1] = columns[i][c];
  return ncolumns + 1;
}

void RuninPeratomColumns::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  const int stored = static_cast<int>(extra[nlocal][m]) - 1;
  m++;
  const int kept = stored >= fewest_restart_columns && stored <= ncolumns ? stored : ncolumns;
  for (int c = 0; c < ncolumns; c++) columns[nlocal][c] = c < kept ? extra[nlocal][m++] : 0.0;
}

int RuninPeratomColumns::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (const int c : forwarded) buf[m++] = columns[list[k]][c];
  return m;
}

void RuninPeratomColumns::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (const int c : forwarded) columns[i][c] = buf[m++];
}

double RuninPeratomColumns::memory_usage()
{
  return static_cast<double>(atom->nmax) * ncolumns * sizeof(double);
}
