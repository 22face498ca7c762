// The wear, transfer and plastic-flattening increments of one step of pair runin/asperity, and their application
// to the per-atom wear state: shared by the LAMMPS and the LIGGGHTS host (the pass is pair_contacts.h).
#ifndef RUNIN_PAIR_INCREMENTS_H
#define RUNIN_PAIR_INCREMENTS_H

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace runin_pair {

// {lost, gained, flattened depth} per atom (owned + ghost; a newton-on host reverse-communicates the ghosts'),
// side by side. All zero between steps: an atom is listed when its first nonzero increment arrives (sums of values
// >= 0 stay nonzero), and only the listed entries are applied (owned atoms) and cleared, instead of passes over all
// owned and ghost atoms.
class Increments {
 public:
  static constexpr int NVALUES = 3;
  enum Value { LOST = 0, GAINED, FLATTENED };

  // room for nmax atoms (grows only; growing clears)
  void reserve(int nmax)
  {
    if (nmax <= nmax_) return;
    nmax_ = nmax;
    values_.assign(static_cast<size_t>(NVALUES) * nmax, 0.0);
    // one slot per atom, plus the one the branch-free listing writes past the end
    owned_.assign(nmax + 1, 0);
    ghost_.assign(nmax + 1, 0);
    nowned_ = nghost_ = 0;
  }
  // none until the next reserve()
  void release()
  {
    values_ = std::vector<double>();
    owned_ = ghost_ = std::vector<int>();
    nmax_ = nowned_ = nghost_ = 0;
  }
  bool reserved() const { return nmax_ > 0; }

  // The summit of one asperity sinks to the deepest residual of its contacts in a step, not their sum: every
  // contact of the asperity sees the same summit, so each one's sink below it is the same flattening.
  void add_flattening(int i, double depth, int nlocal)
  {
    // branch-free: the slot is always written and kept only for an atom listed now
    double *slot = &values_[NVALUES * i];
    const bool was_zero = slot[0] == 0.0 && slot[1] == 0.0 && slot[2] == 0.0;
    slot[FLATTENED] = std::max(slot[FLATTENED], depth);
    const bool first = was_zero && slot[FLATTENED] != 0.0, owned = i < nlocal;
    owned_[nowned_] = i;
    ghost_[nghost_] = i;
    nowned_ += first && owned;
    nghost_ += first && !owned;
  }
  void add_wear(int i, double lost, double gained, int nlocal)
  {
    double *slot = &values_[NVALUES * i];
    const bool was_zero = slot[0] == 0.0 && slot[1] == 0.0 && slot[2] == 0.0;
    slot[LOST] += lost;
    slot[GAINED] += gained;
    const bool first = was_zero && (slot[LOST] != 0.0 || slot[GAINED] != 0.0), owned = i < nlocal;
    owned_[nowned_] = i;
    ghost_[nghost_] = i;
    nowned_ += first && owned;
    nghost_ += first && !owned;
  }

  const double *of(int i) const { return &values_[NVALUES * i]; }
  // the owned atoms with an increment this step
  const int *owned() const { return owned_.data(); }
  int nowned() const { return nowned_; }

  // The listed owned atoms' increments into the wear state (WearFix: its columns, flattened_volume and
  // refresh_geometry), then every listed entry cleared. Returns the first atom whose summit is now worn or
  // flattened past its equator (it has left the truncated-sphere geometry; the host stops), else -1.
  template <class WearFix> int apply(WearFix &fix, const double *radius)
  {
    double **state = fix.state();
    for (int k = 0; k < nowned_; k++) {
      const int i = owned_[k];
      double *inc = &values_[NVALUES * i];
      state[i][WearFix::VOLUME_LOST] += inc[LOST];
      state[i][WearFix::VOLUME_GAINED] += inc[GAINED];
      if (inc[FLATTENED] > 0.0)
        state[i][WearFix::VOLUME_FLATTENED] +=
            WearFix::flattened_volume(radius[i], state[i][WearFix::WEAR_DEPTH], inc[FLATTENED]);
      inc[LOST] = inc[GAINED] = inc[FLATTENED] = 0.0;
      fix.refresh_geometry(i, radius[i]);
      if (state[i][WearFix::WEAR_DEPTH] > radius[i]) return i;
    }
    for (int k = 0; k < nghost_; k++) {
      double *inc = &values_[NVALUES * ghost_[k]];
      inc[LOST] = inc[GAINED] = inc[FLATTENED] = 0.0;
    }
    nowned_ = nghost_ = 0;
    return -1;
  }

  double memory_usage() const
  {
    return static_cast<double>(values_.capacity()) * sizeof(double) +
           static_cast<double>(owned_.capacity() + ghost_.capacity()) * sizeof(int);
  }

 private:
  std::vector<double> values_;
  std::vector<int> owned_, ghost_;
  int nmax_ = 0, nowned_ = 0, nghost_ = 0;
};

// The ERROR for Increments::apply's atom.
template <class Tag>
std::string used_up_message(long long step, Tag atom, double depth, double radius)
{
  return fmt::format("pair runin/asperity: at step {} the summit of atom {} has been worn or flattened by {:.4g} m, "
                     "more than its radius {:.4g} m (the asperity is used up): load or wear coefficient too large",
                     step, atom, depth, radius);
}

}    // namespace runin_pair

#endif
