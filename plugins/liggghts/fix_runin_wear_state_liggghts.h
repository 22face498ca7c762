// Per-atom wear state of RunIn asperities in LIGGGHTS (internal fix RUNIN_WEAR_STATE, created by fix runin/wall or
// pair runin/asperity): the columns and the geometry update of plugins/lammps/fix_runin_wear_state.h
// (FixRuninWearState::refresh_geometry and flattened_volume are the same src/tribo calls). The state follows
// atoms across ranks, its geometry columns go to ghosts and all columns go into restart files.
#ifndef LMP_FIX_RUNIN_WEAR_STATE_LIGGGHTS_H
#define LMP_FIX_RUNIN_WEAR_STATE_LIGGGHTS_H

#include "atom.h"
#include "fix.h"
#include "memory.h"
#include "peratom_columns.h"
#include "wear_state_geometry.h"

#include <mpi.h>

#include <vector>

namespace LAMMPS_NS {

class FixRuninWearStateLiggghts : public runin_host::PeratomColumns<Fix> {
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
  void pre_exchange() override;

  double **state() { return columns; }
  void refresh_geometry(int i, double radius)
  {
    if (runin_host::refresh_worn_row<FixRuninWearStateLiggghts>(columns[i], radius)) note_change(i);
  }
  static double flattened_volume(double radius, double drop, double depth)
  {
    return runin_host::flattened_volume(radius, drop, depth);
  }
  void refresh_geometry_all();
  // Brings the ghosts' geometry columns up to date for this step's force (called by the pair).
  // One rank: every ghost is a periodic image of an owned atom; after a reneighbouring (or `always`, a run's
  // setup) one forward communication of indices finds each ghost's owned source, then the columns are copied
  // from it, and only when some summit changed. More ranks: after a reneighbouring or at setup LIGGGHTS's
  // forward_comm_fix; on the other steps the exchange was started at the end of the previous step
  // (end_of_step, when every RunIn style that changes the geometry has run) with non-blocking messages along
  // LIGGGHTS's own swap plan, a message carrying the columns only when its sender's summits (or those it
  // passes on) changed; here it is completed. So the pair adds no synchronisation point of its own to a step.
  // Returns whether any ghost could have changed.
  bool forward_geometry(bool always);
  long long forwarded_steps() const { return forwarded; }

  int pack_comm(int, int *, double *, int, int *) override;
  void unpack_comm(int, int, double *) override;

 private:
  int changed_here;          // an owned summit's geometry changed since the last exchange (this rank)
  long long forwarded;       // exchanges in this run (post_run: reset)
  int *source;               // one rank: the owned atom each ghost is an image of
  int nmax_source;
  bool send_indices;         // pack_comm/unpack_comm carry source indices (find_sources), not the geometry
  // the non-blocking exchange (more ranks)
  bool ghosts_wanted;        // a pair reads ghost geometry: exchange at the end of each step
  bool exchange_pending;
  MPI_Comm exchange_comm;    // a duplicate of world: its tags (the swap index) meet no LIGGGHTS message
  int next_swap;             // swaps below it are posted (or copied); the rest wait for completion
  bool exchange_dirty;       // this rank's summits, or ghosts it received, changed: send the columns
  std::vector<std::vector<double>> send_buffer, recv_buffer;
  std::vector<MPI_Request> requests;    // per swap: send, receive
  std::vector<char> received;           // per swap: its receive is unpacked
  std::vector<int> highest_sent;        // per swap: the highest atom index it sends (found once per plan)
  bool plan_known;                      // highest_sent is of the current plan (false after a reneighbouring)
  void start_exchange();
  bool advance_exchange(bool wait);
  void finish_exchange(bool unpack);
  void receive_swap(int swap, bool unpack);
  void find_sources();
  // one rank: the owned atoms whose geometry changed since the last copy (each once), and each owned atom's
  // ghost images (per plan), so a step copies to the images of the changed summits only
  std::vector<int> changed_atoms, changed_stamp, image_start, image_list;
  int copy_round = 0;
  bool full_copy = true;
  void note_change(int i)
  {
    changed_here = 1;
    if (i >= static_cast<int>(changed_stamp.size())) {
      full_copy = true;
      return;
    }
    if (changed_stamp[i] == copy_round) return;
    changed_stamp[i] = copy_round;
    changed_atoms.push_back(i);
  }
};

}    // namespace LAMMPS_NS

#endif
