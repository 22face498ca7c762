// fix runin/wall for LIGGGHTS 3.8 (liggghts_runin): asperities against a rigid flat counterface z = z_wall.
// The keywords, the wall motion and servo, the contact loop and the restart record are runin_wall (plugins/
// common/runin_wall_core.h), and the fix itself (the variables, the MPI reductions, the per-atom contact history,
// the global vector) is the class both hosts derive from (plugins/common/runin_wall_fix.h). This class is
// LIGGGHTS's adaptor: its atom style, messages and wear-state fix. What differs from the LAMMPS style:
// doc/liggghts.md.
#ifndef LMP_FIX_RUNIN_WALL_LIGGGHTS_H
#define LMP_FIX_RUNIN_WALL_LIGGGHTS_H

#include "fix.h"
#include "runin_wall_fix.h"

#include <algorithm>

namespace LAMMPS_NS {

class FixRuninWearStateLiggghts;

class FixRuninWallLiggghts : public runin_wall::WallFix<FixRuninWallLiggghts, Fix, FixRuninWearStateLiggghts> {
 public:
  FixRuninWallLiggghts(class LAMMPS *, int, char **);
  void post_create() override;
  void init() override;
  void post_run() override;

 private:
  friend class runin_wall::WallFix<FixRuninWallLiggghts, Fix, FixRuninWearStateLiggghts>;
  void note_range(long long, const runin_wall::StepLocal<int> &local)
  {
    beyond_range_count += local.beyond_range;
    worst_range = std::max(worst_range, local.worst_range);
  }

  double beyond_range_count = 0.0;    // contacts beyond their normal law's range in this run (WARNING at its end)
  double worst_range = 1.0;
};

}    // namespace LAMMPS_NS

#endif
