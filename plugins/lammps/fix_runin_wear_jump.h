// Cycle jumping of asperity wear (doc/fix_runin_wear_jump.rst): every N steps, each summit's worn (and deposited)
// volume of the last N steps is added again (M - 1) times, so that each phase of physical sliding stands for M
// phases. For wear that is slow against the contact mechanics (mild Archard k): the plastic flattening and the
// contact statistics shake down within the phase, the worn geometry advances by the jump.
//
//   fix ID group runin/wear/jump N M max_depth D [max_change Z] [rate v_name T]
#ifdef FIX_CLASS
// clang-format off
FixStyle(runin/wear/jump,FixRuninWearJump);
// clang-format on
#else

#ifndef LMP_FIX_RUNIN_WEAR_JUMP_H
#define LMP_FIX_RUNIN_WEAR_JUMP_H

#include "runin_peratom_columns.h"

#include <string>

namespace LAMMPS_NS {

class FixRuninWearJump : public RuninPeratomColumns {
 public:
  FixRuninWearJump(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_vector(int) override;

  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  static constexpr int kColumns = 2;    // lost and gained volume at the start of the phase
  double factor;                        // M: each phase stands for M phases
  double max_depth;                     // largest mean worn depth of the group added by one jump
  double max_change;                    // > 0: largest change of one summit's height in one jump
  std::string rate_variable;            // rate: the state measure (an equal-style variable) ...
  int rate_ivar = -1;
  double rate_tolerance;                // ... and its tolerated relative change per cycle (phase and jump)
  double depth_now;                     // the mean depth this jump may add (max_depth, or the rate controller's)
  double rate_previous;                 // the measure at the last phase's end (0: none yet)
  double **&phase_start = columns;      // per atom: volumes at the start of the phase (the column store)
  bigint phase_start_step;
  double extra_steps;                   // sum over jumps of (M_applied - 1) x phase steps
  double jumps, reduced_jumps, last_factor, largest_change;
  class FixRuninWearState *wear_state;
  bool phase_started;    // the phase start holds the volumes of a wear state (or of a restart)

  void start_phase();
};

}    // namespace LAMMPS_NS

#endif
#endif
