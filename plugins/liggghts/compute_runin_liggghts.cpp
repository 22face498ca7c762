#include "compute_runin_liggghts.h"
#include "../lammps/runin_roughness_core.h"

#include "runin_contact_sums.h"
#include "fix_runin_wear_state_liggghts.h"
#include "runin_liggghts_errors.h"
#include "tribo/surface_statistics.h"

#include "atom.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

ComputeRuninFrictionLiggghts::ComputeRuninFrictionLiggghts(LAMMPS *lmp, int &iarg_, int narg, char **arg) :
    Compute(lmp, iarg_, narg, arg), wear(nullptr), body_groupbit{0, 0}, bodies_given(false), second_body_is_wall(false),
    body_is_wall(false), has_body(false),
    body_bit(0), normal_axis(2), slide_axis(-1)
{
  int iarg = 3;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    if (keyword == "bodies") {
      if (iarg + 3 > narg)
        runin_liggghts::all(lmp, FLERR, "compute runin/friction: keyword bodies needs two group IDs");
      for (int b = 0; b < 2; b++) {
        if (b == 1 && strcmp(arg[iarg + 2], "wall") == 0) {
          second_body_is_wall = true;
          continue;
        }
        const int igroup = group->find(arg[iarg + 1 + b]);
        if (igroup < 0)
          runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/friction: bodies group {} does not exist",
                                                      arg[iarg + 1 + b]));
        body_groupbit[b] = group->bitmask[igroup];
      }
      bodies_given = true;
      iarg += 3;
    } else if (keyword == "body") {
      if (iarg + 2 > narg)
        runin_liggghts::all(lmp, FLERR, "compute runin/friction: keyword body needs a group ID");
      has_body = true;
      if (strcmp(arg[iarg + 1], "wall") == 0) {
        body_is_wall = true;
      } else {
        const int igroup = group->find(arg[iarg + 1]);
        if (igroup < 0)
          runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/friction: body group {} does not exist",
                                                      arg[iarg + 1]));
        body_bit = group->bitmask[igroup];
      }
      iarg += 2;
    } else if (keyword == "normal" || keyword == "slide") {
      if (iarg + 2 > narg)
        runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/friction: keyword {} needs x, y or z", keyword));
      const std::string axis = arg[iarg + 1];
      if (axis != "x" && axis != "y" && axis != "z")
        runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/friction: {} must be x, y or z, got '{}'",
                                                    keyword, axis));
      (keyword == "normal" ? normal_axis : slide_axis) = axis[0] - 'x';
      iarg += 2;
    } else {
      runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/friction: unknown keyword {} (expected bodies, "
                                                  "body, normal or slide)", keyword));
    }
  }
  vector_flag = 1;
  size_vector = NENTRIES;
  extvector = 0;
  vector = new double[NENTRIES];
}

ComputeRuninFrictionLiggghts::~ComputeRuninFrictionLiggghts()
{
  delete[] vector;
}

void ComputeRuninFrictionLiggghts::init()
{
  sources.clear();
  if (auto *pair = dynamic_cast<RuninContactSource *>(force->pair)) sources.push_back(pair);
  bool have_wall = false;    // contact hosts among the fixes are the fix runin/wall instances
  for (int i = 0; i < modify->nfix; i++)
    if (auto *host = dynamic_cast<RuninContactSource *>(modify->fix[i])) {
      sources.push_back(host);
      have_wall = true;
    }
  if (sources.empty())
    runin_liggghts::all(lmp, FLERR, "compute runin/friction: requires pair_style runin/asperity or a fix runin/wall");
  wear = FixRuninWearStateLiggghts::find(modify);
  if (second_body_is_wall && !have_wall)
    runin_liggghts::all(lmp, FLERR, "compute runin/friction: bodies ... wall requires a fix runin/wall");
  if (slide_axis == normal_axis)
    runin_liggghts::all(lmp, FLERR, "compute runin/friction: slide and normal must be different axes");
  if (body_is_wall && !have_wall)
    runin_liggghts::all(lmp, FLERR, "compute runin/friction: body wall requires a fix runin/wall");
  for (auto *source : sources) source->measure_body(has_body && !body_is_wall ? body_bit : 0);
}

