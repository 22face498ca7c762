#include "compute_runin_friction.h"

#include "fix_runin_wear_state.h"
#include "pair_runin_asperity.h"

#include "error.h"
#include "force.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

ComputeRuninFriction::ComputeRuninFriction(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), pair(nullptr)
{
  if (narg != 3) error->all(FLERR, "compute runin/friction: expected no arguments after the style, got {}", narg - 3);
  vector_flag = 1;
  size_vector = NENTRIES;
  extvector = 0;
  vector = new double[NENTRIES];
}

ComputeRuninFriction::~ComputeRuninFriction()
{
  delete[] vector;
}

void ComputeRuninFriction::init()
{
  pair = dynamic_cast<PairRuninAsperity *>(force->pair_match("runin/asperity", 1));
  if (!pair) error->all(FLERR, "compute runin/friction: requires pair_style runin/asperity");
}

void ComputeRuninFriction::compute_vector()
{
  invoked_vector = update->ntimestep;

  const auto &sums = pair->contact_sums();
  const auto *wear = pair->wear_state();
  double local[6] = {sums.normal_force, sums.tangential_force[0], sums.tangential_force[1],
                     sums.tangential_force[2], sums.contacts,
                     wear ? wear->local_sum(FixRuninWearState::VOLUME_LOST, groupbit) : 0.0};
  double global[6];
  MPI_Allreduce(local, global, 6, MPI_DOUBLE, MPI_SUM, world);

  const double ft = std::sqrt(global[1] * global[1] + global[2] * global[2] + global[3] * global[3]);
  vector[NORMAL_FORCE] = global[0];
  vector[TANGENTIAL_FORCE] = ft;
  vector[MU_EFF] = global[0] > 0.0 ? ft / global[0] : 0.0;
  vector[CONTACTS] = global[4];
  vector[WEAR_VOLUME] = global[5];
}
