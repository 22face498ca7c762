#include "pair_runin_asperity_liggghts.h"
#include "coefficient_grammar.h"

#include "fix_runin_wear_state_liggghts.h"
#include "runin_liggghts_errors.h"
#include "runin_liggghts_material.h"
#include "runin_liggghts_style_maps.h"
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
    Pair(lmp), history_size(tribo::TANGENTIAL_HISTORY_SIZE), dt(0.0), wear_on(true), reshape(true),
    sums_requested(false), body_groupbit(0), computeflag(0), maxrad(nullptr), fix_history(nullptr),
    fix_wear(nullptr)
{
  single_enable = 1;
  // single(): normal force (fforce * del), then the tangential force on i, the contact radius and overlap
  single_extra = 5;
  svector = new double[single_extra];
  no_virial_fdotr_compute = 1;
  restartinfo = 0;
}

PairRuninAsperityLiggghts::~PairRuninAsperityLiggghts()
{
  if (fix_history && modify->find_fix(kHistoryId) >= 0) modify->delete_fix(kHistoryId);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    delete[] maxrad;
  }
  delete[] svector;
}

void PairRuninAsperityLiggghts::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  maxrad = new double[n + 1];
  coeffs.assign((n + 1) * (n + 1), tribo::ContactCoefficients());
}

tribo::ContactCoefficients &PairRuninAsperityLiggghts::coeff_of(int itype, int jtype)
{
  return coeffs[itype * (atom->ntypes + 1) + jtype];
}

void PairRuninAsperityLiggghts::set_sub_model(SubModelKind kind, const std::string &name)
{
  choice.index[static_cast<int>(kind)] = runin_liggghts::kernel_call(
      lmp, FLERR, "pair_style runin/asperity", true, [&] { return tribo::find_sub_model(kind, name); });
  // the film coverage is a per-summit state that only the LAMMPS pair keeps
  if (kind == SubModelKind::friction && tribo::registered_sub_models(kind)[choice.of(kind)].has_film)
    error->all(FLERR, ("pair_style runin/asperity: friction '" + name + "' is not supported in LIGGGHTS (the film "
                       "coverage is kept by the LAMMPS pair only); use a friction model without a film").c_str());
}

bool PairRuninAsperityLiggghts::plastic_normal() const
{
  return tribo::registered_sub_models(SubModelKind::normal)[choice.of(SubModelKind::normal)].flattens_summits;
}

void PairRuninAsperityLiggghts::attach_wear_state()
{
  if (!fix_wear) fix_wear = FixRuninWearStateLiggghts::find_or_create(modify);
}

void PairRuninAsperityLiggghts::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (iarg + 1 >= narg)
      runin_liggghts::all(lmp, FLERR, fmt::format("pair_style runin/asperity: keyword '{}' needs a value", keyword));
    const std::string value = arg[iarg + 1];
    auto yes_no = [&](const char *what) {
      return runin_liggghts::yes_no(lmp, FLERR, value, fmt::format("pair_style runin/asperity: {}", what));
    };
    if (keyword == "wear") {
      wear_on = yes_no("wear");
    } else if (keyword == "archard") {
      if (value == "plain")
        contact_settings.archard_form = tribo::ArchardForm::plain;
      else if (value == "thesis")
        contact_settings.archard_form = tribo::ArchardForm::thesis;
      else
        runin_liggghts::all(lmp, FLERR, fmt::format("pair_style runin/asperity: archard must be 'plain' or "
                                                    "'thesis', got '{}'", value));
    } else if (keyword == "reshape") {
      reshape = yes_no("reshape");
    } else if (keyword == "normal") {
      set_sub_model(SubModelKind::normal, value);
    } else if (keyword == "friction") {
      set_sub_model(SubModelKind::friction, value);
    } else if (keyword == "transfer") {
      const double fraction = runin_liggghts::finite_number(lmp, FLERR, "pair_style runin/asperity",
                                                            "transfer fraction", value.c_str());
      if (!(fraction >= 0.0 && fraction <= 1.0))
        runin_liggghts::all(lmp, FLERR, fmt::format("pair_style runin/asperity: transfer fraction must be in "
                                                    "[0, 1], got '{}'", value));
      contact_settings.transfer_fraction = fraction;
    } else if (keyword == "restick") {
      const double speed = runin_liggghts::finite_number(lmp, FLERR, "pair_style runin/asperity", "restick speed",
                                                         value.c_str());
      if (!(speed >= 0.0))
        runin_liggghts::all(lmp, FLERR, fmt::format("pair_style runin/asperity: restick speed must be >= 0 m/s, "
                                                    "got '{}'", value));
      contact_settings.restick_speed = speed;
    } else {
      runin_liggghts::all(lmp, FLERR,
                          fmt::format("pair_style runin/asperity: unknown keyword '{}' (expected wear, archard, "
                                      "reshape, normal, friction, transfer or restick)", keyword));
    }
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

  const int wanted_history = tribo::contact_history_size_of(choice.of(SubModelKind::normal));
  if (fix_history && wanted_history != history_size)
    runin_liggghts::all(lmp, FLERR, fmt::format("pair runin/asperity: the normal model changed after the first "
                                                "run ({} history values per contact, {} now); define the pair "
                                                "style anew (pair_style none first)", history_size, wanted_history));
  history_size = wanted_history;
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

  sums_requested = false;
  for (int i = 0; i < modify->ncompute; i++)
    if (strcmp(modify->compute[i]->style, "runin/friction") == 0) sums_requested = true;
  sums = RuninContactSums();
}

