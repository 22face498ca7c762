// fix runin/wall: asperities (finite-size spheres) against a rigid flat counterface z = z_wall.
// Same kernels as pair runin/asperity (Hertz / worn flat + restitution damping, Mindlin spring with
// per-atom history, static/kinetic Coulomb limit or adhesion + ploughing strength, re-stick, Archard
// wear of both bodies with optional transfer). The plane slides in x-y and is either displacement
// controlled (fixed or moving z) or load controlled by a servo.
#ifdef FIX_CLASS
// clang-format off
FixStyle(runin/wall,FixRuninWall);
// clang-format on
#else

#ifndef LMP_FIX_RUNIN_WALL_H
#define LMP_FIX_RUNIN_WALL_H

#include "fix.h"
#include "runin_contact_range.h"
#include "runin_wall_fix.h"

namespace LAMMPS_NS {

class FixRuninWearState;

// The LAMMPS adaptor of the wall fix both hosts share (runin_wall_fix.h): atom style and units, the citations,
// the timestep guard, the contact-range WARNING.
class FixRuninWall : public runin_wall::WallFix<FixRuninWall, Fix, FixRuninWearState> {
 public:
  FixRuninWall(class LAMMPS *, int, char **);
  void post_constructor() override;
  void init() override;
  void post_run() override;

 private:
  friend class runin_wall::WallFix<FixRuninWall, Fix, FixRuninWearState>;
  void note_range(bigint step, const runin_wall::StepLocal<tagint> &local)
  {
    if (local.worst_atom > 0) contact_range.note(step, local.beyond_range, local.worst_range, local.worst_atom, 0);
  }

  runin_host::ContactRangeMonitor contact_range;    // contacts beyond their normal law's range (WARNING)
  void guard_timestep();
};

}    // namespace LAMMPS_NS

#endif
#endif
