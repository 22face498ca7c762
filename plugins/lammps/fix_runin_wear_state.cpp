#include "fix_runin_wear_state.h"

#include "runin_lammps_compat.h"
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "input.h"
#include "modify.h"
#include "variable.h"

#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

namespace {
// WEAR_DEPTH, FLAT_RADIUS, VOLUME_FLATTENED and RISE: all the force needs from a ghost (the third for a reload
// of flattened summits, the fourth for a raised free surface, each only when a pair asks for it)
constexpr int kGeometryColumns = 4;
// restart records written before RISE held the columns up to VOLUME_FLATTENED
constexpr int kColumnsBeforeRise = 5;
}

FixRuninWearState::FixRuninWearState(LAMMPS *lmp, int narg, char **arg) :
    RuninPeratomColumns(lmp, narg, arg, NCOLUMNS, "runin/wear_state:values")
{
  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  peratom_freq = 1;
  comm_forward = kGeometryColumns;
  fewest_restart_columns = kColumnsBeforeRise;
  choose_forwarded();

  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) error->all(FLERR, "fix RUNIN/WEAR_STATE: keyword '{}' needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "lost") == 0)
      assign_from_variable(VOLUME_LOST, arg[iarg + 1]);
    else if (strcmp(arg[iarg], "gained") == 0)
      assign_from_variable(VOLUME_GAINED, arg[iarg + 1]);
    else
      error->all(FLERR, "fix RUNIN/WEAR_STATE: unknown keyword '{}' (expected lost or gained)", arg[iarg]);
  }
  if (narg > 3) refresh_geometry_all();
  attach();
}

FixRuninWearState *FixRuninWearState::find(Modify *modify)
{
  return dynamic_cast<FixRuninWearState *>(runin_compat::fix_by_id(modify, default_id));
}

FixRuninWearState *FixRuninWearState::find_or_create(Modify *modify)
{
  if (FixRuninWearState *existing = find(modify)) return existing;
  return dynamic_cast<FixRuninWearState *>(modify->add_fix(fmt::format("{} all RUNIN/WEAR_STATE", default_id)));
}

// Initial volumes from an atom-style variable, evaluated once here (atoms outside the group keep 0).
void FixRuninWearState::assign_from_variable(Column column, const char *reference)
{
  const char *keyword = column == VOLUME_LOST ? "lost" : "gained";
  if (strncmp(reference, "v_", 2) != 0)
    error->all(FLERR, "fix RUNIN/WEAR_STATE: {} must be an atom-style variable v_name, got '{}'", keyword,
               reference);
  const int ivar = input->variable->find(reference + 2);
  if (ivar < 0 || !input->variable->atomstyle(ivar))
    error->all(FLERR, "fix RUNIN/WEAR_STATE: {} needs an atom-style variable, got '{}'", keyword, reference);
  std::vector<double> result(atom->nlocal + 1, 0.0);
  input->variable->compute_atom(ivar, igroup, result.data(), 1, 0);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(result[i] >= 0.0))
      error->one(FLERR, "fix RUNIN/WEAR_STATE: {} volume must be >= 0, got {} for atom {}", keyword, result[i],
                 atom->tag[i]);
    columns[i][column] = result[i];
  }
}

// Per step the volumes change by parts per million: the cap height is found by Newton from the current
// one (the same root to round-off as the closed form, which is the fallback).
void FixRuninWearState::refresh_geometry(int i)
{
  refresh_geometry(i, atom->radius ? atom->radius[i] : 0.0);
}

// Radii or volumes may have been set since the last step; a height that is still the root is kept as it is
// (a restart reproduces the state bit for bit), any other is found again (or from the closed form).
void FixRuninWearState::refresh_geometry_all()
{
  for (int i = 0; i < atom->nlocal; i++) refresh_geometry(i);
}

void FixRuninWearState::forward_geometry()
{
  runin_compat::forward_comm(comm, this);
}

// The geometry columns, in the order the ghosts receive them.
void FixRuninWearState::choose_forwarded()
{
  forwarded = {WEAR_DEPTH, FLAT_RADIUS};
  if (send_flattened) forwarded.push_back(VOLUME_FLATTENED);
  if (send_rise) forwarded.push_back(RISE);
}