void PairRuninAsperityLiggghts::init_list(int id, NeighList *ptr)
{
  if (id == 0)
    list = ptr;
  else if (id == 1)
    listgranhistory = ptr;
}

double PairRuninAsperityLiggghts::init_one(int i, int j)
{
  if (!setflag[i][j]) {
    runin_liggghts::kernel_call(lmp, FLERR, fmt::format("pair runin/asperity: mixing types {} {}", i, j), true, [&] {
      coeff_of(i, j) = tribo::mix_coefficients(choice, coeff_of(i, i), coeff_of(j, j));
      coeff_of(j, i) = tribo::swap_bodies(choice, coeff_of(i, j));
    });
  }
  const int n = atom->ntypes + 1;
  runin_liggghts::kernel_call(lmp, FLERR, fmt::format("pair runin/asperity: types {} {}", i, j), true, [&] {
    models[i * n + j].emplace(choice, coeff_of(i, j), contact_settings);
    models[j * n + i].emplace(choice, coeff_of(j, i), contact_settings);
  });
  return maxrad[i] + maxrad[j];
}

void PairRuninAsperityLiggghts::reset_dt()
{
  dt = update->dt;
}

void *PairRuninAsperityLiggghts::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "computeflag") == 0) return &computeflag;
  return nullptr;
}

double PairRuninAsperityLiggghts::memory_usage()
{
  return increments.memory_usage() + static_cast<double>(touching.capacity()) * sizeof(runin_pair::TouchingPair);
}

template <int... Index>
std::array<PairRuninAsperityLiggghts::EvalFunction, sizeof...(Index)> PairRuninAsperityLiggghts::eval_table(
    std::integer_sequence<int, Index...>)
{
  constexpr int NFRICTION = std::tuple_size_v<tribo::FrictionModels>;
  return {{&PairRuninAsperityLiggghts::eval<(Index >> NFLAGS) / NFRICTION, (Index >> NFLAGS) % NFRICTION,
                                            (Index >> 3) & 1, (Index >> 2) & 1, (Index >> 1) & 1, Index & 1>...}};
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

  constexpr int NMODELS = std::tuple_size_v<tribo::NormalModels> * std::tuple_size_v<tribo::FrictionModels>;
  static const auto table = eval_table(std::make_integer_sequence<int, (NMODELS << NFLAGS)>());
  const int models_index = choice.of(SubModelKind::normal) * std::tuple_size_v<tribo::FrictionModels> +
                           choice.of(SubModelKind::friction);
  // Archard wear only with wear yes: the increments of a plastic model without wear carry flattening alone
  const int index = (models_index << NFLAGS) | (wear_on && advance ? 8 : 0) | (worn_geometry ? 4 : 0) |
                    (sums_requested ? 2 : 0) | (evflag ? 1 : 0);
  runin_liggghts::kernel_call(lmp, FLERR, "pair runin/asperity", false, [&] { (this->*table[index])(eflag); });

  if (track_wear) {
    // newton off: every contact of an owned atom was computed here, so its increments are complete
    const int used_up = increments.apply(*fix_wear, atom->radius);
    if (used_up >= 0)
      runin_liggghts::one(lmp, FLERR, runin_pair::used_up_message(
                                          update->ntimestep, atom->tag[used_up],
                                          fix_wear->state()[used_up][FixRuninWearStateLiggghts::WEAR_DEPTH],
                                          atom->radius[used_up]));
  }
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
