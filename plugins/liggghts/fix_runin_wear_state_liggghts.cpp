#include "fix_runin_wear_state_liggghts.h"

#include "pair_runin_asperity_liggghts.h"
#include "runin_liggghts_errors.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "runin_liggghts_comm_access.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {
// WEAR_DEPTH, FLAT_RADIUS and VOLUME_FLATTENED: all the force needs from a ghost (the last for a reload of
// flattened summits)
constexpr int kGeometryColumns = 3;
}

FixRuninWearStateLiggghts::FixRuninWearStateLiggghts(LAMMPS *lmp, int narg, char **arg) :
    PeratomColumns(lmp, narg, arg, NCOLUMNS, "runin/wear_state:values"), changed_here(1), forwarded(0), source(nullptr),
    nmax_source(0),
    send_indices(false), ghosts_wanted(false), exchange_pending(false), exchange_comm(MPI_COMM_NULL), next_swap(0),
    exchange_dirty(false), plan_known(false)
{
  if (narg > 3)
    runin_liggghts::all(lmp, FLERR, "fix RUNIN/WEAR_STATE: takes no keywords in LIGGGHTS (a start from a given "
                                    "worn state is LAMMPS-only)");
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  peratom_freq = 1;
  comm_forward = kGeometryColumns;
  attach();
}

FixRuninWearStateLiggghts::~FixRuninWearStateLiggghts()
{
  if (exchange_pending) finish_exchange(false);
  if (exchange_comm != MPI_COMM_NULL) MPI_Comm_free(&exchange_comm);
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
  return FixConst::END_OF_STEP | FixConst::PRE_EXCHANGE;
}

void FixRuninWearStateLiggghts::refresh_geometry_all()
{
  for (int i = 0; i < atom->nlocal; i++) refresh_geometry(i, atom->radius ? atom->radius[i] : 0.0);
  changed_here = 1;    // volumes or radii may have been set: send at least once, to every ghost
  full_copy = true;
}

bool FixRuninWearStateLiggghts::forward_geometry(bool always)
{
  const bool reneighboured = always || neighbor->ago == 0;
  if (comm->nprocs == 1) {
    if (!changed_here && !reneighboured) return false;
    if (reneighboured) find_sources();
    if (reneighboured || full_copy) {
      const int nall = atom->nlocal + atom->nghost;
      for (int j = atom->nlocal; j < nall; j++) {
        const double *from = columns[source[j]];
        columns[j][WEAR_DEPTH] = from[WEAR_DEPTH];
        columns[j][FLAT_RADIUS] = from[FLAT_RADIUS];
        columns[j][VOLUME_FLATTENED] = from[VOLUME_FLATTENED];
      }
    } else {
      for (const int i : changed_atoms)
        for (int k = image_start[i]; k < image_start[i + 1]; k++) {
          columns[image_list[k]][WEAR_DEPTH] = columns[i][WEAR_DEPTH];
          columns[image_list[k]][FLAT_RADIUS] = columns[i][FLAT_RADIUS];
          columns[image_list[k]][VOLUME_FLATTENED] = columns[i][VOLUME_FLATTENED];
        }
    }
    changed_atoms.clear();
    ++copy_round;
    full_copy = false;
    changed_here = 0;
    ++forwarded;
    return true;
  }
  ghosts_wanted = true;
  if (exchange_pending && !reneighboured) {
    finish_exchange(true);
    return true;
  }
  // a run's setup, a reneighbouring (the exchange, if any, was completed before it: pre_exchange) or the
  // first step of a run: LIGGGHTS's blocking forward communication along the current plan
  if (exchange_pending) finish_exchange(false);
  comm->forward_comm_fix(this);
  changed_here = 0;
  plan_known = false;    // the plan may be new
  ++forwarded;
  return true;
}

