// compute runin/friction and compute runin/roughness for LIGGGHTS 3.8 (liggghts_runin): the computes both hosts
// share (plugins/common/runin_friction_compute.h, runin_roughness_compute.h) on LIGGGHTS's Compute API and messages.
// The roughness has no keyword surface, no per-atom output and no rise here.
#ifndef LMP_COMPUTE_RUNIN_LIGGGHTS_H
#define LMP_COMPUTE_RUNIN_LIGGGHTS_H

#include "compute.h"
#include "runin_friction_compute.h"
#include "runin_roughness_compute.h"

namespace LAMMPS_NS {

class FixRuninWearStateLiggghts;

class ComputeRuninFrictionLiggghts : public runin_compute::FrictionCompute<Compute, FixRuninWearStateLiggghts> {
 public:
  ComputeRuninFrictionLiggghts(class LAMMPS *, int &, int, char **);
};

class ComputeRuninRoughnessLiggghts
    : public runin_roughness::RoughnessCompute<ComputeRuninRoughnessLiggghts, Compute, FixRuninWearStateLiggghts> {
 public:
  ComputeRuninRoughnessLiggghts(class LAMMPS *, int &, int, char **);

 private:
  friend class runin_roughness::RoughnessCompute<ComputeRuninRoughnessLiggghts, Compute, FixRuninWearStateLiggghts>;
  static constexpr const char *atom_style = "atom_style granular";
  void more_entries(double *) {}
  double summit(int i) const;
};

}    // namespace LAMMPS_NS

#endif
