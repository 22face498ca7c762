// The fix class of fix runin/wall that both hosts derive from: the per-atom contact history with the wall (the
// column store, peratom_columns.h), the wall's variables, its step (servo, contact loop of runin_wall_core.h, the
// MPI reduction with the past-centre and non-finite checks, the totals), the global vector and the restart record.
// Messages go through the host's runin_host_api.h. The deriving class (CRTP) supplies
//   void note_range(step, StepLocal)        the contacts beyond their normal law's range (WARNING at run end)
// and its own constructor (atom style, units, parse; then start()), the wear-state fix's creation, post_run.
#pragma once

#include "peratom_columns.h"
#include "runin_host_api.h"
#include "runin_contact_sums.h"
#include "runin_wall_core.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "input.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace runin_wall {

template <class Host, class Fix, class WearState>
class WallFix : public runin_host::PeratomColumns<Fix>, public LAMMPS_NS::RuninContactSource {
 public:
  // Global vector entries (1-based in input decks).
  enum Output { FX = 0, FY, FZ, WALL_Z, WALL_DX, WALL_DY, WALL_WEAR, CONTACTS, WALL_GAIN, NOUTPUT };

  int setmask() override { return LAMMPS_NS::FixConst::POST_FORCE; }

  void init() override
  {
    resolve(cfg.vel[0], "vel vx");
    resolve(cfg.vel[1], "vel vy");
    resolve(cfg.vz, "vz");
    dt = this->update->dt;
    // the wear-state fix may have been redefined since this fix was created: look it up again
    fix_wear = WearState::find(this->modify);
    if (!fix_wear) runin_host::all(this->lmp, FLERR, "fix runin/wall: the per-atom wear state fix is missing");
    double local_min = std::numeric_limits<double>::infinity();
    for (int i = 0; i < this->atom->nlocal; i++)
      if (this->atom->mask[i] & this->groupbit) local_min = std::min(local_min, this->atom->radius[i]);
    MPI_Allreduce(&local_min, &smallest_radius, 1, MPI_DOUBLE, MPI_MIN, this->world);
  }
  void setup(int) override
  {
    update_wall_velocity();
    if (cfg.control != Control::displacement) motion.velocity[2] = 0.0;
    compute_contacts(false);
  }
  void post_force(int) override
  {
    update_wall_velocity();
    runin_host::kernel_call(this->lmp, FLERR, "fix runin/wall", true, [&] {    // the servo: every rank alike
      move_wall(cfg, motion, dt, this->domain->xprd * this->domain->yprd);
    });
    compute_contacts(true);
  }
  void reset_dt() override { dt = this->update->dt; }

  double compute_vector(int n) override
  {
    switch (n) {
      case WALL_Z: return motion.wall_z;
      case WALL_DX: return motion.wall_dx;
      case WALL_DY: return motion.wall_dy;
      case WALL_WEAR: return motion.wall_wear;
      case WALL_GAIN: return motion.wall_gain;
      default: return totals[n];
    }
  }

  // Global restart state: restart_record (the wall, the servo, the contact model record), the same on both hosts,
  // so either reads the other's numbers.
  void write_restart(FILE *fp) override
  {
    if (this->comm->me != 0) return;
    const std::vector<double> state = restart_record(cfg, motion);
    const int size = static_cast<int>(state.size() * sizeof(double));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(state.data(), sizeof(double), state.size(), fp);
  }
  void restart(char *buf) override
  {
    runin_host::kernel_call(this->lmp, FLERR, "fix runin/wall: restart file", true, [&] {
      const std::string problem = read_restart_record(buf, cfg, motion);
      if (!problem.empty()) runin_host::all(this->lmp, FLERR, "fix runin/wall: restart file: " + problem);
    });
  }

