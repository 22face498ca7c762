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

#include "runin_contact_range.h"
#include "runin_contact_sums.h"
#include "runin_peratom_columns.h"
#include "runin_wall_core.h"
#include "tribo/contact_model.h"

#include <string>

namespace LAMMPS_NS {

class FixRuninWall : public RuninPeratomColumns, public RuninContactSource {
 public:
  // Global vector entries (1-based in input decks).
  enum Output { FX = 0, FY, FZ, WALL_Z, WALL_DX, WALL_DY, WALL_WEAR, CONTACTS, WALL_GAIN, NOUTPUT };

  FixRuninWall(class LAMMPS *, int, char **);
  int setmask() override;
  void post_constructor() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void reset_dt() override;
  void post_run() override;
  double compute_vector(int) override;

  void write_restart(FILE *) override;
  void restart(char *) override;

  const RuninContactSums &contact_sums() const override { return sums; }
  double counterface_wear_volume() const override { return motion.wall_wear; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  bool has_counterface() const override { return true; }

 private:
  static constexpr int HISTORY_SIZE = runin::tribo::CONTACT_HISTORY_SIZE;

  // The keywords (contact model, control, servo) and the wall's state: the host-neutral core that the
  // LIGGGHTS host shares (runin_wall_core.h).
  runin_wall::Config cfg;
  runin_wall::Motion motion;
  int body_groupbit;    // group whose contact reaction the sums carry (0: none)
  double dt;
  double smallest_radius;    // of the group's asperities (init): the wall may not slide further in one step
  bigint past_centre_count = 0;    // asperity evaluations past the summit centre in this run (WARNING)
  runin_host::ContactRangeMonitor contact_range;    // contacts beyond their normal law's range (WARNING)

  double **&history = columns;    // per atom: the contact history with the wall (the column store)
  double totals[NOUTPUT];    // reduced over ranks at every evaluation
  RuninContactSums sums;
  class FixRuninWearState *fix_wear;

  void resolve(runin_wall::Setting &s, const char *keyword);
  double current(const runin_wall::Setting &s) const;
  void update_wall_velocity();
  void compute_contacts(bool advance);
  template <int NORMAL, int FRICTION> void compute_contacts(bool advance);
  void guard_timestep();
  void check_wall_step() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
