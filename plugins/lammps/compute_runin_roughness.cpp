#include "compute_runin_roughness.h"
#include "runin_errors.h"

#include "fix_runin_wear_state.h"
#include "tribo/summit_envelope.h"
#include "tribo/surface_statistics.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

static_assert(ComputeRuninRoughness::S_RZ - ComputeRuninRoughness::S_RA == runin_roughness::RZ - runin_roughness::RA,
              "the surface entries follow runin_roughness::Entry");

ComputeRuninRoughness::ComputeRuninRoughness(LAMMPS *lmp, int narg, char **arg) :
    RoughnessCompute(lmp, narg, arg), nmax(0), peratom(nullptr), surface_dx(0.0)
{
  int iarg = 3;
  while (iarg < narg) {
    if (const int next = parse_keyword(narg, arg, iarg)) {
      iarg = next;
    } else if (strcmp(arg[iarg], "surface") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "compute runin/roughness: keyword 'surface' needs a grid spacing (distance units)");
      surface_dx = runin_lammps::finite_number(lmp, FLERR, "compute runin/roughness", "surface grid spacing",
                                               arg[iarg + 1]);
      if (!(surface_dx > 0.0))
        error->all(FLERR, "compute runin/roughness: surface grid spacing must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, "compute runin/roughness: unknown keyword '{}' (expected bearing, side, mean or surface)",
                 arg[iarg]);
    }
  }
  start_vector(surface_dx > 0.0 ? NSURFACE : 0);

  peratom_flag = 1;
  size_peratom_cols = NPERATOM;
}

ComputeRuninRoughness::~ComputeRuninRoughness()
{
  memory->destroy(peratom);
}

void ComputeRuninRoughness::init()
{
  RoughnessCompute::init();
  if (surface_dx > 0.0) {
    const double cells = std::ceil(domain->xprd / surface_dx) * std::ceil(domain->yprd / surface_dx);
    if (!(cells <= 1.0e8))
      error->all(FLERR, "compute runin/roughness: surface grid spacing {} gives {:.3g} grid points over the box "
                        "(more than 1e8): use a larger spacing", surface_dx, cells);
  }
}

double ComputeRuninRoughness::wear_depth(int i) const
{
  return wear_column(i, FixRuninWearState::WEAR_DEPTH);
}

double ComputeRuninRoughness::rise(int i) const
{
  return wear_column(i, FixRuninWearState::RISE);
}

double ComputeRuninRoughness::summit(int i) const
{
  // side up: top of the sphere; side down: bottom of the sphere, measured downward. A worn summit is
  // truncated by its wear depth h (negative where transfer deposited more than was lost) and raised with its
  // body's free surface (0 unless pair runin/asperity rise yes).
  return sign * atom->x[i][2] + atom->radius[i] - wear_depth(i) + rise(i);
}

// The height field of the group's surface: each rank draws its summits' caps on the whole grid, first out to
// twice the mean summit spacing, then (after a maximum over ranks) further out only where a cap can still rise
// above the lowest point of that first envelope, which bounds the true envelope from below.
void ComputeRuninRoughness::compute_surface(double *out)
{
  const int *mask = atom->mask;
  const double *radius = atom->radius;
  double **x = atom->x;
  const auto nx = static_cast<std::size_t>(std::max(1.0, std::round(domain->xprd / surface_dx)));
  const auto ny = static_cast<std::size_t>(std::max(1.0, std::round(domain->yprd / surface_dx)));
  runin::tribo::SummitEnvelope envelope(domain->boxlo[0], domain->boxlo[1], domain->xprd, domain->yprd, nx, ny,
                                        domain->xperiodic, domain->yperiodic);
  std::vector<runin::tribo::EnvelopeSummit> mine;
  double counts[2] = {0.0, -std::numeric_limits<double>::infinity()};    // members; minus the lowest centre
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      const double w = wear_depth(i);
      // a net deposit (w < 0) raises the whole sphere; wear and flattening cut its top flat
      mine.push_back({x[i][0], x[i][1], sign * x[i][2] + rise(i) - std::min(w, 0.0), radius[i], std::max(w, 0.0)});
      counts[0] += 1.0;
      counts[1] = std::max(counts[1], -mine.back().centre);
    }
  MPI_Allreduce(MPI_IN_PLACE, &counts[0], 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(MPI_IN_PLACE, &counts[1], 1, MPI_DOUBLE, MPI_MAX, world);
  if (!(counts[0] > 0.0)) {
    for (int k = 0; k < NSURFACE; k++) out[k] = 0.0;
    return;
  }
  const double first = 2.0 * std::sqrt(domain->xprd * domain->yprd / counts[0]);
  for (const auto &s : mine) envelope.add(s, first);
  std::vector<double> &z = envelope.heights();
  MPI_Allreduce(MPI_IN_PLACE, z.data(), static_cast<int>(z.size()), MPI_DOUBLE, MPI_MAX, world);
  const double floor = *std::min_element(z.begin(), z.end());    // -inf where the first pass left holes
  for (const auto &s : mine) {
    const double reach = runin::tribo::SummitEnvelope::footprint_above(s, floor);
    if (reach > first) envelope.add(s, reach);
  }
  MPI_Allreduce(MPI_IN_PLACE, z.data(), static_cast<int>(z.size()), MPI_DOUBLE, MPI_MAX, world);
  const runin::tribo::EnvelopeStatistics stats = runin::tribo::envelope_statistics(z, -counts[1]);
  runin_roughness::write_fixed(stats.roughness, out + S_RA);
  out[S_MEAN] = stats.roughness.mean;
  out[S_COVERED] = stats.covered;
}

double ComputeRuninRoughness::mean_height()
{
  const int *mask = atom->mask;
  double local[2] = {0.0, 0.0}, global[2];
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      local[0] += 1.0;
      local[1] += summit(i);
    }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, world);
  return global[0] > 0.0 ? global[1] / global[0] : 0.0;
}

void ComputeRuninRoughness::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(peratom);
    nmax = atom->nmax;
    memory->create(peratom, nmax, NPERATOM, "runin/roughness:peratom");
    array_atom = peratom;
  }
  const double mean = mean_height();
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    const bool member = mask[i] & groupbit;
    peratom[i][HEIGHT] = member ? summit(i) - mean : 0.0;
    peratom[i][WEAR_DEPTH] = member ? wear_depth(i) : 0.0;
  }
}

double ComputeRuninRoughness::memory_usage()
{
  return static_cast<double>(nmax) * NPERATOM * sizeof(double);
}
