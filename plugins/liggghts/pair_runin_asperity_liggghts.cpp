#include "pair_runin_asperity_liggghts.h"
#include "coefficient_grammar.h"

#include "fix_runin_wear_state_liggghts.h"
#include "runin_liggghts_errors.h"
#include "runin_liggghts_material.h"
#include "runin_liggghts_style_maps.h"
#include "timestep_guard.h"
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "fix_contact_history.h"
#include "force.h"
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
namespace tribo = runin::tribo;
using tribo::SubModelKind;

namespace {

const char *const kHistoryId = "RUNIN_CONTACT_HISTORY";

// LIGGGHTS's contact history fix (style "contacthistory", which LIGGGHTS's granular neighbour lists look
// for) with this pair in the place of a PairGran: FixContactHistory::init() looks up pair 'gran' only.
class FixRuninContactHistory : public FixContactHistory {
 public:
  FixRuninContactHistory(LAMMPS *lmp, int narg, char **arg) : FixContactHistory(lmp, narg, arg) {}
  void init() override
  {
    if (atom->tag_enable == 0) runin_liggghts::all(lmp, FLERR, "pair runin/asperity: requires atom IDs");
    int dim = 0;
    pair_gran_ = force->pair;
    computeflag_ = force->pair ? static_cast<int *>(force->pair->extract("computeflag", dim)) : nullptr;
    if (!computeflag_)
      runin_liggghts::all(lmp, FLERR, "pair runin/asperity: its contact history fix outlived the pair style");
    allocate_pages();
  }
};

Fix *history_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixRuninContactHistory(lmp, narg, arg);
}

}    // namespace

PairRuninAsperityLiggghts::PairRuninAsperityLiggghts(LAMMPS *lmp) :
    PairStyle(lmp), computeflag(0), fix_history(nullptr)
{
  restartinfo = 0;
}

PairRuninAsperityLiggghts::~PairRuninAsperityLiggghts()
{
  if (fix_history && modify->find_fix(kHistoryId) >= 0) modify->delete_fix(kHistoryId);
  release();
}

void PairRuninAsperityLiggghts::accept_sub_model(SubModelKind kind, const std::string &name, int index)
{
  if (kind == SubModelKind::friction && tribo::registered_sub_models(kind)[index].has_film)
    error->all(FLERR, ("pair_style runin/asperity: friction '" + name + "' is not supported in LIGGGHTS (the film "
                       "coverage is kept by the LAMMPS pair only); use a friction model without a film").c_str());
}

void PairRuninAsperityLiggghts::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (iarg + 1 >= narg)
      runin_liggghts::all(lmp, FLERR, fmt::format("pair_style runin/asperity: keyword '{}' needs a value", keyword));
    const std::string value = arg[iarg + 1];
    if (!setting(keyword, value))
      runin_liggghts::all(lmp, FLERR,
                          fmt::format("pair_style runin/asperity: unknown keyword '{}' (expected wear, archard, "
                                      "reshape, normal, friction, transfer or restick)", keyword));
  }
  if ((wear_on || plastic_normal()) && domain->box_exist) attach_wear_state();
}

// pair_coeff I J <keyword block | explicit values | file ...> [options]: the grammar, checks and messages of the
// LAMMPS pair (plugins/common/coefficient_grammar.h)
void PairRuninAsperityLiggghts::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 2) runin_liggghts::all(lmp, FLERR, "pair_coeff runin/asperity: expected type I and type J");
  runin_liggghts::require_si_units(lmp, FLERR, "pair runin/asperity");

  // no film coverage on this host: the film keywords are unknown
  const runin_coeff::Host host =
      runin_liggghts::coefficient_host(lmp, "pair_coeff runin/asperity", "pair_coeff runin/asperity", false);
  const tribo::ContactCoefficients c = runin_coeff::pair_coeff(host, narg, arg, choice, contact_settings);

  int ilo, ihi, jlo, jhi;
  force->bounds(arg[0], atom->ntypes, ilo, ihi);
  force->bounds(arg[1], atom->ntypes, jlo, jhi);
  runin_coeff::store_type_pairs(host, arg, ilo, ihi, jlo, jhi, choice, c,
                                [this](int i, int j) -> tribo::ContactCoefficients & { return coeff_of(i, j); }, setflag);
}

