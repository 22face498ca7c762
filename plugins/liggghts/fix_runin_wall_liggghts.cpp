#include "fix_runin_wall_liggghts.h"

#include "fix_runin_wear_state_liggghts.h"
#include "runin_liggghts_errors.h"
#include "runin_liggghts_material.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace tribo = runin::tribo;

namespace {
constexpr int HISTORY_SIZE = runin_wall::HISTORY_SIZE;
}

FixRuninWallLiggghts::FixRuninWallLiggghts(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), body_groupbit(0), dt(0.0), smallest_radius(0.0), past_centre_count(0),
    beyond_range_count(0.0), worst_range(1.0), history(nullptr), fix_wear(nullptr)
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    runin_liggghts::all(lmp, FLERR, "fix runin/wall: requires atom attributes radius, rmass, omega and torque "
                                    "(atom_style granular or sphere)");
  runin_liggghts::require_si_units(lmp, FLERR, "fix runin/wall");
  cfg = runin_wall::parse(narg, arg, runin_liggghts::coefficient_host(lmp, "fix runin/wall", "fix runin/wall: file", false));
  motion.wall_z = cfg.wall_z;

  vector_flag = 1;
  size_vector = NOUTPUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  std::fill(totals, totals + NOUTPUT, 0.0);

  grow_arrays(atom->nmax);
  atom->add_callback(0);    // grow
  atom->add_callback(1);    // restart
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixRuninWallLiggghts::~FixRuninWallLiggghts()
{
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(history);
}

int FixRuninWallLiggghts::setmask()
{
  return POST_FORCE;
}

// Adding a fix from the constructor would corrupt the fix list; here it is safe.
void FixRuninWallLiggghts::post_create()
{
  fix_wear = FixRuninWearStateLiggghts::find_or_create(modify);
}

void FixRuninWallLiggghts::resolve(runin_wall::Setting &s, const char *keyword)
{
  if (s.variable.empty()) return;
  s.ivar = input->variable->find(&s.variable[0]);
  if (s.ivar < 0)
    runin_liggghts::all(lmp, FLERR, fmt::format("fix runin/wall: {} variable '{}' does not exist", keyword,
                                                s.variable));
  if (!input->variable->equalstyle(s.ivar))
    runin_liggghts::all(lmp, FLERR, fmt::format("fix runin/wall: {} variable '{}' must be equal-style", keyword,
                                                s.variable));
}

double FixRuninWallLiggghts::current(const runin_wall::Setting &s) const
{
  return s.ivar >= 0 ? input->variable->compute_equal(s.ivar) : s.value;
}

void FixRuninWallLiggghts::init()
{
  resolve(cfg.vel[0], "vel vx");
  resolve(cfg.vel[1], "vel vy");
  resolve(cfg.vz, "vz");
  dt = update->dt;
  fix_wear = FixRuninWearStateLiggghts::find(modify);
  if (!fix_wear) runin_liggghts::all(lmp, FLERR, "fix runin/wall: the per-atom wear state fix is missing");
  double local_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local_min = std::min(local_min, atom->radius[i]);
  MPI_Allreduce(&local_min, &smallest_radius, 1, MPI_DOUBLE, MPI_MIN, world);
}

void FixRuninWallLiggghts::post_run()
{
  if (past_centre_count > 0 && comm->me == 0)
    error->warning(FLERR, runin_wall::past_centre_summary(past_centre_count).c_str());
  past_centre_count = 0;
  double counts[2] = {beyond_range_count, worst_range}, global[2];
  MPI_Allreduce(&counts[0], &global[0], 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&counts[1], &global[1], 1, MPI_DOUBLE, MPI_MAX, world);
  if (global[0] > 0.0 && comm->me == 0)
    error->warning(FLERR, fmt::format("fix runin/wall: {:.0f} contact evaluations in this run were beyond the "
                                      "interference their normal law is checked to (worst {:.4g} times it)",
                                      global[0], global[1]).c_str());
  beyond_range_count = 0.0;
  worst_range = 1.0;
}

void FixRuninWallLiggghts::reset_dt()
{
  dt = update->dt;
}

void FixRuninWallLiggghts::setup(int)
{
  update_wall_velocity();
  if (cfg.control != runin_wall::Control::displacement) motion.velocity[2] = 0.0;
  compute_contacts(false);
}

void FixRuninWallLiggghts::post_force(int)
{
  update_wall_velocity();
  runin_liggghts::kernel_call(lmp, FLERR, "fix runin/wall", true, [&] {    // the servo: every rank alike
    runin_wall::move_wall(cfg, motion, dt, domain->xprd * domain->yprd);
  });
  compute_contacts(true);
}

