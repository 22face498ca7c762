#include "runin_contact_range.h"

#include "tribo/elastic_plastic.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include <mpi.h>

#include <vector>

namespace runin_lammps {

void ContactRangeMonitor::report(LAMMPS_NS::LAMMPS *lmp, const std::string &style)
{
  double total = 0.0;
  MPI_Allreduce(&count_, &total, 1, MPI_DOUBLE, MPI_SUM, lmp->world);
  if (total > 0.0) {
    const int nprocs = lmp->comm->nprocs;
    std::vector<double> all(4 * nprocs);
    MPI_Gather(first_, 4, MPI_DOUBLE, all.data(), 4, MPI_DOUBLE, 0, lmp->world);
    if (lmp->comm->me == 0) {
      // the earliest step, and there the worst contact (as with one rank, whatever the decomposition)
      const double *first = nullptr;
      for (int p = 0; p < nprocs; p++) {
        const double *candidate = &all[4 * p];
        if (candidate[0] >= 0.0 &&
            (!first || candidate[0] < first[0] || (candidate[0] == first[0] && candidate[1] > first[1])))
          first = candidate;
      }
      const auto i = static_cast<LAMMPS_NS::tagint>(first[2]), j = static_cast<LAMMPS_NS::tagint>(first[3]);
      const double limit = runin::tribo::JacksonGreen::kCheckedRange;
      lmp->error->warning(
          FLERR, "{}: {:.0f} contact evaluation(s) in this run beyond the range of the elastic/plastic law "
          "(interference > {:.0f} omega_c; its Jackson-Green and EKK fits reach 110 omega_c), first at step {:.0f}, "
          "{}: {:.4g} omega_c (load too high for these summits: results there are extrapolations)",
          style, total, limit, first[0], j ? fmt::format("atoms {} and {}", i, j) : fmt::format("atom {}", i),
          first[1] * limit);
    }
  }
  count_ = 0.0;
  first_[0] = -1.0;
}

}    // namespace runin_lammps