void PairRuninAsperityLiggghts::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    runin_liggghts::all(lmp, FLERR, "pair runin/asperity: requires atom attributes radius, rmass, omega and "
                                    "torque (atom_style granular or sphere)");
  if (comm->ghost_velocity == 0)
    runin_liggghts::all(lmp, FLERR, "pair runin/asperity: requires ghost velocities (communicate single vel yes)");
  runin_liggghts::require_si_units(lmp, FLERR, "pair runin/asperity");
  if (force->newton_pair)
    runin_liggghts::all(lmp, FLERR, "pair runin/asperity: requires 'newton off' in LIGGGHTS (its contact history "
                                    "keeps no ghost contacts; LAMMPS takes either)");
  dt = update->dt;

  size_history(fix_history != nullptr);
  if (!fix_history) {
    // LIGGGHTS's contact history: the slots of a vector (the Mindlin spring) turn sign when the contact is seen from j
    std::vector<std::string> words = {kHistoryId, "all", "contacthistory", std::to_string(history_size)};
    for (int k = 0; k < history_size; k++) {
      words.push_back(fmt::format("runin_h{}", k));
      words.push_back(tribo::history_flips_with_bodies(k) ? "1" : "0");
    }
    std::vector<char *> args;
    for (auto &w : words) args.push_back(&w[0]);
    auto &map = runin_liggghts::fix_map(modify);
    const auto saved = map["contacthistory"];
    map["contacthistory"] = &history_creator;
    modify->add_fix(static_cast<int>(args.size()), args.data());
    map["contacthistory"] = saved;
    fix_history = dynamic_cast<FixContactHistory *>(modify->fix[modify->find_fix(kHistoryId)]);
  }
  if (wear_on || plastic_normal()) attach_wear_state();

  // a granular list (radius-sized) and its history list, as LIGGGHTS's pair gran requests them
  int irequest = neighbor->request(this);
  neighbor->requests[irequest]->half = 0;
  neighbor->requests[irequest]->gran = 1;
  irequest = neighbor->request(this);
  neighbor->requests[irequest]->id = 1;
  neighbor->requests[irequest]->half = 0;
  neighbor->requests[irequest]->granhistory = 1;
  neighbor->requests[irequest]->dnum = history_size;

  runin_pair::largest_radius_per_type(atom->radius, atom->type, atom->nlocal, atom->ntypes, world, maxrad);
  models.assign(coeffs.size(), std::nullopt);

  increments.release();
  request_sums();

  // the LAMMPS pair's timestep guard (plugins/common/timestep_guard.h): WARNING/ERROR on dt vs the Rayleigh time,
  // ERROR on an atom moving more than its radius per step
  runin_guard::guard_timestep(lmp, "pair runin/asperity", [this](int i, int j) {
    if (!setflag[i][j]) return runin_guard::PairModuli{};
    const tribo::ContactModel model(choice, coeff_of(i, j), contact_settings);
    return runin_guard::PairModuli{model.effective_modulus(), model.effective_shear_modulus()};
  });
}

void PairRuninAsperityLiggghts::init_list(int id, NeighList *ptr)
{
  if (id == 0)
    list = ptr;
  else if (id == 1)
    listgranhistory = ptr;
}

void *PairRuninAsperityLiggghts::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "computeflag") == 0) return &computeflag;
  return nullptr;
}

void PairRuninAsperityLiggghts::compute(int eflag, int vflag)
{
  if (eflag || vflag)
    ev_setup(eflag, vflag);
  else
    evflag = vflag_fdotr = 0;
  computeflag = 1;
  const bool advance = update->setupflag == 0;
  const bool track_wear = (wear_on || (plastic_normal() && reshape)) && advance;

  if (fix_wear && !advance) fix_wear->refresh_geometry_all();
  const bool worn_geometry = reshape && fix_wear;
  if (worn_geometry) fix_wear->forward_geometry(!advance);
  if (track_wear) increments.reserve(atom->nmax);

  evaluate(eflag, advance, worn_geometry);
  // newton off: every contact of an owned atom was computed here, so its increments are complete
  if (track_wear) apply_increments();
}

