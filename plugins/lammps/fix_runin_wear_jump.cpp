#include "fix_runin_wear_jump.h"

#include "fix_runin_wear_state.h"
#include "runin_errors.h"
#include "tribo/cycle_jump.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int kReportedReductions = 5;    // WARNINGs for reduced jumps before they are only counted
}

FixRuninWearJump::FixRuninWearJump(LAMMPS *lmp, int narg, char **arg) :
    RuninPeratomColumns(lmp, narg, arg, kColumns, "runin/wear/jump:phase_start"), factor(1.0), max_depth(0.0),
    phase_start_step(0), extra_steps(0.0),
    jumps(0.0), reduced_jumps(0.0), last_factor(1.0), largest_change(0.0), wear_state(nullptr), phase_started(false)
{
  if (narg != 7 || strcmp(arg[5], "max_depth") != 0)
    error->all(FLERR, "fix runin/wear/jump: expected 'fix ID group runin/wear/jump N M max_depth D'{}",
               narg == 7 ? fmt::format(", got keyword '{}'", arg[5]) : fmt::format(", got {} arguments", narg - 3));
  const char *where = "fix runin/wear/jump";
  const double every = runin_lammps::finite_number(lmp, FLERR, where, "N (steps per phase)", arg[3]);
  if (!(every >= 1.0) || every != std::floor(every) || every > 2.0e9)
    error->all(FLERR, "fix runin/wear/jump: N (steps per phase) must be an integer >= 1, got {}", arg[3]);
  nevery = static_cast<int>(every);
  factor = runin_lammps::finite_number(lmp, FLERR, where, "M (jump factor)", arg[4]);
  if (!(factor >= 1.0) || !std::isfinite(factor))
    error->all(FLERR, "fix runin/wear/jump: M (jump factor) must be >= 1 and finite, got {}", arg[4]);
  max_depth = runin_lammps::finite_number(lmp, FLERR, where, "max_depth", arg[6]);
  if (!(max_depth > 0.0) || !std::isfinite(max_depth))
    error->all(FLERR, "fix runin/wear/jump: max_depth must be > 0 and finite, got {}", arg[6]);

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 5;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
  restart_global = 1;

  attach();
  wear_state = FixRuninWearState::find(modify);
  start_phase();
}

int FixRuninWearJump::setmask()
{
  return END_OF_STEP;
}

void FixRuninWearJump::init()
{
  wear_state = FixRuninWearState::find(modify);
  if (!wear_state)
    error->all(FLERR, "fix runin/wear/jump: no per-atom wear state: define pair_style runin/asperity (with wear) "
               "before this fix");
  // defined before the pair created its wear state (e.g. after read_restart): the phase starts at this run
  if (!phase_started) start_phase();
}

// The phase starts from the current volumes (at creation, and after each jump).
void FixRuninWearJump::start_phase()
{
  phase_start_step = update->ntimestep;
  double **state = wear_state ? wear_state->state() : nullptr;
  for (int i = 0; i < atom->nlocal; i++) {
    phase_start[i][0] = state ? state[i][FixRuninWearState::VOLUME_LOST] : 0.0;
    phase_start[i][1] = state ? state[i][FixRuninWearState::VOLUME_GAINED] : 0.0;
  }
  phase_started = state != nullptr;
}

void FixRuninWearJump::end_of_step()
{
  const bigint steps = update->ntimestep - phase_start_step;
  if (steps <= 0) return;
  double **state = wear_state->state();
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  // the phase's mean worn depth of the group (its worn volume over the box's xy area) sets the jump
  double phase_volume = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      phase_volume += state[i][FixRuninWearState::VOLUME_LOST] - phase_start[i][0];
  double phase_volume_all = 0.0;
  MPI_Allreduce(&phase_volume, &phase_volume_all, 1, MPI_DOUBLE, MPI_SUM, world);
  const double phase_depth = phase_volume_all / (domain->xprd * domain->yprd);
  const double requested = factor - 1.0;
  const double extra = runin_lammps::kernel_call(lmp, FLERR, "fix runin/wear/jump", true, [&] {
    return runin::tribo::jump_extra(requested, phase_depth, max_depth);
  });
  if (extra < requested) {
    if (reduced_jumps < kReportedReductions && comm->me == 0)
      error->warning(FLERR, "fix runin/wear/jump: jump at step {} reduced from M = {} to {}: the phase wore {:.6g} "
                     "of mean depth, the jump is kept within max_depth = {:.6g}{}", update->ntimestep, factor,
                     1.0 + extra, phase_depth, max_depth,
                     reduced_jumps + 1 == kReportedReductions ? " (further reductions only counted: f_ID[3])" : "");
    reduced_jumps += 1.0;
  }
  double largest = 0.0;    // the largest change of a summit's height in this jump (vector entry 5)
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double before = state[i][FixRuninWearState::WEAR_DEPTH];
    state[i][FixRuninWearState::VOLUME_LOST] += extra * (state[i][FixRuninWearState::VOLUME_LOST] - phase_start[i][0]);
    state[i][FixRuninWearState::VOLUME_GAINED] += extra * (state[i][FixRuninWearState::VOLUME_GAINED] - phase_start[i][1]);
    wear_state->refresh_geometry(i);
    largest = std::max(largest, std::fabs(state[i][FixRuninWearState::WEAR_DEPTH] - before));
  }
  MPI_Allreduce(&largest, &largest_change, 1, MPI_DOUBLE, MPI_MAX, world);
  wear_state->forward_geometry();
  extra_steps += extra * static_cast<double>(steps);
  jumps += 1.0;
  last_factor = 1.0 + extra;
  start_phase();
}

// Sliding steps the jumps stand for beyond the steps run: the equivalent sliding distance is
// (steps run + f_ID) x dt x speed.
double FixRuninWearJump::compute_scalar()
{
  return extra_steps;
}

// 1: extra steps (the scalar), 2: jumps made, 3: jumps reduced by max_depth, 4: the last jump's factor, 5: the
// largest change of a summit's height in the last jump
double FixRuninWearJump::compute_vector(int n)
{
  switch (n) {
    case 0: return extra_steps;
    case 1: return jumps;
    case 2: return reduced_jumps;
    case 3: return last_factor;
    default: return largest_change;
  }
}

void FixRuninWearJump::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[6] = {static_cast<double>(phase_start_step), extra_steps, jumps, reduced_jumps, last_factor,
                          largest_change};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 6, fp);
}

void FixRuninWearJump::restart(char *buf)
{
  const auto *list = reinterpret_cast<const double *>(buf);
  phase_start_step = static_cast<bigint>(list[0]);
  extra_steps = list[1];
  jumps = list[2];
  reduced_jumps = list[3];
  last_factor = list[4];
  largest_change = list[5];
  phase_started = true;
}
