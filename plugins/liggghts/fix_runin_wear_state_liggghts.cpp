#include "fix_runin_wear_state_liggghts.h"

#include "runin_liggghts_errors.h"

#include "atom.h"
#include "comm.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {
constexpr int kGeometryColumns = 2;    // WEAR_DEPTH, FLAT_RADIUS: all the force needs from a ghost
}

FixRuninWearStateLiggghts::FixRuninWearStateLiggghts(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), values(nullptr), changed_here(1), changed_sent(0), changed_anywhere(1),
    changed_request(MPI_REQUEST_NULL), changed_pending(false), forwarded(0), source(nullptr), nmax_source(0),
    send_indices(false)
{
  if (narg > 3)
    runin_liggghts::all(lmp, FLERR, "fix RUNIN/WEAR_STATE: takes no keywords in LIGGGHTS (a start from a given "
                                    "worn state is LAMMPS-only)");
  create_attribute = 1;
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  peratom_freq = 1;
  comm_forward = kGeometryColumns;
  restart_peratom = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);    // grow
  atom->add_callback(1);    // restart
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixRuninWearStateLiggghts::~FixRuninWearStateLiggghts()
{
  if (changed_pending) MPI_Wait(&changed_request, MPI_STATUS_IGNORE);
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(values);
  memory->destroy(source);
}

FixRuninWearStateLiggghts *FixRuninWearStateLiggghts::find(Modify *modify)
{
  const int ifix = modify->find_fix(default_id);
  return ifix >= 0 ? dynamic_cast<FixRuninWearStateLiggghts *>(modify->fix[ifix]) : nullptr;
}

FixRuninWearStateLiggghts *FixRuninWearStateLiggghts::find_or_create(Modify *modify)
{
  if (FixRuninWearStateLiggghts *existing = find(modify)) return existing;
  char id[] = "RUNIN_WEAR_STATE", group[] = "all", style[] = "RUNIN/WEAR_STATE";
  char *args[] = {id, group, style};
  modify->add_fix(3, args);
  return find(modify);
}

int FixRuninWearStateLiggghts::setmask()
{
  return FixConst::END_OF_STEP;
}

void FixRuninWearStateLiggghts::refresh_geometry_all()
{
  for (int i = 0; i < atom->nlocal; i++) refresh_geometry(i, atom->radius ? atom->radius[i] : 0.0);
  changed_here = 1;    // volumes or radii may have been set: send at least once
}

void FixRuninWearStateLiggghts::end_of_step()
{
  if (comm->nprocs == 1 || changed_pending) return;
  changed_sent = changed_here;
  MPI_Iallreduce(&changed_sent, &changed_anywhere, 1, MPI_INT, MPI_MAX, world, &changed_request);
  changed_pending = true;
}

bool FixRuninWearStateLiggghts::changed_globally()
{
  if (comm->nprocs == 1) return changed_here != 0;
  if (!changed_pending) {    // no step ended since the last send (a run's setup): reduce now
    MPI_Allreduce(&changed_here, &changed_anywhere, 1, MPI_INT, MPI_MAX, world);
    return changed_anywhere != 0;
  }
  MPI_Wait(&changed_request, MPI_STATUS_IGNORE);
  changed_pending = false;
  // a change after the reduction started (none within a run: it starts when the step's styles are done) stays
  // in changed_here for the next reduction; every rank must take the same branch, so only the reduced flag counts
  return changed_anywhere != 0;
}

bool FixRuninWearStateLiggghts::forward_geometry(bool always)
{
  // every rank takes the same branch: `always` and neighbor->ago are the same everywhere, the flag is reduced
  const bool send = changed_globally() || always || neighbor->ago == 0;
  if (!send) return false;
  if (comm->nprocs > 1) {
    comm->forward_comm_fix(this);
  } else {
    if (always || neighbor->ago == 0) find_sources();
    const int nall = atom->nlocal + atom->nghost;
    for (int j = atom->nlocal; j < nall; j++) {
      const double *from = values[source[j]];
      values[j][WEAR_DEPTH] = from[WEAR_DEPTH];
      values[j][FLAT_RADIUS] = from[FLAT_RADIUS];
    }
  }
  changed_here = 0;
  ++forwarded;
  return true;
}