runin_pair::Atoms<int> PairRuninAsperityLiggghts::loop_atoms() const
{
  return {atom->x,     atom->v,    atom->omega, atom->f,   atom->torque, atom->radius,
          atom->rmass, atom->type, atom->mask,  atom->tag, atom->nlocal};
}

runin_pair::Neighbours PairRuninAsperityLiggghts::neighbours() const
{
  return {list->inum,       list->ilist,
          list->numneigh,   list->firstneigh,
          list->listgranhistory->firstneigh, list->listgranhistory->firstdouble};
}

// One force evaluation: the pass of the LAMMPS pair (pair_contacts.h) on LIGGGHTS's arrays and contact history.
template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG>
void PairRuninAsperityLiggghts::eval(int eflag)
{
  using W = FixRuninWearStateLiggghts;
  const runin_pair::Step step =
      runin_pair::step_of<W>(models.data(), atom->ntypes + 1, dt, update->ntimestep, update->setupflag == 0, false,
                             increments.reserved(), body_groupbit, RESHAPE ? fix_wear->state() : nullptr, atom->nmax);
  // newton off: a ghost's increments and forces belong to its own rank
  runin_pair::PairHost<PairRuninAsperityLiggghts, false> host{*this, increments, atom->nlocal, 0};
  const runin_pair::Outcome outcome = runin_pair::contacts<NORMAL, FRICTION, WEAR, RESHAPE, SUMS, EVFLAG, W>(
      host, loop_atoms(), neighbours(), step, eflag, touching, contact_range);
  if (SUMS) sums = outcome.sums;
  if (!outcome.invalid.empty()) runin_liggghts::one(lmp, FLERR, outcome.invalid);
  if (!std::isfinite(outcome.force_sum))
    runin_liggghts::one(lmp, FLERR, fmt::format("pair runin/asperity: a contact force is not finite at step {} "
                                                "(a coefficient far outside its physical range?)",
                                                update->ntimestep));
}

void PairRuninAsperityLiggghts::report_contact_range()
{
  const std::string warning = contact_range.report(world, "pair runin/asperity");
  if (!warning.empty()) error->warning(FLERR, warning.c_str());
}

// The force of the contact of i and j as the force loop computes it, without changing its history (compute
// group/group). fforce * del is the normal force on i; svector: tangential force on i (3), contact radius, overlap.
double PairRuninAsperityLiggghts::single(int i, int j, int itype, int jtype, double rsq, double, double,
                                         double &fforce)
{
  fforce = 0.0;
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  if (!models[itype * (atom->ntypes + 1) + jtype])
    runin_liggghts::one(lmp, FLERR, "pair runin/asperity: single() before the pair was initialised");
  double **state_rows = fix_wear && reshape ? fix_wear->state() : nullptr;
  const double *state = state_rows ? state_rows[0] : nullptr;
  // this contact's history in i's neighbour list (a copy: single() must not advance it)
  auto history_of = [&](double *history) {
    if (!list || !list->listgranhistory || !list->listgranhistory->firstdouble)
      runin_liggghts::one(lmp, FLERR, "pair runin/asperity: single() needs the contact history (run setup first)");
    runin_pair::copy_history(neighbours(), i, j, history_size, history);
  };
  runin_pair::SingleContact contact;
  runin_liggghts::kernel_call(lmp, FLERR, "pair runin/asperity: single()", false, [&] {
    contact = runin_pair::single_contact<FixRuninWearStateLiggghts>(loop_atoms(), state,
                                                                    *models[itype * (atom->ntypes + 1) + jtype],
                                                                    choice, plastic_normal(), i, j, rsq, history_of);
  });
  return contact.returned(fforce, svector);
}
