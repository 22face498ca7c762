// Contacts beyond the range their normal law holds to: a counted WARNING, shared by pair and wall.
#ifndef LMP_RUNIN_CONTACT_RANGE_H
#define LMP_RUNIN_CONTACT_RANGE_H

#include "lmptype.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace runin_lammps {

// A contact whose NormalContact::range_ratio exceeds 1 (an elastic-plastic summit past the interference the
// law is checked to) is not fatal: a first loading may go there. The force loop keeps the step's worst
// contact with a max and a select (no branch); after the loop, note() adds the step's count and remembers the
// first offence of the run; report() at the end of the run (collective) prints one WARNING with the run's
// total, the first step, atom(s) and interference, and starts over.
class ContactRangeMonitor {
 public:
  // `atom_j` 0: a wall contact
  void note(LAMMPS_NS::bigint step, double count, double ratio, LAMMPS_NS::tagint atom_i, LAMMPS_NS::tagint atom_j)
  {
    count_ += count;
    if (first_[0] >= 0.0) return;
    first_[0] = static_cast<double>(step);
    first_[1] = ratio;
    first_[2] = static_cast<double>(atom_i);
    first_[3] = static_cast<double>(atom_j);
  }
  void report(LAMMPS_NS::LAMMPS *lmp, const std::string &style);

 private:
  double count_ = 0.0;
  double first_[4] = {-1.0, 0.0, 0.0, 0.0};    // step (-1: none yet), ratio, atom i, atom j
};

}    // namespace runin_lammps

#endif
