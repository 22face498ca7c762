#include "fix_runin_wall.h"
#include "runin_errors.h"
#include "runin_citations.h"
#include "runin_lammps_compat.h"

#include "fix_runin_wear_state.h"
#include "runin_material_file.h"
#include "runin_timestep_guard.h"
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"
#include "tribo/friction_strength.h"
#include "tribo/load_servo.h"
#include "tribo/wear.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "math_extra.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace tribo = runin::tribo;

FixRuninWall::FixRuninWall(LAMMPS *lmp, int narg, char **arg) :
    RuninPeratomColumns(lmp, narg, arg, HISTORY_SIZE, "fix_runin_wall:history"), body_groupbit(0), dt(0.0),
    fix_wear(nullptr)
{
  if (!runin_compat::sphere_atoms(atom)) error->all(FLERR, "fix runin/wall: requires atom_style sphere");
  runin_lammps::require_si_units(lmp, FLERR, "fix runin/wall");

  cfg = runin_wall::parse(narg, arg, coefficient_host(lmp, "fix runin/wall", "fix runin/wall: file", false));
  motion.wall_z = cfg.wall_z;
  // here, before the first run's init prints LAMMPS's citation block
  runin_lammps::cite(lmp, runin_lammps::model_citations(cfg.choice, cfg.wear, true));

  vector_flag = 1;
  size_vector = NOUTPUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  std::fill(totals, totals + NOUTPUT, 0.0);
  attach();
}

int FixRuninWall::setmask()
{
  return POST_FORCE;
}

// Adding a fix from the constructor would corrupt the fix list; here it is safe.
void FixRuninWall::post_constructor()
{
  fix_wear = FixRuninWearState::find_or_create(modify);
}

void FixRuninWall::resolve(runin_wall::Setting &s, const char *keyword)
{
  if (s.variable.empty()) return;
  s.ivar = input->variable->find(s.variable.c_str());
  if (s.ivar < 0) error->all(FLERR, "fix runin/wall: {} variable '{}' does not exist", keyword, s.variable);
  if (!input->variable->equalstyle(s.ivar))
    error->all(FLERR, "fix runin/wall: {} variable '{}' must be equal-style", keyword, s.variable);
}

double FixRuninWall::current(const runin_wall::Setting &s) const
{
  return s.ivar >= 0 ? input->variable->compute_equal(s.ivar) : s.value;
}

void FixRuninWall::init()
{
  resolve(cfg.vel[0], "vel vx");
  resolve(cfg.vel[1], "vel vy");
  resolve(cfg.vz, "vz");
  dt = update->dt;
  // the wear-state fix may have been redefined since this fix was created: look it up again
  fix_wear = FixRuninWearState::find(modify);
  if (!fix_wear) error->all(FLERR, "fix runin/wall: the per-atom wear state fix is missing");
  double local_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local_min = std::min(local_min, atom->radius[i]);
  MPI_Allreduce(&local_min, &smallest_radius, 1, MPI_DOUBLE, MPI_MIN, world);
  guard_timestep();
}

// The timestep guard of pair runin/asperity (runin_timestep_guard.h), applied to the atom types of this
// fix's group against the wall's E* and G*. The wall's own non-finite check is in compute_contacts: the
// guard's finite-force fix runs before post_force, so it never sees the wall force.
void FixRuninWall::guard_timestep()
{
  const int ntypes = atom->ntypes;
  std::vector<int> local(ntypes + 1, 0), in_group(ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local[atom->type[i]] = 1;
  MPI_Allreduce(local.data(), in_group.data(), ntypes + 1, MPI_INT, MPI_MAX, world);
  runin_lammps::guard_timestep(lmp, "fix runin/wall", [&](int i, int j) {
    return i == j && in_group[i]
               ? runin_lammps::PairModuli{cfg.model->effective_modulus(), cfg.model->effective_shear_modulus()}
               : runin_lammps::PairModuli{};
  }, groupbit);
}

void FixRuninWall::post_run()
{
  if (past_centre_count > 0 && comm->me == 0)
    error->warning(FLERR, runin_wall::past_centre_summary(past_centre_count));
  past_centre_count = 0;
  const std::string range_warning = contact_range.report(world, "fix runin/wall");
  if (!range_warning.empty()) error->warning(FLERR, range_warning);
}

void FixRuninWall::reset_dt()
{
  dt = update->dt;
}

void FixRuninWall::setup(int)
{
  update_wall_velocity();
  if (cfg.control != runin_wall::Control::displacement) motion.velocity[2] = 0.0;
  compute_contacts(false);
}

void FixRuninWall::post_force(int)
{
  update_wall_velocity();
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", true, [&] {    // the servo: every rank alike
    runin_wall::move_wall(cfg, motion, dt, domain->xprd * domain->yprd);
  });
  compute_contacts(true);
}

