// compute runin/friction and compute runin/roughness for LIGGGHTS 3.8 (liggghts_runin): the entries, the
// reductions and the arithmetic of plugins/lammps/compute_runin_friction.* and compute_runin_roughness.*
// (the roughness statistics are src/tribo/surface_statistics); only LIGGGHTS's Compute API differs.
#ifndef LMP_COMPUTE_RUNIN_LIGGGHTS_H
#define LMP_COMPUTE_RUNIN_LIGGGHTS_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeRuninFrictionLiggghts : public Compute {
 public:
  enum Entry {
    NORMAL_FORCE = 0, TANGENTIAL_FORCE, MU_EFF, CONTACTS, WEAR_VOLUME, MU_ADHESION, MU_PLOUGHING, STICK_FRACTION,
    CONTACT_AREA, WEAR_VOLUME_BODY1, WEAR_VOLUME_BODY2, WEAR_RATE, FRICTIONAL_POWER, BODY_TANGENTIAL_FORCE,
    BODY_NORMAL_FORCE, MU_BODY, NENTRIES
  };
  ComputeRuninFrictionLiggghts(class LAMMPS *, int &, int, char **);
  ~ComputeRuninFrictionLiggghts();
  void init() override;
  void compute_vector() override;

 private:
  std::vector<class RuninContactSource *> sources;
  class FixRuninWearStateLiggghts *wear;
  int body_groupbit[2];
  bool bodies_given;
  bool second_body_is_wall;    // bodies ... wall: the second body's wear is the counterface's
  bool body_is_wall;           // body wall: the reaction on the counterface of fix runin/wall
  bool has_body;
  int body_bit;
  int normal_axis;
  int slide_axis;
};

class ComputeRuninRoughnessLiggghts : public Compute {
 public:
  ComputeRuninRoughnessLiggghts(class LAMMPS *, int &, int, char **);
  ~ComputeRuninRoughnessLiggghts();
  void init() override;
  void compute_vector() override;

 private:
  double sign;
  std::vector<double> depths;
  class FixRuninWearStateLiggghts *fix_wear;
  double summit(int i) const;
};

}    // namespace LAMMPS_NS

#endif
