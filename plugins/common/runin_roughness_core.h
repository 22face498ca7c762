// The host-neutral part of compute runin/roughness, shared by the LAMMPS style and the LIGGGHTS host: the global
// vector from the member summits' heights in two MPI reductions (count, sum and extremes; then power sums about
// the mean plane and the bearing counts below the highest summit).
#pragma once

#include "tribo/surface_statistics.h"

#include <mpi.h>

#include <cstddef>
#include <vector>

namespace runin_roughness {

// Entries of the global vector: Ra Rq Rsk Rku Rp Rv Rz, then one bearing ratio per depth.
enum Entry { RA = 0, RQ, RSK, RKU, RP, RV, RZ, NFIXED };

// The seven fixed statistics into out[RA .. RZ] (the summit entries, and the surface entries that follow them in
// the same order).
inline void write_fixed(const runin::tribo::RoughnessStatistics &stats, double *out)
{
  out[RA] = stats.Ra;
  out[RQ] = stats.Rq;
  out[RSK] = stats.Rsk;
  out[RKU] = stats.Rku;
  out[RP] = stats.Rp;
  out[RV] = stats.Rv;
  out[RZ] = stats.Rz;
}

// `member(i)` selects the local summits, `height(i)` gives a summit's height; fills vector[0 .. NFIXED + depths).
// Collective on `world`; tribo::roughness may throw (the caller's kernel_call turns that into an ERROR).
template <class Member, class Height>
void compute_vector(MPI_Comm world, int nlocal, Member member, Height height, const std::vector<double> &depths,
                    double *vector)
{
  runin::tribo::HeightRange range;
  for (int i = 0; i < nlocal; i++)
    if (member(i)) range.add(height(i));
  double sums[2] = {range.count, range.sum}, extremes[2] = {range.max, -range.min};
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(MPI_IN_PLACE, extremes, 2, MPI_DOUBLE, MPI_MAX, world);
  range.count = sums[0];
  range.sum = sums[1];
  range.max = extremes[0];
  range.min = -extremes[1];

  runin::tribo::HeightMoments moments(range.mean(), range.max, depths);
  for (int i = 0; i < nlocal; i++)
    if (member(i)) moments.add(height(i));
  MPI_Allreduce(MPI_IN_PLACE, moments.sums().data(), static_cast<int>(moments.size()), MPI_DOUBLE, MPI_SUM, world);
  const auto stats = runin::tribo::roughness(range, moments);
  write_fixed(stats, vector);
  for (std::size_t k = 0; k < depths.size(); k++) vector[NFIXED + k] = stats.bearing[k];
}

}  // namespace runin_roughness
