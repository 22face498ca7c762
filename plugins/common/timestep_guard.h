// The timestep guard at setup of pair runin/asperity and fix runin/wall on both hosts: update->dt against the
// smallest Rayleigh time of the asperities (runin::tribo, src/tribo/stability.h) and each atom's step against its
// radius. Messages go through the host's runin_host_api.h; the LAMMPS host adds its per-step finite-force check
// (plugins/lammps/runin_timestep_guard.h).
#pragma once

#include "runin_host_api.h"
#include "tribo/stability.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "update.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace runin_guard {

struct PairModuli {
  double effective_modulus = 0.0;          // E* [Pa], 0 if the type pair is not set
  double effective_shear_modulus = 0.0;    // G* [Pa]
};

// The smallest Rayleigh time of the contact-capable type pairs and where it is (infinite: no atoms).
struct RayleighLimit {
  double t_rayleigh = std::numeric_limits<double>::infinity();
  double t_cfl = std::numeric_limits<double>::infinity();    // thesis eq. 2.1 with h = 2R, beta = 1: reported beside it
  int worst_i = 0, worst_j = 0;
};

// The largest |v| dt / radius of the group (once per run): above 1, ERROR naming the atom.
inline void guard_displacement(LAMMPS_NS::LAMMPS *lmp, const char *style, int groupbit)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  const double dt = lmp->update->dt;
  struct {
    double ratio;
    int rank;
  } mine{0.0, lmp->comm->me}, worst{};
  int culprit = -1;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || !(atom->radius[i] > 0.0)) continue;
    const double *v = atom->v[i];
    const double ratio = std::hypot(v[0], v[1], v[2]) * dt / atom->radius[i];
    if (!(ratio <= mine.ratio)) {    // NaN too: it counts as infinitely fast
      mine.ratio = std::isnan(ratio) ? std::numeric_limits<double>::infinity() : ratio;
      culprit = i;
    }
  }
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, lmp->world);
  if (!(worst.ratio > 1.0)) return;
  double info[3] = {0.0, 0.0, 0.0};    // atom ID, speed, radius, from the rank that holds it
  if (lmp->comm->me == worst.rank) {
    const double *v = atom->v[culprit];
    info[0] = static_cast<double>(atom->tag[culprit]);
    info[1] = std::hypot(v[0], v[1], v[2]);
    info[2] = atom->radius[culprit];
  }
  MPI_Bcast(info, 3, MPI_DOUBLE, worst.rank, lmp->world);
  const long long step = lmp->update->ntimestep;
  if (!std::isfinite(info[1]))
    runin_host::all(lmp, FLERR, fmt::format("{}: at step {} atom {:.0f} has a velocity that is not finite ({} m/s)",
                                            style, step, info[0], info[1]));
  runin_host::all(lmp, FLERR, fmt::format("{}: at step {} atom {:.0f} moves {:.4g} m per step (speed {:.4g} m/s, "
                                          "dt = {} s), more than its radius {:.4g} m: contacts are not resolved in "
                                          "time (lower the velocity or the timestep)",
                                          style, step, info[0], info[1] * dt, info[1], dt, info[2]));
}

// The dt check (positive, finite), the displacement check of the atoms of `groupbit`, then the smallest Rayleigh
// time over the type pairs with E* > 0 (radius and density per atom from radius/rmass, G and nu from the pair's E*
// and G*). Collective.
inline RayleighLimit rayleigh_limit(LAMMPS_NS::LAMMPS *lmp, const char *style,
                                    const std::function<PairModuli(int, int)> &moduli_of, int groupbit)
{
  namespace tribo = runin::tribo;
  if (!(lmp->update->dt > 0.0) || !std::isfinite(lmp->update->dt))
    runin_host::all(lmp, FLERR, fmt::format("{}: timestep {} s must be positive and finite", style, lmp->update->dt));
  LAMMPS_NS::Atom *atom = lmp->atom;
  guard_displacement(lmp, style, groupbit);
  const int ntypes = atom->ntypes;
  const double inf = std::numeric_limits<double>::infinity();
  // per type: smallest radius and smallest density (both shorten the Rayleigh time)
  std::vector<double> local(2 * (ntypes + 1), inf), global(2 * (ntypes + 1), inf);
  for (int i = 0; i < atom->nlocal; i++) {
    const double r = atom->radius[i];
    if (!(r > 0.0)) continue;
    const double density = atom->rmass[i] / (4.0 / 3.0 * M_PI * r * r * r);
    local[2 * atom->type[i]] = std::min(local[2 * atom->type[i]], r);
    local[2 * atom->type[i] + 1] = std::min(local[2 * atom->type[i] + 1], density);
  }
  MPI_Allreduce(local.data(), global.data(), 2 * (ntypes + 1), MPI_DOUBLE, MPI_MIN, lmp->world);

  RayleighLimit limit;
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++) {
      const PairModuli moduli = moduli_of(i, j);
      if (!(moduli.effective_modulus > 0.0)) continue;
      // every rank sees the same moduli and reduced radii: a failure is collective
      const std::string where = fmt::format("{}: timestep guard for types {} {} (E* = {:.4g}, G* = {:.4g})", style, i,
                                            j, moduli.effective_modulus, moduli.effective_shear_modulus);
      runin_host::kernel_call(lmp, FLERR, where, true, [&] {
        const tribo::Material equivalent =
            tribo::equivalent_material(moduli.effective_modulus, moduli.effective_shear_modulus, 0.3);
        for (int t : {i, j}) {
          if (global[2 * t] == inf) continue;    // no atoms of this type
          const double time = tribo::rayleigh_time(global[2 * t], equivalent, global[2 * t + 1]);
          if (time < limit.t_rayleigh) limit.t_rayleigh = time, limit.worst_i = i, limit.worst_j = j;
          limit.t_cfl = std::min(limit.t_cfl, tribo::cfl_time_step(2.0 * global[2 * t], equivalent.youngs_modulus,
                                                                   global[2 * t + 1]));
        }
      });
    }
  return limit;
}

