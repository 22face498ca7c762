#include "fix_runin_wear_jump.h"

#include "fix_runin_wear_state.h"
#include "runin_errors.h"
#include "tribo/asperity_geometry.h"
#include "tribo/cycle_jump.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr int kReportedReductions = 5;    // WARNINGs for reduced jumps before they are only counted
}

FixRuninWearJump::FixRuninWearJump(LAMMPS *lmp, int narg, char **arg) :
    RuninPeratomColumns(lmp, narg, arg, kColumns, "runin/wear/jump:phase_start"), factor(1.0), max_depth(0.0),
    max_change(0.0), rate_tolerance(0.0), depth_now(0.0), rate_previous(0.0),
    phase_start_step(0), extra_steps(0.0),
    jumps(0.0), reduced_jumps(0.0), last_factor(1.0), largest_change(0.0), wear_state(nullptr), phase_started(false)
{
  constexpr const char *usage =
      "expected 'fix ID group runin/wear/jump N M max_depth D [max_change Z] [rate v_name T]'";
  if (narg < 7 || strcmp(arg[5], "max_depth") != 0)
    error->all(FLERR, "fix runin/wear/jump: {}{}", usage,
               narg < 7 ? fmt::format(", got {} arguments", narg - 3) : fmt::format(", got keyword '{}'", arg[5]));
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
  for (int iarg = 7; iarg < narg;) {
    if (strcmp(arg[iarg], "max_change") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "fix runin/wear/jump: max_change needs a value (Z, a length > 0)");
      max_change = runin_lammps::finite_number(lmp, FLERR, where, "max_change", arg[iarg + 1]);
      if (!(max_change > 0.0))
        error->all(FLERR, "fix runin/wear/jump: max_change must be > 0 and finite, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "rate") == 0) {
      if (iarg + 3 > narg)
        error->all(FLERR, "fix runin/wear/jump: rate needs an equal-style variable v_name and a tolerance T > 0");
      if (strncmp(arg[iarg + 1], "v_", 2) != 0 || arg[iarg + 1][2] == '\0')
        error->all(FLERR, "fix runin/wear/jump: rate variable must be v_name (an equal-style variable), got {}",
                   arg[iarg + 1]);
      rate_variable = arg[iarg + 1] + 2;
      const int ivar = input->variable->find(rate_variable.c_str());
      if (ivar < 0 || !input->variable->equalstyle(ivar))
        error->all(FLERR, "fix runin/wear/jump: rate variable {} does not exist or is not equal-style (define it "
                   "before the fix)", arg[iarg + 1]);
      rate_tolerance = runin_lammps::finite_number(lmp, FLERR, where, "rate tolerance T", arg[iarg + 2]);
      if (!(rate_tolerance > 0.0) || !(rate_tolerance < 1.0))
        error->all(FLERR, "fix runin/wear/jump: rate tolerance T (relative change per cycle) must be in (0, 1), "
                   "got {}", arg[iarg + 2]);
      iarg += 3;
    } else {
      error->all(FLERR, "fix runin/wear/jump: {}, got keyword '{}'", usage, arg[iarg]);
    }
  }
  // with rate the jumps start small and grow while the state allows (an ODE stepper's start): the first phases
  // see the plastic shakedown of the loaded summits, before any measurement of it
  depth_now = rate_variable.empty() ? max_depth : 1e-3 * max_depth;

  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 6;
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
  if (!rate_variable.empty()) {
    rate_ivar = input->variable->find(rate_variable.c_str());
    if (rate_ivar < 0 || !input->variable->equalstyle(rate_ivar))
      error->all(FLERR, "fix runin/wear/jump: rate variable v_{} does not exist or is not equal-style",
                 rate_variable);
  }
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
  if (rate_ivar >= 0) {
    // the measured change of the state over the last cycle (the last jump and this phase) sets this jump
    modify->clearstep_compute();
    const double value = input->variable->compute_equal(rate_ivar);
    modify->addstep_compute(update->ntimestep + nevery);
    if (!std::isfinite(value))
      error->all(FLERR, "fix runin/wear/jump: rate variable v_{} is {} at step {}", rate_variable, value,
                 update->ntimestep);
    if (rate_previous != 0.0) {
      const double change = std::fabs(value - rate_previous) / std::fabs(rate_previous);
      depth_now = runin_lammps::kernel_call(lmp, FLERR, "fix runin/wear/jump", true, [&] {
        return runin::tribo::jump_depth_by_rate(depth_now, change, rate_tolerance, max_depth);
      });
    }
    rate_previous = value;
  }
  double extra = runin_lammps::kernel_call(lmp, FLERR, "fix runin/wear/jump", true, [&] {
    return runin::tribo::jump_extra(requested, phase_depth, depth_now);
  });
  // the state tolerance: no summit's height changes by more than max_change in one jump
  double unbounded_change = 0.0;
  const double by_depth = extra;
  if (max_change > 0.0 && extra > 0.0) {
    const double *radius = atom->radius;
    const auto change_at = [&](double e) {
      double local = 0.0;
      for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit) || !(radius[i] > 0.0)) continue;
        const double *si = state[i];
        const runin::tribo::WornAsperity worn = runin::tribo::worn_asperity(
            radius[i],
            si[FixRuninWearState::VOLUME_LOST] + e * (si[FixRuninWearState::VOLUME_LOST] - phase_start[i][0]) +
                si[FixRuninWearState::VOLUME_FLATTENED],
            si[FixRuninWearState::VOLUME_GAINED] + e * (si[FixRuninWearState::VOLUME_GAINED] - phase_start[i][1]),
            si[FixRuninWearState::WEAR_DEPTH]);
        local = std::max(local, std::fabs(worn.summit_drop - si[FixRuninWearState::WEAR_DEPTH]));
      }
      double all = 0.0;
      MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_MAX, world);
      return all;
    };
    unbounded_change = change_at(extra);
    extra = runin_lammps::kernel_call(lmp, FLERR, "fix runin/wear/jump", true, [&] {
      return runin::tribo::jump_extra_within_change(extra, max_change, change_at);
    });
  }
  if (extra < requested) {
    if (reduced_jumps < kReportedReductions && comm->me == 0) {
      const std::string why = extra < by_depth
          ? fmt::format("a summit's height would change by {:.6g}, the jump is kept within max_change = {:.6g}",
                        unbounded_change, max_change)
          : fmt::format("the phase wore {:.6g} of mean depth, the jump is kept within {} = {:.6g}", phase_depth,
                        rate_ivar >= 0 ? "the rate-controlled depth" : "max_depth", depth_now);
      error->warning(FLERR, "fix runin/wear/jump: jump at step {} reduced from M = {} to {}: {}{}", update->ntimestep,
                     factor, 1.0 + extra, why,
                     reduced_jumps + 1 == kReportedReductions ? " (further reductions only counted: f_ID[3])" : "");
    }
    reduced_jumps += 1.0;
  }
  // the controller grows from the jump made (reduced by max_change, or none after a phase without wear)
  if (rate_ivar >= 0) depth_now = std::max(extra * phase_depth, 1e-3 * max_depth);
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
// largest change of a summit's height in the last jump, 6: the mean depth a jump may add now (max_depth, or the rate
// controller's)
double FixRuninWearJump::compute_vector(int n)
{
  switch (n) {
    case 0: return extra_steps;
    case 1: return jumps;
    case 2: return reduced_jumps;
    case 3: return last_factor;
    case 4: return largest_change;
    default: return depth_now;
  }
}

void FixRuninWearJump::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  // list[0] < 0 marks this layout by its length; the first layout (6 values) began with the phase start step >= 0
  const double list[9] = {-9.0, static_cast<double>(phase_start_step), extra_steps, jumps, reduced_jumps, last_factor,
                          largest_change, depth_now, rate_previous};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 9, fp);
}

void FixRuninWearJump::restart(char *buf)
{
  auto *list = reinterpret_cast<const double *>(buf);
  const bool tagged = list[0] < 0.0;    // this layout (9 values); else the first (6 values, no rate state)
  if (tagged) ++list;
  phase_start_step = static_cast<bigint>(list[0]);
  extra_steps = list[1];
  jumps = list[2];
  reduced_jumps = list[3];
  last_factor = list[4];
  largest_change = list[5];
  if (tagged && !rate_variable.empty()) {    // the controller's state; without rate the depth is this definition's
    depth_now = list[6];
    rate_previous = list[7];
  }
  phase_started = true;
}
