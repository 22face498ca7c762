#include "fix_runin_wall.h"
#include "runin_citations.h"
#include "runin_lammps_compat.h"

#include "fix_runin_wear_state.h"
#include "runin_material_file.h"
#include "runin_timestep_guard.h"

#include "atom.h"
#include "error.h"
#include "modify.h"


using namespace LAMMPS_NS;

FixRuninWall::FixRuninWall(LAMMPS *lmp, int narg, char **arg) : WallFix(lmp, narg, arg)
{
  if (!runin_compat::sphere_atoms(atom)) error->all(FLERR, "fix runin/wall: requires atom_style sphere");
  runin_lammps::require_si_units(lmp, FLERR, "fix runin/wall");

  cfg = runin_wall::parse(narg, arg, coefficient_host(lmp, "fix runin/wall", "fix runin/wall: file", false));
  // here, before the first run's init prints LAMMPS's citation block
  runin_lammps::cite(lmp, runin_lammps::model_citations(cfg.choice, cfg.wear, true));
  start();
}

// Adding a fix from the constructor would corrupt the fix list; here it is safe.
void FixRuninWall::post_constructor()
{
  fix_wear = FixRuninWearState::find_or_create(modify);
}

void FixRuninWall::init()
{
  WallFix::init();
  guard_timestep();
}

// The timestep guard of pair runin/asperity (runin_timestep_guard.h), applied to the atom types of this
// fix's group against the wall's E* and G*. The wall's own non-finite check is in compute_contacts: the
// guard's finite-force fix runs before post_force, so it never sees the wall force.
void FixRuninWall::guard_timestep()
{
  runin_lammps::guard_timestep(lmp, "fix runin/wall",
                               runin_guard::wall_moduli(lmp, groupbit, cfg.model->effective_modulus(),
                                                        cfg.model->effective_shear_modulus()),
                               groupbit);
}

void FixRuninWall::post_run()
{
  report_past_centre();
  const std::string range_warning = contact_range.report(world, "fix runin/wall");
  if (!range_warning.empty()) error->warning(FLERR, range_warning);
}
