// Contacts beyond the range their normal law holds to: a counted WARNING, shared by the pair and the wall of
// both hosts (LAMMPS and LIGGGHTS).
#ifndef RUNIN_CONTACT_RANGE_H
#define RUNIN_CONTACT_RANGE_H

#include "tribo/elastic_plastic.h"

#include <fmt/format.h>
#include <mpi.h>

#include <string>
#include <vector>

namespace runin_host {

// A contact whose NormalContact::range_ratio exceeds 1 (an elastic-plastic summit past the interference the
// law is checked to) is not fatal: a first loading may go there. The force loop keeps the step's worst
// contact with a max and a select (no branch); after the loop, note() adds the step's count and remembers the
// first offence of the run; report() at the end of the run (collective) gives the one WARNING with the run's
// total, the first step, atom(s) and interference, and starts over.
class ContactRangeMonitor {
 public:
  // `atom_j` 0: a wall contact
  void note(long long step, double count, double ratio, long long atom_i, long long atom_j)
  {
    count_ += count;
    if (first_[0] >= 0.0) return;
    first_[0] = static_cast<double>(step);
    first_[1] = ratio;
    first_[2] = static_cast<double>(atom_i);
    first_[3] = static_cast<double>(atom_j);
  }

  // Collective over `world`: the WARNING text (without "WARNING: ") on its first rank when any contact of the
  // run was beyond the range, else empty; then starts over.
  std::string report(MPI_Comm world, const std::string &style)
  {
    double total = 0.0;
    MPI_Allreduce(&count_, &total, 1, MPI_DOUBLE, MPI_SUM, world);
    std::string message;
    if (total > 0.0) {
      int me = 0, nprocs = 1;
      MPI_Comm_rank(world, &me);
      MPI_Comm_size(world, &nprocs);
      std::vector<double> all(4 * nprocs);
      MPI_Gather(first_, 4, MPI_DOUBLE, all.data(), 4, MPI_DOUBLE, 0, world);
      if (me == 0) {
        // the earliest step, and there the worst contact (as with one rank, whatever the decomposition)
        const double *first = nullptr;
        for (int p = 0; p < nprocs; p++) {
          const double *candidate = &all[4 * p];
          if (candidate[0] >= 0.0 &&
              (!first || candidate[0] < first[0] || (candidate[0] == first[0] && candidate[1] > first[1])))
            first = candidate;
        }
        const auto i = static_cast<long long>(first[2]), j = static_cast<long long>(first[3]);
        const double limit = runin::tribo::JacksonGreen::kCheckedRange;
        message = fmt::format(
            "{}: {:.0f} contact evaluation(s) in this run beyond the range of the elastic/plastic law "
            "(interference > {:.0f} omega_c; its Jackson-Green and EKK fits reach 110 omega_c), first at step "
            "{:.0f}, {}: {:.4g} omega_c (load too high for these summits: results there are extrapolations)",
            style, total, limit, first[0], j ? fmt::format("atoms {} and {}", i, j) : fmt::format("atom {}", i),
            first[1] * limit);
      }
    }
    count_ = 0.0;
    first_[0] = -1.0;
    return message;
  }

 private:
  double count_ = 0.0;
  double first_[4] = {-1.0, 0.0, 0.0, 0.0};    // step (-1: none yet), ratio, atom i, atom j
};

}    // namespace runin_host

#endif