// The arithmetic of ComputeRuninFriction::compute_vector (plugins/lammps), entry for entry.
void ComputeRuninFrictionLiggghts::compute_vector()
{
  invoked_vector = update->ntimestep;
  using W = FixRuninWearStateLiggghts;
  constexpr int N = RuninContactSums::NVALUES;
  double local[N + 3] = {};
  for (const auto *source : sources) source->contact_sums().pack(local);
  if (wear) {
    local[N] = wear->local_sum(W::VOLUME_LOST, groupbit);
    if (bodies_given) {
      local[N + 1] = wear->local_sum(W::VOLUME_LOST, body_groupbit[0]);
      local[N + 2] = wear->local_sum(W::VOLUME_LOST, body_groupbit[1]);
    }
  }
  double global[N + 3];
  MPI_Allreduce(local, global, N + 3, MPI_DOUBLE, MPI_SUM, world);

  const double fn = global[0];
  const double ft = std::sqrt(global[1] * global[1] + global[2] * global[2] + global[3] * global[3]);
  const double contacts = global[6];
  vector[NORMAL_FORCE] = fn;
  vector[TANGENTIAL_FORCE] = ft;
  vector[MU_EFF] = fn > 0.0 ? ft / fn : 0.0;
  vector[CONTACTS] = contacts;
  vector[WEAR_VOLUME] = global[N];
  vector[MU_ADHESION] = fn > 0.0 ? global[4] / fn : 0.0;
  vector[MU_PLOUGHING] = fn > 0.0 ? global[5] / fn : 0.0;
  vector[STICK_FRACTION] = contacts > 0.0 ? global[7] / contacts : 0.0;
  vector[CONTACT_AREA] = global[8];
  vector[WEAR_VOLUME_BODY1] = global[N + 1];
  vector[WEAR_VOLUME_BODY2] = global[N + 2];
  if (second_body_is_wall) {
    vector[WEAR_VOLUME_BODY2] = 0.0;
    for (const auto *source : sources) vector[WEAR_VOLUME_BODY2] += source->counterface_wear_volume();
  }
  vector[WEAR_RATE] = update->dt > 0.0 ? global[9] / update->dt : 0.0;
  vector[FRICTIONAL_POWER] = global[10];

  constexpr int BODY = 11, COUNTERFACE = 14;
  const double *reaction = body_is_wall ? &global[COUNTERFACE] : &global[BODY];
  double in_plane = 0.0;
  for (int k = 0; k < 3; k++)
    if (k != normal_axis) in_plane += reaction[k] * reaction[k];
  const double friction = slide_axis >= 0 ? std::fabs(reaction[slide_axis]) : std::sqrt(in_plane);
  const double load = has_body ? std::fabs(reaction[normal_axis]) : 0.0;
  vector[BODY_TANGENTIAL_FORCE] = has_body ? friction : 0.0;
  vector[BODY_NORMAL_FORCE] = load;
  vector[MU_BODY] = load > 0.0 ? vector[BODY_TANGENTIAL_FORCE] / load : 0.0;
  for (int k = 0; k < size_vector; k++)
    if (!std::isfinite(vector[k]))
      runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/friction: entry {} is {} at step {}: the contact "
                                                  "sums overflowed (a coefficient far outside its physical range?)",
                                                  k + 1, vector[k], update->ntimestep));
}

ComputeRuninRoughnessLiggghts::ComputeRuninRoughnessLiggghts(LAMMPS *lmp, int &iarg_, int narg, char **arg) :
    Compute(lmp, iarg_, narg, arg), sign(1.0), fix_wear(nullptr)
{
  int iarg = 3;
  bool seen_bearing = false;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    if (keyword == "bearing") {
      if (seen_bearing) runin_liggghts::all(lmp, FLERR, "compute runin/roughness: keyword 'bearing' given twice");
      seen_bearing = true;
      ++iarg;
      while (iarg < narg && runin_liggghts::is_double(arg[iarg])) {
        const double depth =
            runin_liggghts::finite_number(lmp, FLERR, "compute runin/roughness", "bearing depth", arg[iarg]);
        if (!(depth >= 0.0))
          runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/roughness: bearing depth must be >= 0, got {}",
                                                      arg[iarg]));
        depths.push_back(depth);
        ++iarg;
      }
      if (depths.empty())
        runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/roughness: keyword 'bearing' needs at least one "
                                                    "depth, got {}", iarg < narg ? std::string("'") + arg[iarg] + "'"
                                                                                 : std::string("none")));
    } else if (keyword == "side") {
      if (iarg + 1 >= narg) runin_liggghts::all(lmp, FLERR, "compute runin/roughness: keyword 'side' needs a value");
      const std::string value = arg[iarg + 1];
      if (value == "up")
        sign = 1.0;
      else if (value == "down")
        sign = -1.0;
      else
        runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/roughness: side must be 'up' or 'down', got "
                                                    "'{}'", value));
      iarg += 2;
    } else if (keyword == "mean") {
      if (iarg + 1 >= narg || strcmp(arg[iarg + 1], "z") != 0)
        runin_liggghts::all(lmp, FLERR, "compute runin/roughness: mean must be 'z'");
      iarg += 2;
    } else {
      runin_liggghts::all(lmp, FLERR, fmt::format("compute runin/roughness: unknown keyword '{}' (expected bearing, "
                                                  "side or mean)", keyword));
    }
  }
  vector_flag = 1;
  size_vector = runin_roughness::NFIXED + static_cast<int>(depths.size());
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;
}

ComputeRuninRoughnessLiggghts::~ComputeRuninRoughnessLiggghts()
{
  delete[] vector;
}

void ComputeRuninRoughnessLiggghts::init()
{
  if (!atom->radius_flag)
    runin_liggghts::all(lmp, FLERR, "compute runin/roughness: requires atom attribute radius (atom_style granular)");
  fix_wear = FixRuninWearStateLiggghts::find(modify);
}

double ComputeRuninRoughnessLiggghts::summit(int i) const
{
  const double depth = fix_wear ? fix_wear->state()[i][FixRuninWearStateLiggghts::WEAR_DEPTH] : 0.0;
  return sign * atom->x[i][2] + atom->radius[i] - depth;
}

void ComputeRuninRoughnessLiggghts::compute_vector()
{
  invoked_vector = update->ntimestep;
  const int *mask = atom->mask;
  runin_liggghts::kernel_call(lmp, FLERR, "compute runin/roughness", true, [&] {
    runin_roughness::compute_vector(
        world, atom->nlocal, [&](int i) { return (mask[i] & groupbit) != 0; }, [&](int i) { return summit(i); },
        depths, vector);
  });
}
