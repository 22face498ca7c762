// compute runin/friction on both hosts: its keywords, the contact hosts it reads (the pair and every fix runin/wall,
// RuninContactSource), the reduction over ranks and the arithmetic of the entries. `Compute` is the host's Compute
// class, messages go through the host's runin_host_api.h; the host's class only calls its Compute constructor
// through this one and then parse().
#pragma once

#include "runin_contact_sums.h"
#include "runin_host_api.h"

#include "compute.h"
#include "fix.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <fmt/format.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace runin_compute {

template <class Compute, class WearState> class FrictionCompute : public Compute {
 public:
  // Entries 1-5 are those of the first version, so older decks keep their column numbers.
  enum Entry {
    NORMAL_FORCE = 0,
    TANGENTIAL_FORCE,
    MU_EFF,
    CONTACTS,
    WEAR_VOLUME,
    MU_ADHESION,
    MU_PLOUGHING,
    STICK_FRACTION,
    CONTACT_AREA,
    WEAR_VOLUME_BODY1,
    WEAR_VOLUME_BODY2,
    WEAR_RATE,
    FRICTIONAL_POWER,
    BODY_TANGENTIAL_FORCE,    // reaction on the measured body (keyword body), global frame
    BODY_NORMAL_FORCE,
    MU_BODY,
    NENTRIES
  };

  ~FrictionCompute() override { delete[] this->vector; }

  void init() override
  {
    sources.clear();
    wear = nullptr;
    if (auto *pair = dynamic_cast<LAMMPS_NS::RuninContactSource *>(this->force->pair)) sources.push_back(pair);
    bool have_wall = false;    // contact hosts among the fixes are the fix runin/wall instances
    for (int i = 0; i < this->modify->nfix; i++)
      if (auto *host = dynamic_cast<LAMMPS_NS::RuninContactSource *>(this->modify->fix[i])) {
        sources.push_back(host);
        have_wall = true;
      }
    if (sources.empty()) fail("compute runin/friction: requires pair_style runin/asperity or a fix runin/wall");
    wear = WearState::find(this->modify);
    if (second_body_is_wall && !have_wall) fail("compute runin/friction: bodies ... wall requires a fix runin/wall");
    if (slide_axis == normal_axis) fail("compute runin/friction: slide and normal must be different axes");
    if (body == Body::wall && !have_wall) fail("compute runin/friction: body wall requires a fix runin/wall");
    for (auto *source : sources) source->measure_body(body == Body::group ? body_bit : 0);
  }

  void compute_vector() override
  {
    this->invoked_vector = this->update->ntimestep;
    double *vector = this->vector;

    constexpr int N = LAMMPS_NS::RuninContactSums::NVALUES;
    double local[N + 3] = {};
    for (const auto *source : sources) source->contact_sums().pack(local);
    if (wear) {
      local[N] = wear->local_sum(WearState::VOLUME_LOST, this->groupbit);
      if (bodies_given) {
        local[N + 1] = wear->local_sum(WearState::VOLUME_LOST, body_groupbit[0]);
        local[N + 2] = wear->local_sum(WearState::VOLUME_LOST, body_groupbit[1]);
      }
    }
    double global[N + 3];
    MPI_Allreduce(local, global, N + 3, MPI_DOUBLE, MPI_SUM, this->world);

    // global[]: RuninContactSums::pack order
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
    vector[WEAR_RATE] = this->update->dt > 0.0 ? global[9] / this->update->dt : 0.0;
    vector[FRICTIONAL_POWER] = global[10];

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
    for (int k = 0; k < this->size_vector; k++)
      if (!std::isfinite(vector[k]))
        fail(fmt::format("compute runin/friction: entry {} is {} at step {}: the contact sums overflowed (a "
                         "coefficient far outside its physical range?)",
                         k + 1, vector[k], this->update->ntimestep));
  }

 protected:
  template <class... Args> explicit FrictionCompute(Args &&...args) : Compute(std::forward<Args>(args)...) {}

  // The style arguments after `compute ID group runin/friction`, then the global vector.
  void parse(int narg, char **arg)
  {
    int iarg = 3;
    while (iarg < narg) {
      const std::string keyword = arg[iarg];
      if (keyword == "bodies") {
        if (iarg + 3 > narg) fail("compute runin/friction: keyword bodies needs two group IDs");
        for (int b = 0; b < 2; b++) {
          if (b == 1 && strcmp(arg[iarg + 2], "wall") == 0) {
            second_body_is_wall = true;
            continue;
          }
          body_groupbit[b] = group_bit("bodies", arg[iarg + 1 + b]);
        }
        bodies_given = true;
        iarg += 3;
      } else if (keyword == "body") {
        if (iarg + 2 > narg) fail("compute runin/friction: keyword body needs a group ID or 'wall'");
        if (strcmp(arg[iarg + 1], "wall") == 0) {
          body = Body::wall;
        } else {
          body = Body::group;
          body_bit = group_bit("body", arg[iarg + 1]);
        }
        iarg += 2;
      } else if (keyword == "normal" || keyword == "slide") {
        if (iarg + 2 > narg) fail(fmt::format("compute runin/friction: keyword {} needs x, y or z", keyword));
        const std::string axis = arg[iarg + 1];
        if (axis != "x" && axis != "y" && axis != "z")
          fail(fmt::format("compute runin/friction: {} must be x, y or z, got '{}'", keyword, axis));
        (keyword == "normal" ? normal_axis : slide_axis) = axis[0] - 'x';
        iarg += 2;
      } else {
        fail(fmt::format("compute runin/friction: unknown keyword {} (expected bodies, body, normal or slide)",
                         keyword));
      }
    }
    this->vector_flag = 1;
    this->size_vector = NENTRIES;
    this->extvector = 0;
    this->vector = new double[NENTRIES];
  }

 private:
  std::vector<LAMMPS_NS::RuninContactSource *> sources;
  WearState *wear = nullptr;
  int body_groupbit[2] = {0, 0};
  bool bodies_given = false;
  bool second_body_is_wall = false;    // 'bodies group-ID wall': the counterfaces of the fix runin/wall instances
  // 'body group-ID|wall': the body whose contact reaction gives mu_body; 'normal x|y|z': its load axis
  enum class Body { none, group, wall } body = Body::none;
  int body_bit = 0;
  int normal_axis = 2;
  int slide_axis = -1;    // 'slide x|y|z': friction along this axis; -1: the magnitude in the plane normal to the load

  [[noreturn]] void fail(const std::string &message) { runin_host::all(this->lmp, FLERR, message); }
  int group_bit(const char *keyword, const char *name)
  {
    const int igroup = this->group->find(name);
    if (igroup < 0) fail(fmt::format("compute runin/friction: {} group {} does not exist", keyword, name));
    return this->group->bitmask[igroup];
  }
};

}    // namespace runin_compute
