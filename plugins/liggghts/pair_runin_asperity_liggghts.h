// pair_style runin/asperity for LIGGGHTS 3.8 (liggghts_runin): the host side only. The contact law is
// runin::tribo::ContactModel (src/tribo), the same object the LAMMPS pair (plugins/lammps) evaluates; this
// class holds the LIGGGHTS geometry and bookkeeping: the granular neighbour list, LIGGGHTS's contact history
// (FixContactHistory, via FixRuninContactHistory), the per-atom wear state and the contact sums.
// What differs from the LAMMPS style: doc/liggghts.md.
#ifndef LMP_PAIR_RUNIN_ASPERITY_LIGGGHTS_H
#define LMP_PAIR_RUNIN_ASPERITY_LIGGGHTS_H

#include "pair.h"

#include "../lammps/runin_contact_sums.h"
#include "tribo/contact_model.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class PairRuninAsperityLiggghts : public Pair, public RuninContactSource {
 public:
  PairRuninAsperityLiggghts(class LAMMPS *);
  ~PairRuninAsperityLiggghts();
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  void init_list(int, class NeighList *) override;
  double init_one(int, int) override;
  void reset_dt() override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

  const RuninContactSums &contact_sums() const override { return sums; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  class FixRuninWearStateLiggghts *wear_state() const { return fix_wear; }

 protected:
  int history_size;
  double dt;
  bool wear_on;
  bool reshape;
  runin::tribo::ContactSettings contact_settings;
  runin::tribo::ContactModelChoice choice;
  std::vector<runin::tribo::ContactCoefficients> coeffs;
  std::vector<std::optional<runin::tribo::ContactModel>> models;
  RuninContactSums sums;
  bool sums_requested;
  int body_groupbit;
  int computeflag;    // read by LIGGGHTS's contact history fix (extract("computeflag"))
  double *maxrad;

  // wear, transfer and flattening increments of one step, owned atoms only (newton off: no ghost shares)
  static constexpr int NINCREMENT = 3;
  enum Increment { INC_LOST = 0, INC_GAINED, INC_FLATTENED };
  double *increment;
  int nmax_increment;
  int *worn_owned;
  int nworn_owned;
  void add_flattening(int i, double depth, int nlocal)
  {
    if (i >= nlocal) return;
    double *slot = &increment[NINCREMENT * i];
    const bool was_zero = slot[0] == 0.0 && slot[1] == 0.0 && slot[2] == 0.0;
    slot[INC_FLATTENED] = slot[INC_FLATTENED] > depth ? slot[INC_FLATTENED] : depth;
    if (was_zero && slot[INC_FLATTENED] != 0.0) worn_owned[nworn_owned++] = i;
  }
  void add_wear(int i, double lost, double gained, int nlocal)
  {
    if (i >= nlocal) return;
    double *slot = &increment[NINCREMENT * i];
    const bool was_zero = slot[0] == 0.0 && slot[1] == 0.0 && slot[2] == 0.0;
    slot[0] += lost;
    slot[1] += gained;
    if (was_zero && (slot[0] != 0.0 || slot[1] != 0.0)) worn_owned[nworn_owned++] = i;
  }
  struct TouchingPair {
    int i, j;
    double *history;
  };
  std::vector<TouchingPair> touching;

  class FixContactHistory *fix_history;
  class FixRuninWearStateLiggghts *fix_wear;

  void allocate();
  void grow_increments();
  template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG> void eval(int eflag);
  using EvalFunction = void (PairRuninAsperityLiggghts::*)(int);
  static constexpr int NFLAGS = 4;
  template <int... Index>
  static std::array<EvalFunction, sizeof...(Index)> eval_table(std::integer_sequence<int, Index...>);
  runin::tribo::ContactGeometry contact_geometry(int i, int j, double overlap, double rinv, const double *del,
                                                 double flat) const;
  runin::tribo::ContactCoefficients &coeff_of(int itype, int jtype);
  void set_sub_model(runin::tribo::SubModelKind kind, const std::string &name);
  bool plastic_normal() const;
  void attach_wear_state();
};

}    // namespace LAMMPS_NS

#endif
