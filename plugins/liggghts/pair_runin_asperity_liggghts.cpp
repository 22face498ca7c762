#include "pair_runin_asperity_liggghts.h"

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
    sums_requested(false), body_groupbit(0), computeflag(0), maxrad(nullptr), increment(nullptr),
    nmax_increment(0), worn_owned(nullptr), nworn_owned(0), fix_history(nullptr), fix_wear(nullptr)
{
  single_enable = 0;
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
  memory->destroy(increment);
  memory->destroy(worn_owned);
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
  if (kind == SubModelKind::friction && name == tribo::JunctionFilmFrictionModel::name)
    error->all(FLERR, "pair_style runin/asperity: friction 'junction/film' is not supported in LIGGGHTS (the film "
                      "coverage is kept by the LAMMPS pair only); use 'junction'");
}

bool PairRuninAsperityLiggghts::plastic_normal() const
{
  static const int index = tribo::find_sub_model(SubModelKind::normal, tribo::ElasticPlasticNormalModel::name);
  return choice.of(SubModelKind::normal) == index;
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

// pair_coeff I J E* G* e mu_s mu_k d_c k H [tau_s X] [plough X] [S_y X] [nu X]
// pair_coeff I J file <path> <material-I> <material-J> [the same optional keywords]
void PairRuninAsperityLiggghts::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 2) runin_liggghts::all(lmp, FLERR, "pair_coeff runin/asperity: expected type I and type J");
  const char *where = "pair_coeff runin/asperity";
  runin_liggghts::require_si_units(lmp, FLERR, "pair runin/asperity");

  tribo::ContactParameters p;
  int optional_first = narg;
  const char *origin = "explicit";
  if (narg >= 6 && strcmp(arg[2], "file") == 0) {
    p = runin_liggghts::contact_parameters(
        runin_liggghts::read_material_pair(lmp, arg[3], arg[4], arg[5], where));
    origin = "file";
    optional_first = 6;
  } else if (narg == 10 || (narg > 10 && !runin_liggghts::is_double(arg[10]))) {
    const char *names[] = {"E*", "G*", "e", "mu_s", "mu_k", "d_c", "k", "H"};
    double v[8];
    for (int k = 0; k < 8; k++) v[k] = runin_liggghts::finite_number(lmp, FLERR, where, names[k], arg[2 + k]);
    p.effective_modulus = v[0];
    p.effective_shear_modulus = v[1];
    p.restitution = v[2];
    p.mu_static = v[3];
    p.mu_kinetic = v[4];
    p.slip_weakening_distance = v[5];
    p.wear_coefficient = v[6];
    p.hardness_i = p.hardness_j = v[7];
    p.yield_strength = v[7] / tribo::kTaborConstraintFactor;
    p.yield_from_hardness = true;
    optional_first = 10;
  } else {
    // count the numbers given after the type pair and name the positional values left out
    const char *names[] = {"E*", "G*", "e", "mu_s", "mu_k", "d_c", "k", "H"};
    int given = 0;
    while (2 + given < narg && runin_liggghts::is_double(arg[2 + given])) given++;
    std::string missing;
    for (int k = given; k < 8; k++) missing += fmt::format("{}{}", missing.empty() ? "" : " ", names[k]);
    runin_liggghts::all(lmp, FLERR,
                        fmt::format("pair_coeff runin/asperity: expected 'I J E* G* e mu_s mu_k d_c k H' (8 values "
                                    "after the type pair), got {} value(s){}; or 'I J file <path> <material-I> "
                                    "<material-J>', then optional 'tau_s X' 'plough X' 'S_y X' 'nu X' (the "
                                    "keyword-block form is LAMMPS-only)",
                                    given, given < 8 ? fmt::format(" (missing: {})", missing)
                                                     : fmt::format(" ({} too many)", given - 8)));
  }
  for (int iarg = optional_first; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (keyword == "interface") {
      // the state's friction factor m comes from the coefficient file (contact_coefficients applies it)
      if (iarg + 1 >= narg)
        runin_liggghts::all(lmp, FLERR, fmt::format("pair_coeff runin/asperity: interface needs a state ({})",
                                                    tribo::interface_state_list()));
      p.interface_state = runin_liggghts::kernel_call(lmp, FLERR, where, true,
                                                      [&] { return tribo::find_interface_state(arg[iarg + 1]); });
      continue;
    }
    if (keyword != "tau_s" && keyword != "plough" && keyword != "S_y" && keyword != "nu" && keyword != "f" &&
        keyword != "alpha")
      runin_liggghts::all(lmp, FLERR, fmt::format("pair_coeff runin/asperity: unknown keyword '{}' (expected "
                                                  "tau_s, plough, S_y, nu, f, alpha or interface)", keyword));
    const double value = runin_liggghts::finite_number(lmp, FLERR, where, keyword, iarg + 1 < narg ? arg[iarg + 1] : "");
    if (keyword == "tau_s")
      p.shear_strength = value;
    else if (keyword == "plough")
      p.ploughing_factor = value;
    else if (keyword == "nu")
      p.poisson_ratio = value;
    else if (keyword == "f")
      p.interface_coefficient = value;
    else if (keyword == "alpha")
      p.junction_alpha = value;
    else {
      p.yield_strength = value;
      p.yield_from_hardness = false;
    }
  }
  if (p.yield_from_hardness && plastic_normal() && comm->me == 0)
    error->warning(FLERR, fmt::format("pair_coeff runin/asperity {} {}: no yield strength given (S_y keyword or "
                                      "material file): S_y = H / {} = {:.4g} Pa (Tabor), nu = {}", arg[0], arg[1],
                                      tribo::kTaborConstraintFactor, p.yield_strength, p.poisson_ratio).c_str());
  tribo::ContactCoefficients c;
  runin_liggghts::kernel_call(lmp, FLERR, fmt::format("pair_coeff runin/asperity ({})", origin), true, [&] {
    c = tribo::contact_coefficients(choice, p);
    tribo::ContactModel(choice, c, contact_settings);    // validates every sub-model's coefficients
  });

  int ilo, ihi, jlo, jhi;
  force->bounds(arg[0], atom->ntypes, ilo, ihi);
  force->bounds(arg[1], atom->ntypes, jlo, jhi);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      coeff_of(i, j) = c;
      coeff_of(j, i) = tribo::swap_bodies(choice, c);
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0)
    runin_liggghts::all(lmp, FLERR, fmt::format("pair_coeff runin/asperity: no type pair in range {} {}", arg[0],
                                                arg[1]));
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
    // LIGGGHTS's contact history: values 0-2 (the Mindlin spring) turn sign when the contact is seen from j
    std::vector<std::string> words = {kHistoryId, "all", "contacthistory", std::to_string(history_size)};
    for (int k = 0; k < history_size; k++) {
      words.push_back(fmt::format("runin_h{}", k));
      words.push_back(k <= tribo::HISTORY_SPRING_Z ? "1" : "0");
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

  std::vector<double> local(atom->ntypes + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    local[atom->type[i]] = std::max(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad, atom->ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
  models.assign(coeffs.size(), std::nullopt);

  memory->destroy(increment);
  memory->destroy(worn_owned);
  increment = nullptr;
  worn_owned = nullptr;
  nmax_increment = nworn_owned = 0;

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
  return static_cast<double>(nmax_increment) * (3.0 * sizeof(double) + sizeof(int)) +
         static_cast<double>(touching.capacity()) * sizeof(TouchingPair);
}

template <int... Index>
std::array<PairRuninAsperityLiggghts::EvalFunction, sizeof...(Index)> PairRuninAsperityLiggghts::eval_table(
    std::integer_sequence<int, Index...>)
{
  constexpr int NFRICTION = std::tuple_size_v<tribo::FrictionModels>;
  return {{&PairRuninAsperityLiggghts::eval<(Index >> NFLAGS) / NFRICTION, (Index >> NFLAGS) % NFRICTION,
                                            (Index >> 3) & 1, (Index >> 2) & 1, (Index >> 1) & 1, Index & 1>...}};
}

void PairRuninAsperityLiggghts::grow_increments()
{
  if (atom->nmax <= nmax_increment) return;
  nmax_increment = atom->nmax;
  memory->destroy(increment);
  memory->destroy(worn_owned);
  memory->create(increment, NINCREMENT * nmax_increment, "pair:increment");
  std::fill(increment, increment + NINCREMENT * nmax_increment, 0.0);
  memory->create(worn_owned, nmax_increment + 1, "pair:worn_owned");
  nworn_owned = 0;
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
  if (track_wear) grow_increments();

  constexpr int NMODELS = std::tuple_size_v<tribo::NormalModels> * std::tuple_size_v<tribo::FrictionModels>;
  static const auto table = eval_table(std::make_integer_sequence<int, (NMODELS << NFLAGS)>());
  const int models_index = choice.of(SubModelKind::normal) * std::tuple_size_v<tribo::FrictionModels> +
                           choice.of(SubModelKind::friction);
  const int index = (models_index << NFLAGS) | (track_wear ? 8 : 0) | (worn_geometry ? 4 : 0) |
                    (sums_requested ? 2 : 0) | (evflag ? 1 : 0);
  runin_liggghts::kernel_call(lmp, FLERR, "pair runin/asperity", false, [&] { (this->*table[index])(eflag); });

  if (track_wear) {
    // newton off: every contact of an owned atom was computed here, so its increments are complete
    double **state = fix_wear->state();
    const double *radius = atom->radius;
    using W = FixRuninWearStateLiggghts;
    for (int k = 0; k < nworn_owned; k++) {
      const int i = worn_owned[k];
      double *inc = &increment[NINCREMENT * i];
      state[i][W::VOLUME_LOST] += inc[INC_LOST];
      state[i][W::VOLUME_GAINED] += inc[INC_GAINED];
      if (inc[INC_FLATTENED] > 0.0)
        state[i][W::VOLUME_FLATTENED] +=
            W::flattened_volume(radius[i], state[i][W::WEAR_DEPTH], inc[INC_FLATTENED]);
      inc[INC_LOST] = inc[INC_GAINED] = inc[INC_FLATTENED] = 0.0;
      fix_wear->refresh_geometry(i, radius[i]);
      if (state[i][W::WEAR_DEPTH] > radius[i])
        runin_liggghts::one(lmp, FLERR,
                            fmt::format("pair runin/asperity: at step {} the summit of atom {} has been worn or "
                                        "flattened by {:.4g} m, more than its radius {:.4g} m (the asperity is used "
                                        "up): load or wear coefficient too large",
                                        update->ntimestep, atom->tag[i], state[i][W::WEAR_DEPTH], radius[i]));
    }
    nworn_owned = 0;
  }
}

// The geometry of one contact: the arithmetic of PairRuninAsperity::contact_geometry (plugins/lammps), term
// for term, so both hosts hand the contact model the same numbers.
tribo::ContactGeometry PairRuninAsperityLiggghts::contact_geometry(int i, int j, double overlap, double rinv,
                                                                   const double *del, double flat) const
{
  double **v = atom->v, **omega = atom->omega;
  const double *radius = atom->radius, *rmass = atom->rmass;
  tribo::ContactGeometry g;
  const double radi = radius[i], radj = radius[j];
  const double radsum = radi + radj;
  g.overlap = overlap;
  g.flat_radius = flat;
  for (int k = 0; k < 3; k++) g.normal[k] = del[k] * rinv;
  const double mass_sum = rmass[i] + rmass[j];
  const double inv_sums = 1.0 / (mass_sum * radsum);
  g.effective_mass = rmass[i] * rmass[j] * radsum * inv_sums;
  g.effective_radius = radi * radj * mass_sum * inv_sums;
  const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
  g.normal_velocity = MathExtra::dot3(vr, g.normal);
  const double spin[3] = {radi * omega[i][0] + radj * omega[j][0], radi * omega[i][1] + radj * omega[j][1],
                          radi * omega[i][2] + radj * omega[j][2]};
  double spin_velocity[3];
  MathExtra::cross3(g.normal, spin, spin_velocity);
  for (int k = 0; k < 3; k++) g.tangential_velocity[k] = vr[k] - g.normal_velocity * g.normal[k] + spin_velocity[k];
  return g;
}

template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG>
void PairRuninAsperityLiggghts::eval(int eflag)
{
  const bool advance = update->setupflag == 0;
  double **state_rows = RESHAPE ? fix_wear->state() : nullptr;
  const double *state = state_rows && atom->nmax > 0 ? state_rows[0] : nullptr;
  using W = FixRuninWearStateLiggghts;
  constexpr int NCOL = W::NCOLUMNS;
  constexpr int DEPTH = W::WEAR_DEPTH, FLAT = W::FLAT_RADIUS, FLATTENED = W::VOLUME_FLATTENED;
  double **x = atom->x, **f = atom->f;
  double **torque = atom->torque;
  const double *radius = atom->radius;
  const int *type = atom->type, *mask = atom->mask;
  const int body_bit = body_groupbit;
  const int *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int ntypes1 = atom->ntypes + 1;
  const double step_dt = dt;
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  const std::optional<tribo::ContactModel> *const model_table = models.data();
  constexpr int HISTORY = tribo::contact_history_size<NORMAL>;
  constexpr bool PLASTIC_MODEL =
      std::is_same_v<std::tuple_element_t<NORMAL, tribo::NormalModels>, tribo::ElasticPlasticNormalModel>;
  const bool PLASTIC = PLASTIC_MODEL && RESHAPE && advance && increment != nullptr;
  RuninContactSums local_sums;
  double force_sum = 0.0;
  int invalid_contact = -1;
  double invalid_force = 0.0;

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = list->listgranhistory->firstneigh;
  double **firsthistory = list->listgranhistory->firstdouble;

  auto wear_depth = [state](int k) { return RESHAPE ? state[NCOL * k + DEPTH] : 0.0; };
  auto summit_reach = [](double radi, double radj, double depth_i, double depth_j) {
    return radi + radj - (depth_i + depth_j);
  };

  // pass 1: the touching pairs; pairs that separated lose their history
  int ntouching = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int jnum = numneigh[i];
    if (jnum == 0) continue;
    if (ntouching + jnum > static_cast<int>(touching.size())) touching.resize(2 * (ntouching + jnum));
    TouchingPair *out = touching.data();
    const double xi[3] = {x[i][0], x[i][1], x[i][2]};
    const double radi = radius[i];
    const double depth_i = wear_depth(i);
    int *touch = firsttouch[i];
    double *allhistory = firsthistory[i];
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double del[3] = {xi[0] - x[j][0], xi[1] - x[j][1], xi[2] - x[j][2]};
      const double rsq = MathExtra::dot3(del, del);
      const double reach = summit_reach(radi, radius[j], depth_i, wear_depth(j));
      const bool in_contact = (!RESHAPE || reach > 0.0) && rsq < reach * reach;
      out[ntouching] = {i, j, &allhistory[HISTORY * jj]};
      ntouching += in_contact;
      if (touch[jj] && !in_contact)
        for (int k = 0; k < HISTORY; k++) allhistory[HISTORY * jj + k] = 0.0;
      touch[jj] = in_contact;
    }
  }

  // pass 2: the contact forces
  for (int c = 0; c < ntouching; c++) {
    const int i = touching[c].i, j = touching[c].j;
    double *history = touching[c].history;
    const int itype = type[i];
    const double radi = radius[i], radj = radius[j];
    const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
    const double rsq = MathExtra::dot3(del, del);
    const double reach = summit_reach(radi, radj, wear_depth(i), wear_depth(j));
    const int jtype = type[j];
    const tribo::ContactModel &model = *model_table[itype * ntypes1 + jtype];
    const double r = std::sqrt(rsq);
    const double rinv = 1.0 / r;
    const double flat =
        RESHAPE ? tribo::combined_flat_radius(state[NCOL * i + FLAT], state[NCOL * j + FLAT]) : 0.0;
    tribo::ContactGeometry g = contact_geometry(i, j, reach - r, rinv, del, flat);
    if (RESHAPE) g.summit_drop = std::max(wear_depth(i), 0.0) + std::max(wear_depth(j), 0.0);
    // a new contact of flattened summits is a reload: the model restores the state that flattened them
    // (PairRuninAsperity::flattened_drop, the same sum)
    if (PLASTIC_MODEL && RESHAPE && g.summit_drop > 0.0 && !(history[tribo::HISTORY_MAX_OVERLAP] > 0.0))
      g.flattened_drop = tribo::flattened_part_of_drop(radi, state[NCOL * i + DEPTH], state[NCOL * i + FLATTENED]) +
                         tribo::flattened_part_of_drop(radj, state[NCOL * j + DEPTH], state[NCOL * j + FLATTENED]);
    const double smaller_radius = std::min(radi, radj);
    const tribo::ContactResult contact = model.evaluate<NORMAL, FRICTION, WEAR>(g, history, step_dt, advance);
    const double fn = contact.normal_force;
    const double *ft = contact.tangential.force;
    const double *normal = g.normal;
    const bool invalid =
        (std::max(g.overlap + g.summit_drop, std::fabs(g.normal_velocity) * step_dt) > smaller_radius) |
        (fn * step_dt * step_dt > smaller_radius * g.effective_mass);
    const bool first_invalid = invalid & (invalid_contact < 0);
    invalid_contact = first_invalid ? c : invalid_contact;
    invalid_force = first_invalid ? fn : invalid_force;

    const double fpair[3] = {fn * normal[0] + ft[0], fn * normal[1] + ft[1], fn * normal[2] + ft[2]};
    force_sum += fpair[0] + fpair[1] + fpair[2];
    double tor[3];
    MathExtra::cross3(normal, ft, tor);
    const bool j_here = j < nlocal;    // newton off
    const double arm_i = radi - 0.5 * g.overlap, arm_j = radj - 0.5 * g.overlap;
    for (int k = 0; k < 3; k++) {
      f[i][k] += fpair[k];
      torque[i][k] -= arm_i * tor[k];
    }
    if (j_here)
      for (int k = 0; k < 3; k++) {
        f[j][k] -= fpair[k];
        torque[j][k] -= arm_j * tor[k];
      }

    const double weight = SUMS && !j_here ? 0.5 : 1.0;
    if (SUMS) {
      const bool j_is_counter = jtype > itype || (jtype == itype && tag[j] > tag[i]);
      const double orient = j_is_counter ? -weight : weight;
      local_sums.normal_force += weight * fn;
      for (int k = 0; k < 3; k++) local_sums.tangential_force[k] += orient * ft[k];
      local_sums.contacts += weight;
      if (!contact.tangential.slipping) local_sums.sticking_contacts += weight;
      local_sums.contact_area += weight * contact.normal.real_area;
      local_sums.adhesion_force += weight * contact.strength.adhesion;
      local_sums.ploughing_force += weight * contact.strength.ploughing;
      local_sums.frictional_power +=
          weight * contact.tangential.force_magnitude * contact.tangential.slip_increment * inv_dt;
      const int side = ((mask[i] & body_bit) != 0) - ((mask[j] & body_bit) != 0);
      for (int k = 0; k < 3; k++) local_sums.body_force[k] += side * weight * fpair[k];
    }

    if (PLASTIC && contact.normal.residual_increment > 0.0) {
      const double share_i = model.flattening_share_i();
      add_flattening(i, share_i * contact.normal.residual_increment, nlocal);
      if (j_here) add_flattening(j, (1.0 - share_i) * contact.normal.residual_increment, nlocal);
    }
    if (WEAR && contact.tangential.slip_increment > 0.0) {
      const tribo::WearExchange &exchange = contact.wear;
      add_wear(i, exchange.lost_a, exchange.gained_a, nlocal);
      if (j_here) add_wear(j, exchange.lost_b, exchange.gained_b, nlocal);
      force_sum += exchange.lost_a + exchange.lost_b;
      if (SUMS) local_sums.wear_volume += weight * contact.worn_volume;
    }

    if (EVFLAG) {
      const double energy = eflag ? model.elastic_energy<NORMAL>(g, history) : 0.0;
      ev_tally_xyz(i, j, nlocal, 0, energy, 0.0, fpair[0], fpair[1], fpair[2], del[0], del[1], del[2]);
    }
  }

  if (SUMS) sums = local_sums;
  if (invalid_contact >= 0) {
    const int i = touching[invalid_contact].i, j = touching[invalid_contact].j;
    runin_liggghts::one(lmp, FLERR,
                        fmt::format("pair runin/asperity: at step {} atoms {} and {} interfere past the centre of "
                                    "the smaller summit, or close or are pushed apart by more than its radius in "
                                    "one step (normal force {:.4g} N): load, speed or timestep too large",
                                    update->ntimestep, tag[i], tag[j], invalid_force));
  }
  if (!std::isfinite(force_sum))
    runin_liggghts::one(lmp, FLERR, fmt::format("pair runin/asperity: a contact force is not finite at step {} "
                                                "(a coefficient far outside its physical range?)",
                                                update->ntimestep));
}
