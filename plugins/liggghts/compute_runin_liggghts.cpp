#include "compute_runin_liggghts.h"

#include "fix_runin_wear_state_liggghts.h"
#include "runin_liggghts_errors.h"

#include "atom.h"

#include <string>

using namespace LAMMPS_NS;

ComputeRuninFrictionLiggghts::ComputeRuninFrictionLiggghts(LAMMPS *lmp, int &iarg_, int narg, char **arg) :
    FrictionCompute(lmp, iarg_, narg, arg)
{
  parse(narg, arg);
}

ComputeRuninRoughnessLiggghts::ComputeRuninRoughnessLiggghts(LAMMPS *lmp, int &iarg_, int narg, char **arg) :
    RoughnessCompute(lmp, iarg_, narg, arg)
{
  int iarg = 3;
  while (iarg < narg) {
    const int next = parse_keyword(narg, arg, iarg);
    if (!next)
      runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/roughness: unknown keyword '{}' (expected bearing, "
                                                  "side or mean)", arg[iarg]));
    iarg = next;
  }
  start_vector(0);
}

double ComputeRuninRoughnessLiggghts::summit(int i) const
{
  return sign * atom->x[i][2] + atom->radius[i] - wear_column(i, FixRuninWearStateLiggghts::WEAR_DEPTH);
}
