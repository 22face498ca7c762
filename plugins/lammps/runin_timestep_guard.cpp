#include "runin_timestep_guard.h"
#include "runin_errors.h"
#include "runin_lammps_compat.h"

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
  const runin_guard::RayleighLimit limit = runin_guard::rayleigh_limit(lmp, style, moduli_of, groupbit);
  if (!runin_compat::fix_by_id(lmp->modify, LAMMPS_NS::FixRuninFiniteCheck::default_id)) {
    auto *fix = dynamic_cast<LAMMPS_NS::FixRuninFiniteCheck *>(lmp->modify->add_fix(
        fmt::format("{} all RUNIN/FINITE_CHECK", LAMMPS_NS::FixRuninFiniteCheck::default_id)));
    if (fix) fix->style_label = style;
  }
  return runin_guard::judge(lmp, style, limit);
}

}    // namespace runin_lammps
