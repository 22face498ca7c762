#include "compute_runin_friction.h"

#include "fix_runin_wear_state.h"
#include "runin_contact_sums.h"

#include "error.h"
#include "fix.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

ComputeRuninFriction::ComputeRuninFriction(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), wear(nullptr), body_groupbit{0, 0}, bodies_given(false), second_body_is_wall(false),
    body(Body::none), body_bit(0), normal_axis(2), slide_axis(-1)
{
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "bodies") == 0) {
      if (iarg + 3 > narg) error->all(FLERR, "compute runin/friction: keyword bodies needs two group IDs");
      for (int b = 0; b < 2; b++) {
        if (b == 1 && strcmp(arg[iarg + 2], "wall") == 0) {
          second_body_is_wall = true;
          continue;
        }
        const int igroup = group->find(arg[iarg + 1 + b]);
        if (igroup < 0)
          error->all(FLERR, "compute runin/friction: bodies group {} does not exist", arg[iarg + 1 + b]);
        body_groupbit[b] = group->bitmask[igroup];
      }
      bodies_given = true;
      iarg += 3;
    } else if (strcmp(arg[iarg], "body") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "compute runin/friction: keyword body needs a group ID or 'wall'");
      if (strcmp(arg[iarg + 1], "wall") == 0) {
        body = Body::wall;
      } else {
        const int igroup = group->find(arg[iarg + 1]);
        if (igroup < 0) error->all(FLERR, "compute runin/friction: body group {} does not exist", arg[iarg + 1]);
        body = Body::group;
        body_bit = group->bitmask[igroup];
      }
      iarg += 2;
    } else if (strcmp(arg[iarg], "normal") == 0 || strcmp(arg[iarg], "slide") == 0) {
      const std::string keyword = arg[iarg];
      if (iarg + 2 > narg) error->all(FLERR, "compute runin/friction: keyword {} needs x, y or z", keyword);
      const std::string axis = arg[iarg + 1];
      if (axis != "x" && axis != "y" && axis != "z")
        error->all(FLERR, "compute runin/friction: {} must be x, y or z, got '{}'", keyword, axis);
      (keyword == "normal" ? normal_axis : slide_axis) = axis[0] - 'x';
      iarg += 2;
    } else {
      error->all(FLERR, "compute runin/friction: unknown keyword {} (expected bodies, body, normal or slide)",
                 arg[iarg]);
    }
  }
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
  sources.clear();
  wear = nullptr;
  if (auto *pair = dynamic_cast<RuninContactSource *>(force->pair)) sources.push_back(pair);
  bool have_wall = false;    // contact hosts among the fixes are the fix runin/wall instances
  for (int i = 0; i < modify->nfix; i++)
    if (auto *host = dynamic_cast<RuninContactSource *>(modify->fix[i])) {
      sources.push_back(host);
      have_wall = true;
    }
  if (sources.empty())
    error->all(FLERR, "compute runin/friction: requires pair_style runin/asperity or a fix runin/wall");
  wear = FixRuninWearState::find(modify);
  if (second_body_is_wall && !have_wall)
    error->all(FLERR, "compute runin/friction: bodies ... wall requires a fix runin/wall");
  if (slide_axis == normal_axis)
    error->all(FLERR, "compute runin/friction: slide and normal must be different axes");
  if (body == Body::wall && !have_wall)
    error->all(FLERR, "compute runin/friction: body wall requires a fix runin/wall");
  for (auto *source : sources) source->measure_body(body == Body::group ? body_bit : 0);
}

void ComputeRuninFriction::compute_vector()
{
  invoked_vector = update->ntimestep;

  constexpr int N = RuninContactSums::NVALUES;
  double local[N + 3] = {};
  for (const auto *source : sources) source->contact_sums().pack(local);
  if (wear) {
    local[N] = wear->local_sum(FixRuninWearState::VOLUME_LOST, groupbit);
    if (bodies_given) {
      local[N + 1] = wear->local_sum(FixRuninWearState::VOLUME_LOST, body_groupbit[0]);
      local[N + 2] = wear->local_sum(FixRuninWearState::VOLUME_LOST, body_groupbit[1]);
    }
  }
  double global[N + 3];
  MPI_Allreduce(local, global, N + 3, MPI_DOUBLE, MPI_SUM, world);

  RuninContactSums sum;
  sum.normal_force = global[0];
  const double ft = std::sqrt(global[1] * global[1] + global[2] * global[2] + global[3] * global[3]);
  sum.adhesion_force = global[4];
  sum.ploughing_force = global[5];
  sum.contacts = global[6];
  sum.sticking_contacts = global[7];
  sum.contact_area = global[8];
  sum.wear_volume = global[9];
  sum.frictional_power = global[10];

  const double fn = sum.normal_force;
  vector[NORMAL_FORCE] = fn;
  vector[TANGENTIAL_FORCE] = ft;
  vector[MU_EFF] = fn > 0.0 ? ft / fn : 0.0;
  vector[CONTACTS] = sum.contacts;
  vector[WEAR_VOLUME] = global[N];
  vector[MU_ADHESION] = fn > 0.0 ? sum.adhesion_force / fn : 0.0;
  vector[MU_PLOUGHING] = fn > 0.0 ? sum.ploughing_force / fn : 0.0;
  vector[STICK_FRACTION] = sum.contacts > 0.0 ? sum.sticking_contacts / sum.contacts : 0.0;
  vector[CONTACT_AREA] = sum.contact_area;
  vector[WEAR_VOLUME_BODY1] = global[N + 1];
  vector[WEAR_VOLUME_BODY2] = global[N + 2];
  if (second_body_is_wall) {
    vector[WEAR_VOLUME_BODY2] = 0.0;
    for (const auto *source : sources) vector[WEAR_VOLUME_BODY2] += source->counterface_wear_volume();
  }
  vector[WEAR_RATE] = update->dt > 0.0 ? sum.wear_volume / update->dt : 0.0;
  vector[FRICTIONAL_POWER] = sum.frictional_power;

  // the reaction the measured body feels, in the global frame: load along the normal axis, friction in the
  // plane normal to it (the sliding direction for a body driven in that plane)
  constexpr int BODY = 11, COUNTERFACE = 14;
  const double *reaction = body == Body::wall ? &global[COUNTERFACE] : &global[BODY];
  double in_plane = 0.0;
  for (int k = 0; k < 3; k++)
    if (k != normal_axis) in_plane += reaction[k] * reaction[k];
  const double friction = slide_axis >= 0 ? std::fabs(reaction[slide_axis]) : std::sqrt(in_plane);
  const double load = body == Body::none ? 0.0 : std::fabs(reaction[normal_axis]);
  vector[BODY_TANGENTIAL_FORCE] = body == Body::none ? 0.0 : friction;
  vector[BODY_NORMAL_FORCE] = load;
  vector[MU_BODY] = load > 0.0 ? vector[BODY_TANGENTIAL_FORCE] / load : 0.0;
  // the sums are reduced over all ranks: every rank sees the same entries
  for (int k = 0; k < size_vector; k++)
    if (!std::isfinite(vector[k]))
      error->all(FLERR, "compute runin/friction: entry {} is {} at step {}: the contact sums overflowed (a "
                 "coefficient far outside its physical range?)", k + 1, vector[k], update->ntimestep);
}
