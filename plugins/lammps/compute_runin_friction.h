// compute runin/friction: global contact sums of every RunIn contact host
// (pair runin/asperity and any fix runin/wall), reduced over MPI ranks.
#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(runin/friction,ComputeRuninFriction);
// clang-format on
#else

#ifndef LMP_COMPUTE_RUNIN_FRICTION_H
#define LMP_COMPUTE_RUNIN_FRICTION_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeRuninFriction : public Compute {
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

  ComputeRuninFriction(class LAMMPS *, int, char **);
  ~ComputeRuninFriction() override;
  void init() override;
  void compute_vector() override;

 private:
  std::vector<class RuninContactSource *> sources;
  class FixRuninWearState *wear;
  int body_groupbit[2];
  bool bodies_given;
  bool second_body_is_wall;    // 'bodies group-ID wall': the counterfaces of the fix runin/wall instances
  // 'body group-ID|wall': the body whose contact reaction gives mu_body; 'normal x|y|z': its load axis
  enum class Body { none, group, wall } body;
  int body_bit;
  int normal_axis;
  int slide_axis;    // 'slide x|y|z': friction along this axis; -1: the magnitude in the plane normal to the load
};

}    // namespace LAMMPS_NS

#endif
#endif
