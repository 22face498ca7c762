// pair_style runin/asperity for LIGGGHTS 3.8 (liggghts_runin): the host side only. The contact law is
// runin::tribo::ContactModel (src/tribo), the same object the LAMMPS pair (plugins/lammps) evaluates; this
// class holds the LIGGGHTS geometry and bookkeeping: the granular neighbour list, LIGGGHTS's contact history
// (FixContactHistory, via FixRuninContactHistory), the per-atom wear state and the contact sums.
// What differs from the LAMMPS style: doc/liggghts.md.
#ifndef LMP_PAIR_RUNIN_ASPERITY_LIGGGHTS_H
#define LMP_PAIR_RUNIN_ASPERITY_LIGGGHTS_H

#include "pair.h"

#include "pair_contacts.h"
#include "pair_increments.h"
#include "runin_contact_range.h"
#include "runin_contact_sums.h"
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
  double single(int, int, int, int, double, double, double, double &) override;
  void reset_dt() override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

  const RuninContactSums &contact_sums() const override { return sums; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  class FixRuninWearStateLiggghts *wear_state() const { return fix_wear; }
  // The run's contacts beyond their normal law's range: one WARNING (collective; at the end of each run).
  void report_contact_range();

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

  // wear, transfer and flattening increments of one step (newton off: owned atoms only)
  runin_pair::Increments increments;
  std::vector<runin_pair::TouchingPair> touching;
  runin_host::ContactRangeMonitor contact_range;

  class FixContactHistory *fix_history;
  class FixRuninWearStateLiggghts *fix_wear;

  void allocate();
  // The force loop, specialised at compile time on the sub-models and features in use (as the LAMMPS pair).
  template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG> [[gnu::flatten]] void eval(int eflag);
  using EvalFunction = void (PairRuninAsperityLiggghts::*)(int);
  static constexpr int NFLAGS = 4;
  template <int... Index>
  static std::array<EvalFunction, sizeof...(Index)> eval_table(std::integer_sequence<int, Index...>);
  // The shared pass (pair_contacts.h): its adaptor (no film: friction junction/film is refused in settings()), and
  // its view of the atoms and of the neighbour list with the contact history (eval and single())
  friend struct runin_pair::PairHost<PairRuninAsperityLiggghts, false>;
  runin_pair::Atoms<int> loop_atoms() const;
  runin_pair::Neighbours neighbours() const;
  runin::tribo::ContactCoefficients &coeff_of(int itype, int jtype);
  void set_sub_model(runin::tribo::SubModelKind kind, const std::string &name);
  bool plastic_normal() const;
  void attach_wear_state();
};

}    // namespace LAMMPS_NS

#endif
