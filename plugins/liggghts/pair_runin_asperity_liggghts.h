// pair_style runin/asperity for LIGGGHTS 3.8 (liggghts_runin): the host side only. The contact law is
// runin::tribo::ContactModel (src/tribo), the same object the LAMMPS pair (plugins/lammps) evaluates; this
// class holds the LIGGGHTS geometry and bookkeeping: the granular neighbour list, LIGGGHTS's contact history
// (FixContactHistory, via FixRuninContactHistory), the per-atom wear state and the contact sums.
// What differs from the LAMMPS style: doc/liggghts.md.
#ifndef LMP_PAIR_RUNIN_ASPERITY_LIGGGHTS_H
#define LMP_PAIR_RUNIN_ASPERITY_LIGGGHTS_H

#include "pair.h"

#include "pair_style.h"
#include "runin_contact_range.h"

#include <string>

namespace LAMMPS_NS {

class FixRuninWearStateLiggghts;

class PairRuninAsperityLiggghts
    : public runin_pair::PairStyle<PairRuninAsperityLiggghts, Pair, FixRuninWearStateLiggghts> {
 public:
  PairRuninAsperityLiggghts(class LAMMPS *);
  ~PairRuninAsperityLiggghts();
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  void init_list(int, class NeighList *) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void *extract(const char *, int &) override;

  // The run's contacts beyond their normal law's range: one WARNING (collective; at the end of each run).
  void report_contact_range();

 protected:
  int computeflag;    // read by LIGGGHTS's contact history fix (extract("computeflag"))
  runin_host::ContactRangeMonitor contact_range;
  class FixContactHistory *fix_history;

  // The force loop, specialised at compile time on the sub-models and features in use (as the LAMMPS pair).
  template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG> [[gnu::flatten]] void eval(int eflag);
  friend class runin_pair::PairStyle<PairRuninAsperityLiggghts, Pair, FixRuninWearStateLiggghts>;
  // the film coverage is a per-summit state that only the LAMMPS pair keeps
  void accept_sub_model(runin::tribo::SubModelKind kind, const std::string &name, int index);
  // The shared pass's (pair_contacts.h) view of the atoms and of the neighbour list with the contact history (eval
  // and single()); its adaptor has no film: friction junction/film is refused in settings()
  runin_pair::Atoms<int> loop_atoms() const;
  runin_pair::Neighbours neighbours() const;
};

}    // namespace LAMMPS_NS

#endif
