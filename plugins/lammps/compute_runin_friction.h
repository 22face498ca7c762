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
#include "runin_friction_compute.h"

namespace LAMMPS_NS {

class FixRuninWearState;

// The LAMMPS adaptor of the compute both hosts share (runin_friction_compute.h).
class ComputeRuninFriction : public runin_compute::FrictionCompute<Compute, FixRuninWearState> {
 public:
  ComputeRuninFriction(class LAMMPS *, int, char **);
};

}    // namespace LAMMPS_NS

#endif
#endif
