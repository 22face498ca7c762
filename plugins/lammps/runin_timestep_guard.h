// Stability guard for RunIn pair styles: a timestep check at init and a non-finite-force check
// every step. The limits come from runin::tribo (src/tribo/stability.h).
// The per-step check costs a pass over the forces of all owned and ghost atoms (and an MPI_Allreduce
// on more than one rank). A pair style that tests each contact force in its own loop (nearly free: one
// sum) implements runin_lammps::FiniteForcePair, and the fix then skips its pass whenever that pair is the
// only source of forces before reverse communication (no hybrid, bonds or kspace).
#ifdef FIX_CLASS
// clang-format off
FixStyle(RUNIN/FINITE_CHECK,FixRuninFiniteCheck);
// clang-format on
#else

#ifndef LMP_RUNIN_TIMESTEP_GUARD_H
#define LMP_RUNIN_TIMESTEP_GUARD_H

#include "fix.h"
#include "runin_contact_range.h"
#include "timestep_guard.h"

#include <functional>
#include <string>
#include <type_traits>

namespace LAMMPS_NS {

// Internal fix: after the pair forces (before reverse communication, so the culprit pair is still
// visible) stops the run with one ERROR line naming the step and atom IDs if any force is not finite.
class FixRuninFiniteCheck : public Fix {
 public:
  static constexpr const char *default_id = "RUNIN_FINITE_CHECK";
  FixRuninFiniteCheck(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_reverse(int, int) override;
  void pre_reverse(int, int) override;
  void post_run() override;
  std::string style_label = "pair runin/asperity";

 private:
  bool pair_checks_itself = false;    // set at init: the pair's own per-contact test covers every force
  void check();
};

}    // namespace LAMMPS_NS

namespace runin_lammps {

using PairModuli = runin_guard::PairModuli;

// The shared guard (plugins/common/timestep_guard.h): compares update->dt with the smallest Rayleigh time of the
// asperities in contact-capable type pairs (radius and density per atom from radius/rmass, G and nu from the pair's
// E* and G*): WARNING above TimeStepPolicy::warn_fraction t_R, ERROR above fail_factor t_R. Installs the finite-force
// check.
// Returns the smallest Rayleigh time (0 if there are no atoms). Also an ERROR (naming the atom) when an atom of
// `groupbit` would move more than its radius in one step at its current velocity (e.g. 'velocity ... 1e308'):
// contacts are not resolved in time, and it would fly off before any contact check sees it.
double guard_timestep(LAMMPS_NS::LAMMPS *lmp, const char *style,
                      const std::function<PairModuli(int, int)> &moduli_of, int groupbit = 1);

// Implemented by a pair style whose force loop tests every force it adds (e.g. isfinite of the sum of its
// pair forces) and calls stop_on_non_finite_force when the test fails. Its loop also counts the contacts beyond
// their law's range in contact_range, which FixRuninFiniteCheck reports at the end of each run.
class FiniteForcePair {
 public:
  virtual ~FiniteForcePair() noexcept(std::is_nothrow_destructible_v<LAMMPS_NS::Pointers>) {}    // see RuninContactSource
  runin_host::ContactRangeMonitor contact_range;
};

// For a force loop that found a non-finite force on this rank: stops the run with the guard's ERROR
// (step and up to 4 IDs of owned or ghost atoms whose force is not finite). On one rank error->all; on
// more, error->one (the other ranks do not know, and a collective per step is what the caller avoids).
void stop_on_non_finite_force(LAMMPS_NS::LAMMPS *lmp, const std::string &style);

}    // namespace runin_lammps

#endif
#endif
