// liggghts_runin: Debian's LIGGGHTS 3.8 library (libliggghts3) with the RunIn styles registered in its style
// maps before input is read, as plugins/lammps/lmp_runin.cpp does for LAMMPS.
// Usage is that of liggghts: mpirun -np 2 liggghts_runin -in in.deck
#include "compute_runin_liggghts.h"
#include "fix_runin_wall_liggghts.h"
#include "fix_runin_wear_state_liggghts.h"
#include "pair_runin_asperity_liggghts.h"
#include "runin_liggghts_style_maps.h"

#include "force.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"
#include "universe.h"

#include <mpi.h>

#include <cstdio>
#include <exception>
#include <string>

using namespace LAMMPS_NS;

namespace {
Pair *pair_creator(LAMMPS *lmp)
{
  return new PairRuninAsperityLiggghts(lmp);
}
Fix *wall_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixRuninWallLiggghts(lmp, narg, arg);
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
  runin_liggghts::fix_map(lmp->modify)["runin/wall"] = &wall_creator;
  runin_liggghts::compute_map(lmp->modify)["runin/friction"] = &compute_creator<ComputeRuninFrictionLiggghts>;
  runin_liggghts::compute_map(lmp->modify)["runin/roughness"] = &compute_creator<ComputeRuninRoughnessLiggghts>;
}
}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  try {
    auto *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
    // LIGGGHTS's Error::all follows the ERROR line of a PUBLIC build with a random second line of jokes and
    // tips, and its generator returns a pointer into a freed string (unreadable bytes): one ERROR line is
    // what RunIn promises. The generator only runs when the version string names PUBLIC.
    char *const original_version = lmp->universe->version;    // LIGGGHTS frees it with the instance
    static std::string version = original_version;
    for (std::size_t at; (at = version.find("PUBLIC")) != std::string::npos;) version.replace(at, 6, "public");
    lmp->universe->version = &version[0];
    register_styles(lmp);
    lmp->input->file();
    lmp->universe->version = original_version;
    delete lmp;
  } catch (const std::exception &e) {
    fprintf(stderr, "ERROR: liggghts_runin: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return 0;
}
