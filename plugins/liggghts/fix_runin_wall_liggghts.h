// fix runin/wall for LIGGGHTS 3.8 (liggghts_runin): asperities against a rigid flat counterface z = z_wall.
// The keywords, the wall motion and servo, the contact loop and the restart record are runin_wall (plugins/
// common/runin_wall_core.h), the code the LAMMPS fix runs; the law is runin::tribo::ContactModel. This class
// holds LIGGGHTS's side: the variables, the MPI reductions, the per-atom contact history (exchange and restart)
// and the wear-state fix. What differs from the LAMMPS style: doc/liggghts.md.
#ifndef LMP_FIX_RUNIN_WALL_LIGGGHTS_H
#define LMP_FIX_RUNIN_WALL_LIGGGHTS_H

#include "fix.h"

#include "runin_contact_sums.h"
#include "runin_wall_core.h"

namespace LAMMPS_NS {

class FixRuninWallLiggghts : public Fix, public RuninContactSource {
 public:
  enum Output { FX = 0, FY, FZ, WALL_Z, WALL_DX, WALL_DY, WALL_WEAR, CONTACTS, WALL_GAIN, NOUTPUT };

  FixRuninWallLiggghts(class LAMMPS *, int, char **);
  ~FixRuninWallLiggghts();
  int setmask() override;
  void post_create() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void reset_dt() override;
  void post_run() override;
  double compute_vector(int) override;

  void write_restart(FILE *) override;
  void restart(char *) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return runin_wall::HISTORY_SIZE + 1; }
  int maxsize_restart() override { return runin_wall::HISTORY_SIZE + 1; }
  double memory_usage() override;

  const RuninContactSums &contact_sums() const override { return sums; }
  double counterface_wear_volume() const override { return motion.wall_wear; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  bool has_counterface() const override { return true; }

 private:
  runin_wall::Config cfg;
  runin_wall::Motion motion;
  int body_groupbit;
  double dt;
  double smallest_radius;
  bigint past_centre_count;
  double beyond_range_count;    // contacts beyond their normal law's range in this run (WARNING at its end)
  double worst_range;
  double **history;
  double totals[NOUTPUT];
  RuninContactSums sums;
  class FixRuninWearStateLiggghts *fix_wear;

  void resolve(runin_wall::Setting &s, const char *keyword);
  double current(const runin_wall::Setting &s) const;
  void update_wall_velocity();
  void compute_contacts(bool advance);
  template <int NORMAL, int FRICTION> void compute_contacts(bool advance);
};

}    // namespace LAMMPS_NS

#endif