// The step's geometry is final (the pair and fix runin/wall have run): post the exchange.
void FixRuninWearStateLiggghts::end_of_step()
{
  if (comm->nprocs == 1 || !ghosts_wanted || exchange_pending) return;
  start_exchange();
}

// Atoms are about to migrate and the swap plan to change: complete the exchange on the old plan (every rank
// reneighbours on the same step, so every rank completes it here).
void FixRuninWearStateLiggghts::pre_exchange()
{
  if (exchange_pending) finish_exchange(false);
}

void FixRuninWearStateLiggghts::start_exchange()
{
  if (exchange_comm == MPI_COMM_NULL) MPI_Comm_dup(world, &exchange_comm);
  const runin_liggghts::SwapPlan plan = runin_liggghts::swap_plan(comm);
  if (!plan_known) {
    send_buffer.resize(plan.nswap);
    recv_buffer.resize(plan.nswap);
    highest_sent.assign(plan.nswap, -1);
    for (int s = 0; s < plan.nswap; s++) {
      for (int k = 0; k < plan.sendnum[s]; k++)
        highest_sent[s] = plan.sendlist[s][k] > highest_sent[s] ? plan.sendlist[s][k] : highest_sent[s];
      send_buffer[s].resize(1 + kGeometryColumns * static_cast<std::size_t>(plan.sendnum[s]));
      recv_buffer[s].resize(1 + kGeometryColumns * static_cast<std::size_t>(plan.recvnum[s]));
    }
    plan_known = true;
  }
  requests.assign(2 * plan.nswap, MPI_REQUEST_NULL);
  received.assign(plan.nswap, 0);
  exchange_dirty = changed_here != 0;
  changed_here = 0;
  next_swap = 0;
  exchange_pending = true;
  advance_exchange(false);
}

// Posts (or, for a swap within this rank, copies) the swaps in order as long as what they send is known; with
// `wait`, waits for the receives a swap needs instead of stopping. Returns whether every swap is posted.
bool FixRuninWearStateLiggghts::advance_exchange(bool wait)
{
  const runin_liggghts::SwapPlan plan = runin_liggghts::swap_plan(comm);
  const int me = comm->me, nlocal = atom->nlocal;
  for (; next_swap < plan.nswap; next_swap++) {
    const int s = next_swap;
    const int *list = plan.sendlist[s];
    // the ghosts this swap sends must have their values: received in an earlier swap that is complete
    const int highest = highest_sent[s];
    for (int r = 0; r < s && highest >= nlocal; r++) {
      if (received[r] || plan.recvnum[r] == 0 || highest < plan.firstrecv[r]) continue;
      if (!wait) return false;
      receive_swap(r, true);
    }
    if (plan.sendproc[s] == me) {
      received[s] = 1;
      if (!exchange_dirty) continue;    // nothing this swap copies changed
      for (int k = 0; k < plan.recvnum[s]; k++) {
        columns[plan.firstrecv[s] + k][WEAR_DEPTH] = columns[list[k]][WEAR_DEPTH];
        columns[plan.firstrecv[s] + k][FLAT_RADIUS] = columns[list[k]][FLAT_RADIUS];
        columns[plan.firstrecv[s] + k][VOLUME_FLATTENED] = columns[list[k]][VOLUME_FLATTENED];
      }
      continue;
    }
    double *out = send_buffer[s].data();
    out[0] = exchange_dirty ? 1.0 : 0.0;    // header: whether the columns follow
    int size = 1;
    if (exchange_dirty)
      for (int k = 0; k < plan.sendnum[s]; k++) {
        out[size++] = columns[list[k]][WEAR_DEPTH];
        out[size++] = columns[list[k]][FLAT_RADIUS];
        out[size++] = columns[list[k]][VOLUME_FLATTENED];
      }
    MPI_Irecv(recv_buffer[s].data(), static_cast<int>(recv_buffer[s].size()), MPI_DOUBLE, plan.recvproc[s], s,
              exchange_comm, &requests[2 * s + 1]);
    MPI_Isend(out, size, MPI_DOUBLE, plan.sendproc[s], s, exchange_comm, &requests[2 * s]);
  }
  return true;
}

