// Per-atom wear state of RunIn asperities in LIGGGHTS (internal fix RUNIN_WEAR_STATE, created by
// pair runin/asperity): the columns and the geometry update of plugins/lammps/fix_runin_wear_state.h
// (FixRuninWearState::refresh_geometry and flattened_volume are the same src/tribo calls). The state follows
// atoms across ranks, its geometry columns go to ghosts and all columns go into restart files.
#ifndef LMP_FIX_RUNIN_WEAR_STATE_LIGGGHTS_H
#define LMP_FIX_RUNIN_WEAR_STATE_LIGGGHTS_H

#include "fix.h"
#include "tribo/asperity_geometry.h"

namespace LAMMPS_NS {

class FixRuninWearStateLiggghts : public Fix {
 public:
  enum Column { VOLUME_LOST = 0, VOLUME_GAINED, WEAR_DEPTH, FLAT_RADIUS, VOLUME_FLATTENED, NCOLUMNS };
  static constexpr const char *default_id = "RUNIN_WEAR_STATE";
  static constexpr const char *style_name = "RUNIN/WEAR_STATE";
  static FixRuninWearStateLiggghts *find(class Modify *modify);
  static FixRuninWearStateLiggghts *find_or_create(class Modify *modify);

  FixRuninWearStateLiggghts(class LAMMPS *, int, char **);
  ~FixRuninWearStateLiggghts();
  int setmask() override;
  void end_of_step() override;
  void post_run() override;

  double **state() { return values; }
  double local_sum(Column column, int groupbit) const;
  void refresh_geometry(int i, double radius)
  {
    if (!(radius > 0.0)) {
      values[i][WEAR_DEPTH] = values[i][FLAT_RADIUS] = 0.0;
      return;
    }
    const runin::tribo::WornAsperity worn = runin::tribo::worn_asperity(
        radius, values[i][VOLUME_LOST] + values[i][VOLUME_FLATTENED], values[i][VOLUME_GAINED],
        values[i][WEAR_DEPTH]);
    changed_here |= (worn.summit_drop != values[i][WEAR_DEPTH]) | (worn.flat_radius != values[i][FLAT_RADIUS]);
    values[i][WEAR_DEPTH] = worn.summit_drop;
    values[i][FLAT_RADIUS] = worn.flat_radius;
  }
  static double flattened_volume(double radius, double drop, double depth)
  {
    constexpr double kPiThird = 3.14159265358979323846 / 3.0;
    const double h0 = drop > 0.0 ? drop : 0.0, h1 = h0 + depth;
    return kPiThird * (h1 * h1 * (3.0 * radius - h1) - h0 * h0 * (3.0 * radius - h0));
  }
  void refresh_geometry_all();
  // Sends the geometry columns to the ghosts when they may be stale: after a reneighbouring (new ghosts), at
  // a run's setup (`always`), or when some rank changed an owned summit's geometry since the last send. The
  // "some rank" flag is reduced without a wait of its own: an MPI_Iallreduce started at the end of each step
  // (end_of_step, after every RunIn style that changes the geometry has run) and completed here, in the next
  // step's force, after LIGGGHTS's own per-step synchronisations (neighbour decision, forward communication).
  // On one rank every ghost is a periodic image of an owned atom: the columns are copied from it (the source
  // indices are found by one forward communication of indices after each reneighbouring), no buffers.
  // Returns whether it sent.
  bool forward_geometry(bool always);
  long long forwarded_steps() const { return forwarded; }

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return NCOLUMNS + 1; }
  int maxsize_restart() override { return NCOLUMNS + 1; }
  int pack_comm(int, int *, double *, int, int *) override;
  void unpack_comm(int, int, double *) override;
  double memory_usage() override;

 private:
  double **values;
  int changed_here;          // an owned summit's geometry changed since the last send (this rank)
  int changed_sent, changed_anywhere;
  MPI_Request changed_request;
  bool changed_pending;      // the reduction of changed_here is under way
  long long forwarded;       // sends in this run (post_run: reset)
  int *source;               // one rank: the owned atom each ghost is an image of
  int nmax_source;
  bool send_indices;         // pack_comm/unpack_comm carry source indices (find_sources), not the geometry
  void find_sources();
  bool changed_globally();
};

}    // namespace LAMMPS_NS

#endif