void FixRuninWall::update_wall_velocity()
{
  modify->clearstep_compute();
  motion.velocity[0] = current(cfg.vel[0]);
  motion.velocity[1] = current(cfg.vel[1]);
  motion.velocity[2] = cfg.control == runin_wall::Control::displacement ? current(cfg.vz) : 0.0;
  modify->addstep_compute(update->ntimestep + 1);
  check_wall_step();
}

// Every rank evaluates the same variables, so the checks are collective. A wall that moves further than a
// summit radius in one step skips whole contacts: the contact laws are not resolved in time.
void FixRuninWall::check_wall_step() const
{
  const std::string problem = runin_wall::wall_step_problem(motion.velocity, dt, smallest_radius, update->ntimestep);
  if (!problem.empty()) error->all(FLERR, problem);
}

void FixRuninWall::compute_contacts(bool advance)
{
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", false, [&] {
    tribo::with_sub_models(cfg.choice, [&](auto normal, auto friction) {
      compute_contacts<decltype(normal)::value, decltype(friction)::value>(advance);
    });
  });
}

// The contact loop is runin_wall::contacts (runin_wall_core.h, shared with the LIGGGHTS host); here the
// reduction over ranks and its checks.
template <int NORMAL, int FRICTION> void FixRuninWall::compute_contacts(bool advance)
{
  using namespace runin_wall;
  const runin_wall::Atoms<tagint> atoms{atom->x,      atom->v,     atom->f,    atom->omega, atom->torque,
                                        atom->radius, atom->rmass, atom->mask, atom->tag,   atom->nlocal};
  StepLocal<tagint> step;
  runin_wall::contacts<NORMAL, FRICTION>(cfg, motion, atoms, history, fix_wear, groupbit, body_groupbit, dt,
                                         advance, sums, step);
  if (advance && step.worst_atom > 0)
    contact_range.note(update->ntimestep, step.beyond_range, step.worst_range, step.worst_atom, 0);

  double global[NLOCAL];
  MPI_Allreduce(step.local, global, NLOCAL, MPI_DOUBLE, MPI_SUM, world);
  if (global[LOCAL_THROUGH] > 0.0) {
    // counted, not fatal: a first-loading sweep may press summits that far on purpose; the count is
    // reported at the end of the run (post_run)
    tagint culprit = step.first_through;
    MPI_Allreduce(&step.first_through, &culprit, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (past_centre_count == 0 && comm->me == 0)
      error->warning(FLERR, past_centre_message(update->ntimestep, motion.wall_z, global[LOCAL_THROUGH], culprit));
    past_centre_count += static_cast<bigint>(global[LOCAL_THROUGH]);
  }
  if (!step_finite(global, motion)) {
    tagint culprit = step.first_bad;
    MPI_Allreduce(&step.first_bad, &culprit, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    error->all(FLERR, non_finite_message(update->ntimestep, culprit != std::numeric_limits<tagint>::max(), culprit,
                                         motion, update->dt));
  }
  take_totals(global, motion, totals + FX, totals[CONTACTS]);
}

double FixRuninWall::compute_vector(int n)
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

// Global restart state: runin_wall::restart_record (the wall, the servo, the contact model record).
void FixRuninWall::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const std::vector<double> state = runin_wall::restart_record(cfg, motion);
  const int size = static_cast<int>(state.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(state.data(), sizeof(double), state.size(), fp);
}

void FixRuninWall::restart(char *buf)
{
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall: restart file", true, [&] {
    const std::string problem = runin_wall::read_restart_record(buf, cfg, motion);
    if (!problem.empty()) error->all(FLERR, "fix runin/wall: restart file: {}", problem);
  });
}
