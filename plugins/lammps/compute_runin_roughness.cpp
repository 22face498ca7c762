#include "compute_runin_roughness.h"
#include "runin_roughness_core.h"
#include "runin_errors.h"

#include "fix_runin_wear_state.h"
#include "tribo/surface_statistics.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include <cstring>
#include <exception>
#include <string>

using namespace LAMMPS_NS;

ComputeRuninRoughness::ComputeRuninRoughness(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), sign(1.0), nmax(0), peratom(nullptr), fix_wear(nullptr)
{
  int iarg = 3;
  bool seen_bearing = false;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    if (keyword == "bearing") {
      if (seen_bearing) error->all(FLERR, "compute runin/roughness: keyword 'bearing' given twice");
      seen_bearing = true;
      ++iarg;
      while (iarg < narg && utils::is_double(arg[iarg])) {
        const double depth =
            runin_lammps::finite_number(lmp, FLERR, "compute runin/roughness", "bearing depth", arg[iarg]);
        if (!(depth >= 0.0))
          error->all(FLERR, "compute runin/roughness: bearing depth must be >= 0, got {}", arg[iarg]);
        depths.push_back(depth);
        ++iarg;
      }
      if (depths.empty())
        error->all(FLERR, "compute runin/roughness: keyword 'bearing' needs at least one depth, got {}",
                   iarg < narg ? std::string("'") + arg[iarg] + "'" : std::string("none"));
    } else if (keyword == "side") {
      if (iarg + 1 >= narg) error->all(FLERR, "compute runin/roughness: keyword 'side' needs a value");
      const std::string value = arg[iarg + 1];
      if (value == "up")
        sign = 1.0;
      else if (value == "down")
        sign = -1.0;
      else
        error->all(FLERR, "compute runin/roughness: side must be 'up' or 'down', got '{}'", value);
      iarg += 2;
    } else if (keyword == "mean") {
      if (iarg + 1 >= narg) error->all(FLERR, "compute runin/roughness: keyword 'mean' needs a value");
      const std::string value = arg[iarg + 1];
      if (value != "z")
        error->all(FLERR, "compute runin/roughness: mean must be 'z' (a tilted least-squares plane is not "
                          "implemented), got '{}'", value);
      iarg += 2;
    } else {
      error->all(FLERR, "compute runin/roughness: unknown keyword '{}' (expected bearing, side or mean)", keyword);
    }
  }

  vector_flag = 1;
  size_vector = runin_roughness::NFIXED + static_cast<int>(depths.size());
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;

  peratom_flag = 1;
  size_peratom_cols = NPERATOM;
}

ComputeRuninRoughness::~ComputeRuninRoughness()
{
  delete[] vector;
  memory->destroy(peratom);
}

void ComputeRuninRoughness::init()
{
  if (!atom->radius_flag)
    error->all(FLERR, "compute runin/roughness: requires atom attribute radius (atom_style sphere)");
  // the wear state is created by pair runin/asperity or fix runin/wall, possibly after this compute
  fix_wear = FixRuninWearState::find(modify);
}

double ComputeRuninRoughness::wear_depth(int i) const
{
  return fix_wear ? fix_wear->state()[i][FixRuninWearState::WEAR_DEPTH] : 0.0;
}

double ComputeRuninRoughness::summit(int i) const
{
  // side up: top of the sphere; side down: bottom of the sphere, measured downward. A worn summit is
  // truncated by its wear depth h (negative where transfer deposited more than was lost).
  return sign * atom->x[i][2] + atom->radius[i] - wear_depth(i);
}

double ComputeRuninRoughness::mean_height()
{
  const int *mask = atom->mask;
  double local[2] = {0.0, 0.0}, global[2];
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      local[0] += 1.0;
      local[1] += summit(i);
    }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, world);
  return global[0] > 0.0 ? global[1] / global[0] : 0.0;
}

void ComputeRuninRoughness::compute_vector()
{
  invoked_vector = update->ntimestep;
  const int *mask = atom->mask;
  runin_lammps::kernel_call(lmp, FLERR, "compute runin/roughness", true, [&] {
    runin_roughness::compute_vector(
        world, atom->nlocal, [&](int i) { return (mask[i] & groupbit) != 0; }, [&](int i) { return summit(i); },
        depths, vector);
  });
}

void ComputeRuninRoughness::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(peratom);
    nmax = atom->nmax;
    memory->create(peratom, nmax, NPERATOM, "runin/roughness:peratom");
    array_atom = peratom;
  }
  const double mean = mean_height();
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    const bool member = mask[i] & groupbit;
    peratom[i][HEIGHT] = member ? summit(i) - mean : 0.0;
    peratom[i][WEAR_DEPTH] = member ? wear_depth(i) : 0.0;
  }
}

double ComputeRuninRoughness::memory_usage()
{
  return static_cast<double>(nmax) * NPERATOM * sizeof(double);
}
