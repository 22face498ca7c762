// Per-atom surface-film coverage of RunIn asperities (internal fix, created by pair runin/asperity when its friction
// model has a film, friction junction/film; doc/surface_films.md). One value per summit, theta in [0, 1], in a
// one-column per-atom store (runin_peratom_columns.h: exchange, restart), forwarded to ghosts (the friction of a
// contact reads both summits'); a per-step removal exposure (sum of slip / s_r over the summit's contacts) is gathered from ghosts by
// reverse communication and cleared every step.
//
//   fix RUNIN_FILM group RUNIN/FILM [coverage theta0 | coverage v_name]
//
// Defined by the user (before pair_style, with this ID) only to start from per-atom coverages (an atom-style
// variable, evaluated once).
// Output: a per-atom vector, the coverage (f_RUNIN_FILM in dumps and compute reduce).
#ifdef FIX_CLASS
// clang-format off
FixStyle(RUNIN/FILM,FixRuninFilm);
// clang-format on
#else

#ifndef LMP_FIX_RUNIN_FILM_H
#define LMP_FIX_RUNIN_FILM_H

#include "runin_peratom_columns.h"

namespace LAMMPS_NS {

class FixRuninFilm : public RuninPeratomColumns {
 public:
  static constexpr const char *default_id = "RUNIN_FILM";
  static FixRuninFilm *find(class Modify *modify);
  // Creates it for group all with the given initial coverage when it does not exist yet (an existing one keeps its
  // values: a restart or an earlier run).
  static FixRuninFilm *find_or_create(class Modify *modify, double initial_coverage);

  FixRuninFilm(class LAMMPS *, int, char **);
  ~FixRuninFilm() override;
  int setmask() override { return 0; }

  double *coverage() { return columns ? columns[0] : nullptr; }    // one contiguous column
  double *exposure() { return removal; }
  // Before the force loop: the coverage to the ghosts, the exposure of owned and ghost atoms cleared.
  void begin_step();
  // After it: the ghosts' exposure to their owners (newton on), then every owned summit advanced by its removal
  // exposure and the growth exposure of its type (growth[type] = k_g dt of the type's own pair).
  void end_step(bool newton, const double *growth);

  void grow_arrays(int) override;    // the coverage and the removal exposure
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  // removal exposure of this step per atom (owned and ghost): cleared by begin_step, moves with no atom
  double *removal;
};

}    // namespace LAMMPS_NS

#endif
#endif
