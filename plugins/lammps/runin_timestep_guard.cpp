#include "runin_timestep_guard.h"
#include "runin_errors.h"
#include "runin_lammps_compat.h"

#include "tribo/stability.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace LAMMPS_NS;
namespace tribo = runin::tribo;

FixRuninFiniteCheck::FixRuninFiniteCheck(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {}

int FixRuninFiniteCheck::setmask()
{
  return FixConst::PRE_REVERSE;
}

void FixRuninFiniteCheck::init()
{
  pair_checks_itself = force->pair && dynamic_cast<runin_lammps::FiniteForcePair *>(force->pair) &&
                       force->pair->compute_flag && !force->bond && !force->angle && !force->dihedral &&
                       !force->improper && !force->kspace;
}

void FixRuninFiniteCheck::setup_pre_reverse(int, int)
{
  if (!pair_checks_itself) check();
}

void FixRuninFiniteCheck::pre_reverse(int, int)
{
  if (!pair_checks_itself) check();
}

// the pair has no end-of-run hook of its own
void FixRuninFiniteCheck::post_run()
{
  if (auto *pair = dynamic_cast<runin_lammps::FiniteForcePair *>(force->pair)) {
    const std::string warning = pair->contact_range.report(world, fmt::format("pair {}", force->pair_style));
    if (!warning.empty()) error->warning(FLERR, warning);
  }
}

namespace {

constexpr int kShown = 4;

// Sorted IDs (at most kShown) of the owned and ghost atoms of this rank whose force is not finite.
std::vector<tagint> non_finite_atoms(Atom *atom)
{
  double **f = atom->f;
  const int nall = atom->nlocal + atom->nghost;
  std::vector<tagint> bad;
  for (int i = 0; i < nall; i++)
    if (!std::isfinite(f[i][0] + f[i][1] + f[i][2])) bad.push_back(atom->tag[i]);
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  if (bad.size() > static_cast<size_t>(kShown)) bad.resize(kShown);
  return bad;
}

std::string non_finite_message(LAMMPS *lmp, const std::string &style, const std::vector<tagint> &ids)
{
  std::string list;
  for (tagint id : ids) list += fmt::format(" {}", id);
  return fmt::format("{}: non-finite force at step {} on atoms{}; the run is unstable (coincident atoms or "
                     "a timestep too large: dt = {} s)", style, lmp->update->ntimestep, list, lmp->update->dt);
}

}    // namespace

void FixRuninFiniteCheck::check()
{
  double **f = atom->f;
  const int nall = atom->nlocal + atom->nghost;
  // one pass of sums (NaN and inf propagate); the per-atom pass runs only when it is not finite
  double total = 0.0;
  for (int i = 0; i < nall; i++) total += f[i][0] + f[i][1] + f[i][2];
  std::vector<tagint> bad;
  if (!std::isfinite(total)) bad = non_finite_atoms(atom);
  int anywhere = bad.empty() ? 0 : 1;
  if (comm->nprocs > 1) {
    const int here = anywhere;
    MPI_Allreduce(&here, &anywhere, 1, MPI_INT, MPI_MAX, world);
  }
  if (!anywhere) return;

  bad.resize(kShown, std::numeric_limits<tagint>::max());
  std::vector<tagint> all(static_cast<size_t>(kShown) * comm->nprocs);
  MPI_Allgather(bad.data(), kShown, MPI_LMP_TAGINT, all.data(), kShown, MPI_LMP_TAGINT, world);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  all.erase(std::remove(all.begin(), all.end(), std::numeric_limits<tagint>::max()), all.end());
  if (all.size() > static_cast<size_t>(kShown)) all.resize(kShown);
  error->all(FLERR, non_finite_message(lmp, style_label, all));
}

namespace runin_lammps {

namespace {
// The largest |v| dt / radius of the group (once per run): above 1, ERROR naming the atom.
void guard_displacement(LAMMPS *lmp, const char *style, int groupbit)
{
  Atom *atom = lmp->atom;
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
  if (!std::isfinite(info[1]))
    lmp->error->all(FLERR, fmt::format("{}: at step {} atom {:.0f} has a velocity that is not finite ({} m/s)", style,
                                       lmp->update->ntimestep, info[0], info[1]));
  lmp->error->all(FLERR, fmt::format("{}: at step {} atom {:.0f} moves {:.4g} m per step (speed {:.4g} m/s, dt = {} s), "
                                     "more than its radius {:.4g} m: contacts are not resolved in time (lower the "
                                     "velocity or the timestep)", style, lmp->update->ntimestep, info[0],
                                     info[1] * dt, info[1], dt, info[2]));
}
}    // namespace

void stop_on_non_finite_force(LAMMPS *lmp, const std::string &style)
{
  const std::string message = non_finite_message(lmp, style, non_finite_atoms(lmp->atom));
  if (lmp->comm->nprocs == 1)
    lmp->error->all(FLERR, message);
  else
    lmp->error->one(FLERR, message);
}

double guard_timestep(LAMMPS *lmp, const char *style, const std::function<PairModuli(int, int)> &moduli_of,
                      int groupbit)
{
  if (!(lmp->update->dt > 0.0) || !std::isfinite(lmp->update->dt))
    lmp->error->all(FLERR, fmt::format("{}: timestep {} s must be positive and finite", style, lmp->update->dt));
  Atom *atom = lmp->atom;
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

  double t_rayleigh = inf;
  double t_cfl = inf;    // thesis eq. 2.1 with h = 2R, beta = 1: reported beside the Rayleigh limit
  int worst_i = 0, worst_j = 0;
  for (int i = 1; i <= ntypes; i++)
    for (int j = i; j <= ntypes; j++) {
      const PairModuli moduli = moduli_of(i, j);
      if (!(moduli.effective_modulus > 0.0)) continue;
      // every rank sees the same moduli and reduced radii: a failure is collective
      const std::string where = fmt::format("{}: timestep guard for types {} {} (E* = {:.4g}, G* = {:.4g})", style, i, j,
                                            moduli.effective_modulus, moduli.effective_shear_modulus);
      runin_lammps::kernel_call(lmp, FLERR, where, true, [&] {
        const tribo::Material equivalent =
            tribo::equivalent_material(moduli.effective_modulus, moduli.effective_shear_modulus, 0.3);
        for (int t : {i, j}) {
          if (global[2 * t] == inf) continue;    // no atoms of this type
          const double time = tribo::rayleigh_time(global[2 * t], equivalent, global[2 * t + 1]);
          if (time < t_rayleigh) t_rayleigh = time, worst_i = i, worst_j = j;
          t_cfl = std::min(t_cfl,
                           tribo::cfl_time_step(2.0 * global[2 * t], equivalent.youngs_modulus, global[2 * t + 1]));
        }
      });
    }

  if (!runin_compat::fix_by_id(lmp->modify, LAMMPS_NS::FixRuninFiniteCheck::default_id)) {
    auto *fix = dynamic_cast<LAMMPS_NS::FixRuninFiniteCheck *>(lmp->modify->add_fix(
        fmt::format("{} all RUNIN/FINITE_CHECK", LAMMPS_NS::FixRuninFiniteCheck::default_id)));
    if (fix) fix->style_label = style;
  }
  if (t_rayleigh == inf) return 0.0;

  const double dt = lmp->update->dt;
  using Policy = tribo::TimeStepPolicy;
  switch (tribo::judge_time_step(dt, t_rayleigh)) {
    case tribo::TimeStepVerdict::fail:
      lmp->error->all(FLERR, "{}: timestep {:.4g} s is {:.3g} x the Rayleigh time {:.4g} s (types {} {}); explicit "
                      "integration diverges above {} x, use a timestep <= {:.4g} s",
                      style, dt, dt / t_rayleigh, t_rayleigh, worst_i, worst_j, Policy::fail_factor,
                      Policy::warn_fraction * t_rayleigh);
      break;
    case tribo::TimeStepVerdict::warn:
      if (lmp->comm->me == 0)
        lmp->error->warning(FLERR, "{}: timestep {:.4g} s exceeds the critical timestep {:.4g} s ({} x the Rayleigh "
                            "time {:.4g} s, types {} {}; CFL limit of thesis eq. 2.1 with h = 2R: {:.4g} s)",
                            style, dt, Policy::warn_fraction * t_rayleigh, Policy::warn_fraction, t_rayleigh,
                            worst_i, worst_j, t_cfl);
      break;
    case tribo::TimeStepVerdict::ok:
      break;
  }
  return t_rayleigh;
}

}    // namespace runin_lammps
