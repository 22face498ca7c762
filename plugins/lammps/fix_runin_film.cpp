#include "fix_runin_film.h"

#include "runin_lammps_compat.h"
#include "tribo/surface_film.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "variable.h"
#include "utils.h"

#include <algorithm>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
namespace tribo = runin::tribo;

FixRuninFilm::FixRuninFilm(LAMMPS *lmp, int narg, char **arg) :
    RuninPeratomColumns(lmp, narg, arg, 1, "runin/film:theta"), removal(nullptr)
{
  peratom_flag = 1;
  size_peratom_cols = 0;
  peratom_freq = 1;
  comm_forward = 1;
  comm_reverse = 1;
  forwarded = {0};
  fill = 1.0;    // the coverage of atoms created after this fix

  const char *per_atom = nullptr;    // coverage v_name: an atom-style variable, evaluated once below
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg) error->all(FLERR, "fix RUNIN/FILM: keyword '{}' needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "coverage") != 0)
      error->all(FLERR, "fix RUNIN/FILM: unknown keyword '{}' (expected coverage)", arg[iarg]);
    if (strncmp(arg[iarg + 1], "v_", 2) == 0) {
      per_atom = arg[iarg + 1];
      continue;
    }
    const double value = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (!(value >= 0.0 && value <= 1.0))
      error->all(FLERR, "fix RUNIN/FILM: coverage: film coverage must be in [0, 1], got {}", arg[iarg + 1]);
    fill = value;
  }

  grow_arrays(atom->nmax);    // the removal exposure next to the store's coverage
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
  if (per_atom) {
    // per-atom initial coverage (e.g. one body covered, the other clean); atoms outside the group keep the coverage above
    const int ivar = input->variable->find(per_atom + 2);
    if (ivar < 0 || !input->variable->atomstyle(ivar))
      error->all(FLERR, "fix RUNIN/FILM: coverage needs a number in [0, 1] or an atom-style variable, got '{}'",
                 per_atom);
    std::vector<double> result(atom->nlocal + 1, 0.0);
    input->variable->compute_atom(ivar, igroup, result.data(), 1, 0);
    const int *mask = atom->mask;
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      if (!(result[i] >= 0.0 && result[i] <= 1.0))
        error->one(FLERR, "fix RUNIN/FILM: coverage: film coverage must be in [0, 1], got {} for atom {}", result[i],
                   atom->tag[i]);
      columns[i][0] = result[i];
    }
  }
  attach();
}

FixRuninFilm *FixRuninFilm::find(Modify *modify)
{
  return dynamic_cast<FixRuninFilm *>(runin_compat::fix_by_id(modify, default_id));
}

FixRuninFilm *FixRuninFilm::find_or_create(Modify *modify, double initial_coverage)
{
  if (FixRuninFilm *existing = find(modify)) return existing;
  return dynamic_cast<FixRuninFilm *>(
      modify->add_fix(fmt::format("{} all RUNIN/FILM coverage {:.17g}", default_id, initial_coverage)));
}

FixRuninFilm::~FixRuninFilm()
{
  memory->destroy(removal);
}

void FixRuninFilm::begin_step()
{
  runin_compat::forward_comm(comm, this);
  std::fill(removal, removal + atom->nlocal + atom->nghost, 0.0);
}

void FixRuninFilm::end_step(bool newton, const double *growth)
{
  if (newton) runin_compat::reverse_comm(comm, this);
  const int *type = atom->type;
  double *theta = coverage();
  for (int i = 0; i < atom->nlocal; i++) theta[i] = tribo::FilmKinetics::advance(theta[i], removal[i], growth[type[i]]);
}

void FixRuninFilm::grow_arrays(int nmax)
{
  RuninPeratomColumns::grow_arrays(nmax);
  memory->grow(removal, nmax, "runin/film:removal");
}

int FixRuninFilm::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = removal[first + k];
  return n;
}

void FixRuninFilm::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) removal[list[k]] += buf[k];
}

double FixRuninFilm::memory_usage()
{
  return RuninPeratomColumns::memory_usage() + static_cast<double>(atom->nmax) * sizeof(double);
}
