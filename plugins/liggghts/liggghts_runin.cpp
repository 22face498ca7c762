// liggghts_runin: Debian's LIGGGHTS 3.8 library (libliggghts3) with the RunIn styles registered in its style
// maps before input is read, as plugins/lammps/lmp_runin.cpp does for LAMMPS.
// Usage is that of liggghts: mpirun -np 2 liggghts_runin -in in.deck
#include "compute_runin_liggghts.h"
#include "fix_runin_wear_state_liggghts.h"
#include "pair_runin_asperity_liggghts.h"
#include "runin_liggghts_style_maps.h"

#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"

#include <mpi.h>

#include <cstdio>
#include <exception>

using namespace LAMMPS_NS;

namespace {
Pair *pair_creator(LAMMPS *lmp)
{
  return new PairRuninAsperityLiggghts(lmp);
}
Fix *wear_state_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixRuninWearStateLiggghts(lmp, narg, arg);
}
template <typename T> Compute *compute_creator(LAMMPS *lmp, int iarg, int narg, char **arg)
{
  return new T(lmp, iarg, narg, arg);
}

void register_styles(LAMMPS *lmp)
{
  (*lmp->force->pair_map)["runin/asperity"] = &pair_creator;
  runin_liggghts::fix_map(lmp->modify)["RUNIN/WEAR_STATE"] = &wear_state_creator;
  runin_liggghts::compute_map(lmp->modify)["runin/friction"] = &compute_creator<ComputeRuninFrictionLiggghts>;
  runin_liggghts::compute_map(lmp->modify)["runin/roughness"] = &compute_creator<ComputeRuninRoughnessLiggghts>;
}
}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  try {
    auto *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
    register_styles(lmp);
    lmp->input->file();
    delete lmp;
  } catch (const std::exception &e) {
    fprintf(stderr, "ERROR: liggghts_runin: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return 0;
}
