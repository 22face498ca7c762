// Per-atom wear state of RunIn asperities (internal fix, created by pair runin/asperity).
// Holds the full per-atom storage method set so the state follows atoms across ranks,
// to ghosts when asked, and through write_restart/read_restart.
#ifdef FIX_CLASS
// clang-format off
FixStyle(RUNIN/WEAR_STATE,FixRuninWearState);
// clang-format on
#else

#ifndef LMP_FIX_RUNIN_WEAR_STATE_H
#define LMP_FIX_RUNIN_WEAR_STATE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixRuninWearState : public Fix {
 public:
  enum Column { VOLUME_LOST = 0, NCOLUMNS };
  static constexpr const char *default_id = "RUNIN_WEAR_STATE";

  FixRuninWearState(class LAMMPS *, int, char **);
  ~FixRuninWearState() override;
  int setmask() override { return 0; }

  double **state() { return values; }
  double local_sum(Column column, int groupbit) const;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return NCOLUMNS + 1; }
  int maxsize_restart() override { return NCOLUMNS + 1; }
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  double **values;
};

}    // namespace LAMMPS_NS

#endif
#endif