void FixRuninWallLiggghts::update_wall_velocity()
{
  modify->clearstep_compute();
  motion.velocity[0] = current(cfg.vel[0]);
  motion.velocity[1] = current(cfg.vel[1]);
  motion.velocity[2] = cfg.control == runin_wall::Control::displacement ? current(cfg.vz) : 0.0;
  modify->addstep_compute(update->ntimestep + 1);
  const std::string problem = runin_wall::wall_step_problem(motion.velocity, dt, smallest_radius, update->ntimestep);
  if (!problem.empty()) runin_liggghts::all(lmp, FLERR, problem);
}

void FixRuninWallLiggghts::compute_contacts(bool advance)
{
  runin_liggghts::kernel_call(lmp, FLERR, "fix runin/wall", false, [&] {
    tribo::with_sub_models(cfg.choice, [&](auto normal, auto friction) {
      compute_contacts<decltype(normal)::value, decltype(friction)::value>(advance);
    });
  });
}

template <int NORMAL, int FRICTION> void FixRuninWallLiggghts::compute_contacts(bool advance)
{
  using namespace runin_wall;
  const Atoms<int> atoms{atom->x,      atom->v,     atom->f,    atom->omega, atom->torque,
                         atom->radius, atom->rmass, atom->mask, atom->tag,   atom->nlocal};
  StepLocal<int> step;
  runin_wall::contacts<NORMAL, FRICTION>(cfg, motion, atoms, history, fix_wear, groupbit, body_groupbit, dt, advance,
                                         sums, step);
  if (advance) {
    beyond_range_count += step.beyond_range;
    worst_range = std::max(worst_range, step.worst_range);
  }

  double global[NLOCAL];
  MPI_Allreduce(step.local, global, NLOCAL, MPI_DOUBLE, MPI_SUM, world);
  if (global[LOCAL_THROUGH] > 0.0) {
    int culprit = step.first_through;
    MPI_Allreduce(&step.first_through, &culprit, 1, MPI_INT, MPI_MIN, world);
    if (past_centre_count == 0 && comm->me == 0)
      error->warning(FLERR, past_centre_message(update->ntimestep, motion.wall_z, global[LOCAL_THROUGH], culprit)
                                .c_str());
    past_centre_count += static_cast<bigint>(global[LOCAL_THROUGH]);
  }
  if (!step_finite(global, motion)) {
    int culprit = step.first_bad;
    MPI_Allreduce(&step.first_bad, &culprit, 1, MPI_INT, MPI_MIN, world);
    runin_liggghts::all(lmp, FLERR, non_finite_message(update->ntimestep, culprit != std::numeric_limits<int>::max(),
                                                       culprit, motion, update->dt));
  }
  take_totals(global, motion, totals + FX, totals[CONTACTS]);
}

double FixRuninWallLiggghts::compute_vector(int n)
{
  switch (n) {
    case WALL_Z: return motion.wall_z;
    case WALL_DX: return motion.wall_dx;
    case WALL_DY: return motion.wall_dy;
    case WALL_WEAR: return motion.wall_wear;
    case WALL_GAIN: return motion.wall_gain;
    default: return totals[n];
  }
}

// The global record of the LAMMPS fix (runin_wall::restart_record), so either host reads the other's numbers.
void FixRuninWallLiggghts::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const std::vector<double> state = runin_wall::restart_record(cfg, motion);
  const int size = static_cast<int>(state.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(state.data(), sizeof(double), state.size(), fp);
}

void FixRuninWallLiggghts::restart(char *buf)
{
  runin_liggghts::kernel_call(lmp, FLERR, "fix runin/wall: restart file", true, [&] {
    const std::string problem = runin_wall::read_restart_record(buf, cfg, motion);
    if (!problem.empty()) runin_liggghts::all(lmp, FLERR, "fix runin/wall: restart file: " + problem);
  });
}

void FixRuninWallLiggghts::grow_arrays(int nmax)
{
  memory->grow(history, nmax, HISTORY_SIZE, "fix_runin_wall:history");
}

void FixRuninWallLiggghts::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < HISTORY_SIZE; k++) history[j][k] = history[i][k];
}

void FixRuninWallLiggghts::set_arrays(int i)
{
  for (int k = 0; k < HISTORY_SIZE; k++) history[i][k] = 0.0;
}

int FixRuninWallLiggghts::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < HISTORY_SIZE; k++) buf[k] = history[i][k];
  return HISTORY_SIZE;
}

int FixRuninWallLiggghts::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < HISTORY_SIZE; k++) history[nlocal][k] = buf[k];
  return HISTORY_SIZE;
}

int FixRuninWallLiggghts::pack_restart(int i, double *buf)
{
  buf[0] = HISTORY_SIZE + 1;    // LIGGGHTS skips per-fix blocks by this count
  for (int k = 0; k < HISTORY_SIZE; k++) buf[k + 1] = history[i][k];
  return HISTORY_SIZE + 1;
}

void FixRuninWallLiggghts::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < HISTORY_SIZE; k++) history[nlocal][k] = extra[nlocal][m++];
}

double FixRuninWallLiggghts::memory_usage()
{
  return static_cast<double>(atom->nmax) * HISTORY_SIZE * sizeof(double);
}
