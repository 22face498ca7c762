#include "compute_runin_friction.h"

#include "fix_runin_wear_state.h"

using namespace LAMMPS_NS;

ComputeRuninFriction::ComputeRuninFriction(LAMMPS *lmp, int narg, char **arg) : FrictionCompute(lmp, narg, arg)
{
  parse(narg, arg);
}
