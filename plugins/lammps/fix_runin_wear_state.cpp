#include "fix_runin_wear_state.h"

#include "atom.h"
#include "error.h"
#include "memory.h"

using namespace LAMMPS_NS;

FixRuninWearState::FixRuninWearState(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), values(nullptr)
{
  if (narg != 3) error->all(FLERR, "fix RUNIN/WEAR_STATE: expected no arguments, got {}", narg - 3);

  restart_peratom = 1;
  create_attribute = 1;
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  peratom_freq = 1;
  comm_forward = NCOLUMNS;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixRuninWearState::~FixRuninWearState()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(values);
}

double FixRuninWearState::local_sum(Column column, int groupbit) const
{
  double sum = 0.0;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) sum += values[i][column];
  return sum;
}

void FixRuninWearState::grow_arrays(int nmax)
{
  memory->grow(values, nmax, NCOLUMNS, "runin/wear_state:values");
  array_atom = values;
}

void FixRuninWearState::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int c = 0; c < NCOLUMNS; c++) values[j][c] = values[i][c];
}

void FixRuninWearState::set_arrays(int i)
{
  for (int c = 0; c < NCOLUMNS; c++) values[i][c] = 0.0;
}

int FixRuninWearState::pack_exchange(int i, double *buf)
{
  for (int c = 0; c < NCOLUMNS; c++) buf[c] = values[i][c];
  return NCOLUMNS;
}

int FixRuninWearState::unpack_exchange(int nlocal, double *buf)
{
  for (int c = 0; c < NCOLUMNS; c++) values[nlocal][c] = buf[c];
  return NCOLUMNS;
}

int FixRuninWearState::pack_restart(int i, double *buf)
{
  // first value: length of this fix's record, as Atom's restart extra layout requires
  buf[0] = NCOLUMNS + 1;
  for (int c = 0; c < NCOLUMNS; c++) buf[c + 1] = values[i][c];
  return NCOLUMNS + 1;
}

void FixRuninWearState::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int c = 0; c < NCOLUMNS; c++) values[nlocal][c] = extra[nlocal][m++];
}

int FixRuninWearState::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < NCOLUMNS; c++) buf[m++] = values[list[k]][c];
  return m;
}

void FixRuninWearState::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int c = 0; c < NCOLUMNS; c++) values[i][c] = buf[m++];
}

double FixRuninWearState::memory_usage()
{
  return static_cast<double>(atom->nmax) * NCOLUMNS * sizeof(double);
}