  const LAMMPS_NS::RuninContactSums &contact_sums() const override { return sums; }
  double counterface_wear_volume() const override { return motion.wall_wear; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  bool has_counterface() const override { return true; }

 protected:
  WallFix(LAMMPS_NS::LAMMPS *lmp, int narg, char **arg) :
      runin_host::PeratomColumns<Fix>(lmp, narg, arg, HISTORY_SIZE, "fix_runin_wall:history")
  {
  }
  // The end of the host's constructor, once the keywords are parsed into cfg: the global vector, the restart
  // record, the callbacks.
  void start()
  {
    motion.wall_z = cfg.wall_z;
    this->vector_flag = 1;
    this->size_vector = NOUTPUT;
    this->global_freq = 1;
    this->extvector = 0;
    this->restart_global = 1;
    std::fill(totals, totals + NOUTPUT, 0.0);
    this->attach();
  }
  // The first past-centre WARNING of the run has counted the rest: their total (post_run, rank 0).
  void report_past_centre()
  {
    if (past_centre_count > 0 && this->comm->me == 0)
      this->error->warning(FLERR, past_centre_summary(past_centre_count).c_str());
    past_centre_count = 0;
  }

  // The keywords (contact model, control, servo) and the wall's state (runin_wall_core.h).
  Config cfg;
  Motion motion;
  int body_groupbit = 0;    // group whose contact reaction the sums carry (0: none)
  double dt = 0.0;
  double smallest_radius = 0.0;    // of the group's asperities (init): the wall may not slide further in one step
  long long past_centre_count = 0;    // asperity evaluations past the summit centre in this run (WARNING)
  double totals[NOUTPUT];    // reduced over ranks at every evaluation
  LAMMPS_NS::RuninContactSums sums;
  WearState *fix_wear = nullptr;

 private:
  Host &host() { return static_cast<Host &>(*this); }

  void resolve(Setting &s, const char *keyword)
  {
    if (s.variable.empty()) return;
    s.ivar = this->input->variable->find(&s.variable[0]);
    if (s.ivar < 0)
      runin_host::all(this->lmp, FLERR,
                  fmt::format("fix runin/wall: {} variable '{}' does not exist", keyword, s.variable));
    if (!this->input->variable->equalstyle(s.ivar))
      runin_host::all(this->lmp, FLERR,
                  fmt::format("fix runin/wall: {} variable '{}' must be equal-style", keyword, s.variable));
  }
  double current(const Setting &s) const
  {
    return s.ivar >= 0 ? this->input->variable->compute_equal(s.ivar) : s.value;
  }

  // Every rank evaluates the same variables, so the checks are collective. A wall that moves further than a
  // summit radius in one step skips whole contacts: the contact laws are not resolved in time.
  void update_wall_velocity()
  {
    this->modify->clearstep_compute();
    motion.velocity[0] = current(cfg.vel[0]);
    motion.velocity[1] = current(cfg.vel[1]);
    motion.velocity[2] = cfg.control == Control::displacement ? current(cfg.vz) : 0.0;
    this->modify->addstep_compute(this->update->ntimestep + 1);
    const std::string problem = wall_step_problem(motion.velocity, dt, smallest_radius, this->update->ntimestep);
    if (!problem.empty()) runin_host::all(this->lmp, FLERR, problem);
  }

  void compute_contacts(bool advance)
  {
    runin_host::kernel_call(this->lmp, FLERR, "fix runin/wall", false, [&] {
      runin::tribo::with_sub_models(cfg.choice, [&](auto normal, auto friction) {
        compute_contacts<decltype(normal)::value, decltype(friction)::value>(advance);
      });
    });
  }

  // The contact loop (runin_wall::contacts), then the reduction over ranks and its checks.
  template <int NORMAL, int FRICTION> void compute_contacts(bool advance)
  {
    auto *atom = this->atom;
    using Tag = std::remove_const_t<std::remove_pointer_t<decltype(atom->tag)>>;    // tagint; int in LIGGGHTS
    const MPI_Datatype tag_type = sizeof(Tag) == sizeof(int) ? MPI_INT : MPI_LONG_LONG;
    const Atoms<Tag> atoms{atom->x,      atom->v,     atom->f,    atom->omega, atom->torque,
                           atom->radius, atom->rmass, atom->mask, atom->tag,   atom->nlocal};
    StepLocal<Tag> step;
    // this->columns: per atom, the contact history with the wall
    runin_wall::contacts<NORMAL, FRICTION>(cfg, motion, atoms, this->columns, fix_wear, this->groupbit,
                                           body_groupbit, dt, advance, sums, step);
    if (advance) host().note_range(this->update->ntimestep, step);

    double global[NLOCAL];
    MPI_Allreduce(step.local, global, NLOCAL, MPI_DOUBLE, MPI_SUM, this->world);
    if (global[LOCAL_THROUGH] > 0.0) {
      // counted, not fatal: a first-loading sweep may press summits that far on purpose; the count is
      // reported at the end of the run (post_run)
      Tag culprit = step.first_through;
      MPI_Allreduce(&step.first_through, &culprit, 1, tag_type, MPI_MIN, this->world);
      if (past_centre_count == 0 && this->comm->me == 0)
        this->error->warning(
            FLERR,
            past_centre_message(this->update->ntimestep, motion.wall_z, global[LOCAL_THROUGH], culprit).c_str());
      past_centre_count += static_cast<long long>(global[LOCAL_THROUGH]);
    }
    if (!step_finite(global, motion)) {
      Tag culprit = step.first_bad;
      MPI_Allreduce(&step.first_bad, &culprit, 1, tag_type, MPI_MIN, this->world);
      runin_host::all(this->lmp, FLERR,
                  non_finite_message(this->update->ntimestep, culprit != std::numeric_limits<Tag>::max(), culprit,
                                     motion, this->update->dt));
    }
    take_totals(global, motion, totals + FX, totals[CONTACTS]);
  }
};

}    // namespace runin_wall
