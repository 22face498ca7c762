// compute runin/friction: global contact sums of pair runin/asperity.
#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(runin/friction,ComputeRuninFriction);
// clang-format on
#else

#ifndef LMP_COMPUTE_RUNIN_FRICTION_H
#define LMP_COMPUTE_RUNIN_FRICTION_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeRuninFriction : public Compute {
 public:
  enum Entry { NORMAL_FORCE = 0, TANGENTIAL_FORCE, MU_EFF, CONTACTS, WEAR_VOLUME, NENTRIES };

  ComputeRuninFriction(class LAMMPS *, int, char **);
  ~ComputeRuninFriction() override;
  void init() override;
  void compute_vector() override;

 private:
  class PairRuninAsperity *pair;
};

}    // namespace LAMMPS_NS

#endif
#endif