void FixRuninWearStateLiggghts::find_sources()
{
  if (atom->nmax > nmax_source) {
    nmax_source = atom->nmax;
    memory->destroy(source);
    memory->create(source, nmax_source, "runin/wear_state:source");
  }
  for (int i = 0; i < atom->nlocal; i++) source[i] = i;
  send_indices = true;    // the swaps run in order: a ghost sent again takes the source it was given
  comm->forward_comm_fix(this);
  send_indices = false;
}

void FixRuninWearStateLiggghts::post_run()
{
  if (changed_pending) {
    MPI_Wait(&changed_request, MPI_STATUS_IGNORE);
    changed_pending = false;
    changed_here |= changed_anywhere;
  }
  forwarded = 0;
}

double FixRuninWearStateLiggghts::local_sum(Column column, int groupbit) const
{
  double sum = 0.0;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) sum += values[i][column];
  return sum;
}

void FixRuninWearStateLiggghts::grow_arrays(int nmax)
{
  memory->grow(values, nmax, NCOLUMNS, "runin/wear_state:values");
  array_atom = values;
}

void FixRuninWearStateLiggghts::copy_arrays(int i, int j, int)
{
  for (int c = 0; c < NCOLUMNS; c++) values[j][c] = values[i][c];
}

void FixRuninWearStateLiggghts::set_arrays(int i)
{
  for (int c = 0; c < NCOLUMNS; c++) values[i][c] = 0.0;
}

int FixRuninWearStateLiggghts::pack_exchange(int i, double *buf)
{
  for (int c = 0; c < NCOLUMNS; c++) buf[c] = values[i][c];
  return NCOLUMNS;
}

int FixRuninWearStateLiggghts::unpack_exchange(int nlocal, double *buf)
{
  for (int c = 0; c < NCOLUMNS; c++) values[nlocal][c] = buf[c];
  return NCOLUMNS;
}

int FixRuninWearStateLiggghts::pack_restart(int i, double *buf)
{
  buf[0] = NCOLUMNS + 1;    // LIGGGHTS skips per-fix blocks by this count
  for (int c = 0; c < NCOLUMNS; c++) buf[c + 1] = values[i][c];
  return NCOLUMNS + 1;
}

void FixRuninWearStateLiggghts::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int c = 0; c < NCOLUMNS; c++) values[nlocal][c] = extra[nlocal][m++];
}

int FixRuninWearStateLiggghts::pack_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  if (send_indices) {
    for (int k = 0; k < n; k++) {
      buf[m++] = source[list[k]];
      buf[m++] = 0.0;
    }
    return kGeometryColumns;
  }
  for (int k = 0; k < n; k++) {
    buf[m++] = values[list[k]][WEAR_DEPTH];
    buf[m++] = values[list[k]][FLAT_RADIUS];
  }
  return kGeometryColumns;    // LIGGGHTS's Comm::forward_comm_fix takes the count per atom
}

void FixRuninWearStateLiggghts::unpack_comm(int n, int first, double *buf)
{
  int m = 0;
  if (send_indices) {
    for (int i = first; i < first + n; i++, m += 2) source[i] = static_cast<int>(buf[m]);
    return;
  }
  for (int i = first; i < first + n; i++) {
    values[i][WEAR_DEPTH] = buf[m++];
    values[i][FLAT_RADIUS] = buf[m++];
  }
}

double FixRuninWearStateLiggghts::memory_usage()
{
  return static_cast<double>(atom->nmax) * NCOLUMNS * sizeof(double);
}
