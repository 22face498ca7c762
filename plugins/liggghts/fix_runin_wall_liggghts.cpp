#include "fix_runin_wall_liggghts.h"

#include "fix_runin_wear_state_liggghts.h"
#include "runin_liggghts_errors.h"
#include "runin_liggghts_material.h"
#include "timestep_guard.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"

using namespace LAMMPS_NS;

FixRuninWallLiggghts::FixRuninWallLiggghts(LAMMPS *lmp, int narg, char **arg) : WallFix(lmp, narg, arg)
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    runin_liggghts::all(lmp, FLERR, "fix runin/wall: requires atom attributes radius, rmass, omega and torque "
                                    "(atom_style granular or sphere)");
  runin_liggghts::require_si_units(lmp, FLERR, "fix runin/wall");
  cfg = runin_wall::parse(narg, arg, runin_liggghts::coefficient_host(lmp, "fix runin/wall", "fix runin/wall: file", false));
  start();
}

// Adding a fix from the constructor would corrupt the fix list; here it is safe.
void FixRuninWallLiggghts::post_create()
{
  fix_wear = FixRuninWearStateLiggghts::find_or_create(modify);
}

// the LAMMPS wall's timestep guard (plugins/common/timestep_guard.h), for the atom types of this fix's group
void FixRuninWallLiggghts::init()
{
  WallFix::init();
  runin_guard::guard_timestep(lmp, "fix runin/wall",
                              runin_guard::wall_moduli(lmp, groupbit, cfg.model->effective_modulus(),
                                                       cfg.model->effective_shear_modulus()),
                              groupbit);
}

void FixRuninWallLiggghts::post_run()
{
  report_past_centre();
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
