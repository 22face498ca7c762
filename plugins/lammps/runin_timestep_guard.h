// Stability guard for RunIn pair styles: a timestep check at init and a non-finite-force check
// every step. The limits come from runin::tribo (src/tribo/stability.h).
#ifdef FIX_CLASS
// clang-format off
FixStyle(RUNIN/FINITE_CHECK,FixRuninFiniteCheck);
// clang-format on
#else

#ifndef LMP_RUNIN_TIMESTEP_GUARD_H
#define LMP_RUNIN_TIMESTEP_GUARD_H

#include "fix.h"

#include <functional>
#include <string>

namespace LAMMPS_NS {

// Internal fix: after the pair forces (before reverse communication, so the culprit pair is still
// visible) stops the run with one ERROR line naming the step and atom IDs if any force is not finite.
class FixRuninFiniteCheck : public Fix {
 public:
  static constexpr const char *default_id = "RUNIN_FINITE_CHECK";
  FixRuninFiniteCheck(class LAMMPS *, int, char **);
  int setmask() override;
  void setup_pre_reverse(int, int) override;
  void pre_reverse(int, int) override;
  std::string style_label = "pair runin/asperity";

 private:
  void check();
};

}    // namespace LAMMPS_NS

namespace runin_lammps {

struct PairModuli {
  double effective_modulus = 0.0;          // E* [Pa], 0 if the type pair is not set
  double effective_shear_modulus = 0.0;    // G* [Pa]
};

// Compares update->dt with the smallest Rayleigh time of the asperities in contact-capable type pairs
// (radius and density per atom from radius/rmass, G and nu from the pair's E* and G*): WARNING above
// TimeStepPolicy::warn_fraction t_R, ERROR above fail_factor t_R. Installs the finite-force check.
// Returns the smallest Rayleigh time (0 if there are no atoms).
double guard_timestep(LAMMPS_NS::LAMMPS *lmp, const char *style,
                      const std::function<PairModuli(int, int)> &moduli_of);

}    // namespace runin_lammps

#endif
#endif