void FixRuninWearStateLiggghts::receive_swap(int s, bool unpack)
{
  if (received[s]) return;
  MPI_Wait(&requests[2 * s + 1], MPI_STATUS_IGNORE);
  received[s] = 1;
  const std::vector<double> &in = recv_buffer[s];
  if (!(in[0] != 0.0)) return;    // the sender's summits did not change: the ghosts hold their values
  exchange_dirty = true;          // what this rank passes on changed
  if (!unpack) return;
  const runin_liggghts::SwapPlan plan = runin_liggghts::swap_plan(comm);
  for (int k = 0, m = 1; k < plan.recvnum[s]; k++, m += kGeometryColumns) {
    columns[plan.firstrecv[s] + k][WEAR_DEPTH] = in[m];
    columns[plan.firstrecv[s] + k][FLAT_RADIUS] = in[m + 1];
    columns[plan.firstrecv[s] + k][VOLUME_FLATTENED] = in[m + 2];
  }
}

// Completes the exchange: posts what is left (waiting for the receives it needs), receives everything.
// `unpack` false: on a plan about to be replaced (pre_exchange, end of run): the messages are only matched.
void FixRuninWearStateLiggghts::finish_exchange(bool unpack)
{
  advance_exchange(true);
  const int nswap = static_cast<int>(received.size());
  for (int s = 0; s < nswap; s++) receive_swap(s, unpack);    // (copies within this rank are received)
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  exchange_pending = false;
  ++forwarded;
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
  // each owned atom's images, grouped by owner (counting sort)
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  image_start.assign(nlocal + 1, 0);
  for (int j = nlocal; j < nall; j++) image_start[source[j] + 1]++;
  for (int i = 0; i < nlocal; i++) image_start[i + 1] += image_start[i];
  image_list.resize(nall - nlocal);
  std::vector<int> fill(image_start.begin(), image_start.end() - 1);
  for (int j = nlocal; j < nall; j++) image_list[fill[source[j]]++] = j;
  changed_stamp.assign(nlocal, -1);
  changed_atoms.clear();
}

void FixRuninWearStateLiggghts::post_run()
{
  // the pair has no end-of-run hook; its elastic/plastic summits, the only ones with a range, keep this fix
  if (auto *pair = dynamic_cast<PairRuninAsperityLiggghts *>(force->pair)) pair->report_contact_range();
  if (exchange_pending) finish_exchange(false);
  ghosts_wanted = false;
  forwarded = 0;
}

int FixRuninWearStateLiggghts::pack_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  if (send_indices) {
    for (int k = 0; k < n; k++) {
      buf[m++] = source[list[k]];
      for (int c = 1; c < kGeometryColumns; c++) buf[m++] = 0.0;
    }
    return kGeometryColumns;
  }
  for (int k = 0; k < n; k++) {
    buf[m++] = columns[list[k]][WEAR_DEPTH];
    buf[m++] = columns[list[k]][FLAT_RADIUS];
    buf[m++] = columns[list[k]][VOLUME_FLATTENED];
  }
  return kGeometryColumns;    // LIGGGHTS's Comm::forward_comm_fix takes the count per atom
}

void FixRuninWearStateLiggghts::unpack_comm(int n, int first, double *buf)
{
  int m = 0;
  if (send_indices) {
    for (int i = first; i < first + n; i++, m += kGeometryColumns) source[i] = static_cast<int>(buf[m]);
    return;
  }
  for (int i = first; i < first + n; i++) {
    columns[i][WEAR_DEPTH] = buf[m++];
    columns[i][FLAT_RADIUS] = buf[m++];
    columns[i][VOLUME_FLATTENED] = buf[m++];
  }
}