// update->dt against the limit: WARNING above TimeStepPolicy::warn_fraction t_R, ERROR above fail_factor t_R.
// Returns the smallest Rayleigh time (0 if there are no atoms).
inline double judge(LAMMPS_NS::LAMMPS *lmp, const char *style, const RayleighLimit &limit)
{
  namespace tribo = runin::tribo;
  const double t_rayleigh = limit.t_rayleigh;
  if (t_rayleigh == std::numeric_limits<double>::infinity()) return 0.0;
  const double dt = lmp->update->dt;
  using Policy = tribo::TimeStepPolicy;
  switch (tribo::judge_time_step(dt, t_rayleigh)) {
    case tribo::TimeStepVerdict::fail:
      runin_host::all(lmp, FLERR,
                      fmt::format("{}: timestep {:.4g} s is {:.3g} x the Rayleigh time {:.4g} s (types {} {}); "
                                  "explicit integration diverges above {} x, use a timestep <= {:.4g} s",
                                  style, dt, dt / t_rayleigh, t_rayleigh, limit.worst_i, limit.worst_j,
                                  Policy::fail_factor, Policy::warn_fraction * t_rayleigh));
    case tribo::TimeStepVerdict::warn:
      if (lmp->comm->me == 0) {
        const std::string warning =
            fmt::format("{}: timestep {:.4g} s exceeds the critical timestep {:.4g} s ({} x the Rayleigh time {:.4g} "
                        "s, types {} {}; CFL limit of thesis eq. 2.1 with h = 2R: {:.4g} s)",
                        style, dt, Policy::warn_fraction * t_rayleigh, Policy::warn_fraction, t_rayleigh,
                        limit.worst_i, limit.worst_j, limit.t_cfl);
        lmp->error->warning(FLERR, warning.c_str());
      }
      break;
    case tribo::TimeStepVerdict::ok:
      break;
  }
  return t_rayleigh;
}

// The whole guard (a host with no per-step check of its own to install between the two halves).
inline double guard_timestep(LAMMPS_NS::LAMMPS *lmp, const char *style,
                             const std::function<PairModuli(int, int)> &moduli_of, int groupbit = 1)
{
  return judge(lmp, style, rayleigh_limit(lmp, style, moduli_of, groupbit));
}

// fix runin/wall's moduli: the wall's E* and G* for each atom type present in its group (collective), no type pairs.
inline std::function<PairModuli(int, int)> wall_moduli(LAMMPS_NS::LAMMPS *lmp, int groupbit, double effective_modulus,
                                                       double effective_shear_modulus)
{
  LAMMPS_NS::Atom *atom = lmp->atom;
  const int ntypes = atom->ntypes;
  std::vector<int> local(ntypes + 1, 0), in_group(ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local[atom->type[i]] = 1;
  MPI_Allreduce(local.data(), in_group.data(), ntypes + 1, MPI_INT, MPI_MAX, lmp->world);
  return [in_group, effective_modulus, effective_shear_modulus](int i, int j) {
    return i == j && in_group[i] ? PairModuli{effective_modulus, effective_shear_modulus} : PairModuli{};
  };
}

}    // namespace runin_guard
