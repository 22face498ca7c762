// Per-atom wear state of RunIn asperities (internal fix, created by pair runin/asperity).
// Its per-atom column store (runin_peratom_columns.h) carries the state across ranks, to ghosts (the geometry
// columns, which the contact force reads) and through write_restart/read_restart.
//
//   fix RUNIN_WEAR_STATE group RUNIN/WEAR_STATE [lost v_name] [gained v_name]
//
// Defined by the user (before pair_style, with this ID) only to start from a given worn state.
#ifdef FIX_CLASS
// clang-format off
FixStyle(RUNIN/WEAR_STATE,FixRuninWearState);
// clang-format on
#else

#ifndef LMP_FIX_RUNIN_WEAR_STATE_H
#define LMP_FIX_RUNIN_WEAR_STATE_H

#include "runin_peratom_columns.h"
#include "wear_state_geometry.h"

namespace LAMMPS_NS {

class FixRuninWearState : public RuninPeratomColumns {
 public:
  // VOLUME_LOST: removed by wear; VOLUME_GAINED: deposited by transfer from counter-asperities;
  // VOLUME_FLATTENED: the summit cap pressed flat by plastic contact (displaced, not removed) [m^3].
  // WEAR_DEPTH h (summit drop) and FLAT_RADIUS a_w follow from them and the radius: one truncated sphere
  // whose cap volume is lost + flattened - gained, so wear and plastic flattening act on the same summit.
  // RISE: how far the free surface of the atom's body has risen by the volume its flattened caps displaced
  // (pair runin/asperity rise yes or free; Pullen and Williamson 1972) [m]; 0 otherwise.
  enum Column { VOLUME_LOST = 0, VOLUME_GAINED, WEAR_DEPTH, FLAT_RADIUS, VOLUME_FLATTENED, RISE, NCOLUMNS };
  static constexpr const char *default_id = "RUNIN_WEAR_STATE";
  // The wear-state fix of this LAMMPS instance (by its ID), or nullptr; the second form creates it
  // for group all when it does not exist yet. Look it up again at init: it may have been redefined.
  static FixRuninWearState *find(class Modify *modify);
  static FixRuninWearState *find_or_create(class Modify *modify);

  FixRuninWearState(class LAMMPS *, int, char **);
  int setmask() override { return 0; }

  double **state() { return columns; }
  // Recompute WEAR_DEPTH and FLAT_RADIUS of owned atom i from its volumes and radius, starting from its
  // current WEAR_DEPTH (per step, after a small change of the volumes).
  void refresh_geometry(int i);
  // The same with the radius given (inline, for the per-step loop of the pair style).
  void refresh_geometry(int i, double radius) { runin_host::refresh_worn_row<FixRuninWearState>(columns[i], radius); }
  static double flattened_volume(double radius, double drop, double depth)
  {
    return runin_host::flattened_volume(radius, drop, depth);
  }
  // The same for every owned atom (at setup: volumes or radii may have been set).
  void refresh_geometry_all();
  // Send the geometry columns to the ghosts.
  void forward_geometry();
  // Whether the ghosts also get VOLUME_FLATTENED (a pair with a plastic normal model reads it for reloads).
  void forward_flattened(bool on)
  {
    send_flattened = on;
    choose_forwarded();
  }
  // Whether the ghosts also get RISE (a pair with volume-conserving flattening reads it for the summit reach).
  void forward_rise(bool on)
  {
    send_rise = on;
    choose_forwarded();
  }

 private:
  bool send_flattened = true;
  bool send_rise = false;
  void choose_forwarded();
  void assign_from_variable(Column column, const char *name);
};

}    // namespace LAMMPS_NS

#endif
#endif
