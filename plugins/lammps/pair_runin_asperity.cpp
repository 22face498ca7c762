#include "pair_runin_asperity.h"

#include "fix_runin_wear_state.h"
#include "runin_lammps_compat.h"
#include "runin_material_file.h"
#include "runin_timestep_guard.h"    // timestep guard hook, finite-force check
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "fix_dummy.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using MathConst::MY_PI;
namespace tribo = runin::tribo;

namespace {

const char *const kDummyId = "NEIGH_HISTORY_RUNIN_DUMMY";
const char *const kHistoryId = "NEIGH_HISTORY_RUNIN";

using TypePairModel = PairRuninAsperity::TypePairModel;

TypePairModel make_model(const PairRuninAsperity::Coefficients &c, tribo::ArchardForm form, double transfer)
{
  tribo::HertzNormal(c.effective_modulus, 1.0);    // validates E*
  if (!(c.effective_shear_modulus > 0.0))
    throw tribo::InvalidCoefficient("G*: effective shear modulus must be > 0");
  if (!(c.hardness_j > 0.0)) throw tribo::InvalidCoefficient("H: hardness must be > 0");
  const double softer = std::min(c.hardness_i, c.hardness_j);
  return TypePairModel{c.effective_modulus,
                       c.effective_shear_modulus,
                       tribo::RestitutionDamping(c.restitution),
                       tribo::StaticKineticFriction(c.mu_static, c.mu_kinetic, c.slip_weakening_distance),
                       tribo::ArchardWear(c.wear_coefficient, softer, form),
                       tribo::AdhesionPloughing(c.shear_strength, c.ploughing_factor),
                       tribo::WearExchangeRule(tribo::wear_share(c.hardness_i, c.hardness_j), transfer)};
}

inline double dot(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline void cross(const double *a, const double *b, double *out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

}    // namespace

PairRuninAsperity::PairRuninAsperity(LAMMPS *lmp) :
    Pair(lmp), dt(0.0), wear_on(true), reshape(true), archard_form(tribo::ArchardForm::plain),
    friction_model(FrictionModel::coulomb), transfer_fraction(0.0), restick_speed(0.0), sums_requested(false),
    increment(nullptr), nmax_increment(0), worn_owned(nullptr), worn_ghost(nullptr), nworn_owned(0),
    nworn_ghost(0), maxrad(nullptr), fix_history(nullptr), fix_wear(nullptr)
{
  single_enable = 0;
  no_virial_fdotr_compute = 1;
  finitecutflag = 1;
  restartinfo = 1;
  comm_reverse = 2;    // wear and transfer increments (1 without transfer, set at init)
  // slip distance is a scalar: do not negate it when LAMMPS swaps i and j
  nondefault_history_transfer = 1;
  beyond_contact = 0;

  // placeholder keeps the history fix at this position in the fix list (as GRANULAR does)
  fix_dummy = dynamic_cast<FixDummy *>(modify->add_fix(std::string(kDummyId) + " all DUMMY"));
}

PairRuninAsperity::~PairRuninAsperity()
{
  if (copymode) return;
  if (fix_history)
    modify->delete_fix(kHistoryId);
  else if (modify->find_fix(kDummyId) >= 0)
    modify->delete_fix(kDummyId);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    delete[] maxrad;
  }
  memory->destroy(increment);
  memory->destroy(worn_owned);
  memory->destroy(worn_ghost);
}

void PairRuninAsperity::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  maxrad = new double[n + 1];
  coeffs.assign((n + 1) * (n + 1), Coefficients());
}

PairRuninAsperity::Coefficients PairRuninAsperity::Coefficients::unpack(const double *v)
{
  Coefficients c;
  c.effective_modulus = v[0];
  c.effective_shear_modulus = v[1];
  c.restitution = v[2];
  c.mu_static = v[3];
  c.mu_kinetic = v[4];
  c.slip_weakening_distance = v[5];
  c.wear_coefficient = v[6];
  c.hardness_i = v[7];
  c.hardness_j = v[8];
  return c;
}

PairRuninAsperity::Coefficients &PairRuninAsperity::coeff_of(int itype, int jtype)
{
  return coeffs[itype * (atom->ntypes + 1) + jtype];
}

void PairRuninAsperity::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (iarg + 1 >= narg)
      error->all(FLERR, "pair_style runin/asperity: keyword '{}' needs a value", keyword);
    const std::string value = arg[iarg + 1];
    if (keyword == "wear") {
      if (value == "yes" || value == "on")
        wear_on = true;
      else if (value == "no" || value == "off")
        wear_on = false;
      else
        error->all(FLERR, "pair_style runin/asperity: wear must be 'yes' or 'no', got '{}'", value);
    } else if (keyword == "archard") {
      if (value == "plain")
        archard_form = tribo::ArchardForm::plain;
      else if (value == "thesis")
        archard_form = tribo::ArchardForm::thesis;
      else
        error->all(FLERR, "pair_style runin/asperity: archard must be 'plain' or 'thesis', got '{}'", value);
    } else if (keyword == "reshape") {
      if (value == "yes" || value == "on")
        reshape = true;
      else if (value == "no" || value == "off")
        reshape = false;
      else
        error->all(FLERR, "pair_style runin/asperity: reshape must be 'yes' or 'no', got '{}'", value);
    } else if (keyword == "friction") {
      if (value == "coulomb")
        friction_model = FrictionModel::coulomb;
      else if (value == "strength")
        friction_model = FrictionModel::strength;
      else
        error->all(FLERR, "pair_style runin/asperity: friction must be 'coulomb' or 'strength', got '{}'", value);
    } else if (keyword == "transfer") {
      const double fraction = utils::is_double(value) ? utils::numeric(FLERR, value.c_str(), false, lmp) : -1.0;
      if (!(fraction >= 0.0 && fraction <= 1.0))
        error->all(FLERR, "pair_style runin/asperity: transfer fraction must be in [0, 1], got '{}'", value);
      transfer_fraction = fraction;
    } else if (keyword == "restick") {
      const double speed = utils::is_double(value) ? utils::numeric(FLERR, value.c_str(), false, lmp) : -1.0;
      if (!(speed >= 0.0))
        error->all(FLERR, "pair_style runin/asperity: restick speed must be >= 0 m/s, got '{}'", value);
      restick_speed = speed;
    } else {
      error->all(FLERR,
                 "pair_style runin/asperity: unknown keyword '{}' (expected wear, archard, reshape, friction, "
                 "transfer or restick)",
                 keyword);
    }
  }
  if (wear_on && domain->box_exist) attach_wear_state();
}

// The per-atom wear state exists from pair_style on, so dumps and computes can name it before a run.
void PairRuninAsperity::attach_wear_state()
{
  if (!fix_wear) fix_wear = FixRuninWearState::find_or_create(modify);
}

void PairRuninAsperity::validate(const Coefficients &c, const char *origin)
{
  try {
    make_model(c, archard_form, transfer_fraction);
  } catch (const tribo::InvalidCoefficient &e) {
    error->all(FLERR, "pair_coeff runin/asperity ({}): {}", origin, e.what());
  }
}

void PairRuninAsperity::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 2) error->all(FLERR, "pair_coeff runin/asperity: expected type I and type J");

  Coefficients c;
  const char *origin = "explicit";
  int optional_first = narg;
  if (narg >= 6 && strcmp(arg[2], "file") == 0) {
    c = read_coefficients_file(arg[3], arg[4], arg[5]);
    origin = "file";
    optional_first = 6;
  } else if (narg == 10 || (narg > 10 && !utils::is_double(arg[10]))) {
    const char *names[] = {"E*", "G*", "e", "mu_s", "mu_k", "d_c", "k", "H"};
    double v[Coefficients::NPACKED];
    for (int k = 0; k < 8; k++) {
      if (!utils::is_double(arg[2 + k]))
        error->all(FLERR, "pair_coeff runin/asperity: {} must be a number, got '{}'", names[k], arg[2 + k]);
      v[k] = utils::numeric(FLERR, arg[2 + k], false, lmp);
    }
    v[8] = v[7];    // one hardness for both types
    c = Coefficients::unpack(v);
    optional_first = 10;
  } else {
    error->all(FLERR,
               "pair_coeff runin/asperity: expected 'I J E* G* e mu_s mu_k d_c k H' (8 values) or "
               "'I J file <path> <material-I> <material-J>', then optional 'tau_s X' 'plough X'; got {} arguments",
               narg);
  }
  read_optional_coefficients(c, narg, arg, optional_first);
  validate(c, origin);

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      coeff_of(i, j) = c;
      Coefficients swapped = c;
      std::swap(swapped.hardness_i, swapped.hardness_j);
      coeff_of(j, i) = swapped;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "pair_coeff runin/asperity: no type pair in range {} {}", arg[0], arg[1]);
}

void PairRuninAsperity::read_optional_coefficients(Coefficients &c, int narg, char **arg, int first)
{
  for (int iarg = first; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (keyword != "tau_s" && keyword != "plough")
      error->all(FLERR, "pair_coeff runin/asperity: unknown keyword '{}' (expected tau_s or plough)", keyword);
    if (iarg + 1 >= narg || !utils::is_double(arg[iarg + 1]))
      error->all(FLERR, "pair_coeff runin/asperity: {} needs a number, got '{}'", keyword,
                 iarg + 1 < narg ? arg[iarg + 1] : "");
    const double value = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    (keyword == "tau_s" ? c.shear_strength : c.ploughing_factor) = value;
  }
}

// Coefficient file (potentials/*.runin); format and checks in runin_material_file.h.
PairRuninAsperity::Coefficients PairRuninAsperity::read_coefficients_file(
    const std::string &file, const std::string &material_i, const std::string &material_j)
{
  const RuninMaterialPair entry =
      read_runin_material_pair(lmp, file, material_i, material_j, "pair_coeff runin/asperity");
  const double values[Coefficients::NPACKED] = {tribo::effective_modulus(entry.a, entry.b),
                                                tribo::effective_shear_modulus(entry.a, entry.b),
                                                entry.restitution,
                                                entry.mu_static,
                                                entry.mu_kinetic,
                                                entry.slip_weakening_distance,
                                                entry.wear_coefficient,
                                                entry.a.hardness,
                                                entry.b.hardness};
  return Coefficients::unpack(values);
}

void PairRuninAsperity::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "pair runin/asperity: requires atom attributes radius and rmass (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair runin/asperity: requires ghost velocities (comm_modify vel yes)");

  runin_compat::request_size_history_list(this, neighbor, instance_me);
  dt = update->dt;

  if (!fix_history) {
    auto cmd = fmt::format("{} all NEIGH_HISTORY {}", kHistoryId, static_cast<int>(HISTORY_SIZE));
    fix_history = dynamic_cast<FixNeighHistory *>(modify->replace_fix(kDummyId, cmd, 1));
    fix_history->pair = this;
    fix_dummy = nullptr;
  }
  if (wear_on) attach_wear_state();    // after read_restart, pair_style settings did not run

  // largest radius per type bounds the contact cutoff
  std::vector<double> local(atom->ntypes + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    local[atom->type[i]] = std::max(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad, atom->ntypes + 1, MPI_DOUBLE, MPI_MAX, world);

  models.assign(coeffs.size(), std::nullopt);

  // transferred volume is communicated only with transfer > 0; reallocate at the first step
  comm_reverse = transfer_fraction > 0.0 ? 2 : 1;
  memory->destroy(increment);
  memory->destroy(worn_owned);
  memory->destroy(worn_ghost);
  increment = nullptr;
  worn_owned = worn_ghost = nullptr;
  nmax_increment = nworn_owned = nworn_ghost = 0;

  // contact sums cost a few operations per contact: only when a compute can read them
  sums_requested = false;
  for (int i = 0; i < modify->ncompute; i++)
    if (strcmp(modify->compute[i]->style, "runin/friction") == 0) sums_requested = true;
  sums = RuninContactSums();

  // --- timestep guard hook (runin_timestep_guard.h): WARNING/ERROR on dt vs the Rayleigh time ---
  runin_lammps::guard_timestep(lmp, "pair runin/asperity", [this](int i, int j) {
    return setflag[i][j] ? runin_lammps::PairModuli{coeff_of(i, j).effective_modulus,
                                                    coeff_of(i, j).effective_shear_modulus}
                         : runin_lammps::PairModuli{};
  });
  // --- end timestep guard hook ---
}

double PairRuninAsperity::init_one(int i, int j)
{
  if (!setflag[i][j])
    error->all(FLERR, "pair runin/asperity: coefficients for types {} {} are not set (pair_coeff)", i, j);
  const int n = atom->ntypes + 1;
  models[i * n + j].emplace(make_model(coeff_of(i, j), archard_form, transfer_fraction));
  models[j * n + i].emplace(make_model(coeff_of(j, i), archard_form, transfer_fraction));
  return maxrad[i] + maxrad[j];
}

template <int... Index>
std::array<PairRuninAsperity::EvalFunction, sizeof...(Index)> PairRuninAsperity::eval_table(
    std::integer_sequence<int, Index...>)
{
  return {{&PairRuninAsperity::eval<(Index >> 4) & 1, (Index >> 3) & 1, (Index >> 2) & 1, (Index >> 1) & 1,
                                    Index & 1>...}};
}

void PairRuninAsperity::grow_increments()
{
  if (atom->nmax <= nmax_increment) return;
  nmax_increment = atom->nmax;
  memory->destroy(increment);
  memory->destroy(worn_owned);
  memory->destroy(worn_ghost);
  memory->create(increment, 2 * nmax_increment, "pair:increment");
  std::fill(increment, increment + 2 * nmax_increment, 0.0);
  // one slot per atom, plus the one add_wear writes past the end
  memory->create(worn_owned, nmax_increment + 1, "pair:worn_owned");
  memory->create(worn_ghost, nmax_increment + 1, "pair:worn_ghost");
  nworn_owned = nworn_ghost = 0;
}

void PairRuninAsperity::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool advance = update->setupflag == 0;
  const bool track_wear = wear_on && advance;

  // worn geometry of owned atoms (all of them at setup: radii or volumes may have been set), then ghosts
  if (fix_wear && !advance) fix_wear->refresh_geometry_all();
  const bool worn_geometry = reshape && fix_wear;
  if (worn_geometry) fix_wear->forward_geometry();
  if (track_wear) grow_increments();

  static const auto table = eval_table(std::make_integer_sequence<int, 32>());
  const int index = (track_wear ? 16 : 0) | (worn_geometry ? 8 : 0) |
                    (friction_model == FrictionModel::strength ? 4 : 0) | (sums_requested ? 2 : 0) |
                    (evflag ? 1 : 0);
  (this->*table[index])(eflag);

  if (track_wear) {
    if (force->newton_pair) runin_compat::reverse_comm(comm, this);
    // listed owned atoms: add the increments to the state and refresh the geometry; then clear all listed
    double **state = fix_wear->state();
    const double *radius = atom->radius;
    for (int k = 0; k < nworn_owned; k++) {
      const int i = worn_owned[k];
      state[i][FixRuninWearState::VOLUME_LOST] += increment[2 * i];
      state[i][FixRuninWearState::VOLUME_GAINED] += increment[2 * i + 1];
      increment[2 * i] = increment[2 * i + 1] = 0.0;
      fix_wear->refresh_geometry(i, radius[i]);
    }
    for (int k = 0; k < nworn_ghost; k++) {
      const int i = worn_ghost[k];
      increment[2 * i] = increment[2 * i + 1] = 0.0;
    }
    nworn_owned = nworn_ghost = 0;
  }
}

// One force evaluation. WEAR: advance the wear increments; RESHAPE: worn geometry enters the contact;
// STRENGTH: friction strength (adhesion + ploughing); SUMS: fill the contact sums; EVFLAG: tally energy
// and virial.
template <int WEAR, int RESHAPE, int STRENGTH, int SUMS, int EVFLAG> void PairRuninAsperity::eval(int eflag)
{
  const bool advance = update->setupflag == 0;
  // the wear state is one contiguous block (memory->grow), NCOLUMNS per atom: index it without the row pointers
  double **state_rows = RESHAPE ? fix_wear->state() : nullptr;
  const double *state = state_rows && atom->nmax > 0 ? state_rows[0] : nullptr;
  constexpr int NCOL = FixRuninWearState::NCOLUMNS;
  constexpr int DEPTH = FixRuninWearState::WEAR_DEPTH, FLAT = FixRuninWearState::FLAT_RADIUS;
  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **omega = atom->omega, **torque = atom->torque;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int ntypes1 = atom->ntypes + 1;
  const double step_dt = dt;    // a local: the force stores could alias the member
  const double inv_dt = dt > 0.0 ? 1.0 / dt : 0.0;
  const double restick = restick_speed;
  const std::optional<TypePairModel> *const model_table = models.data();
  RuninContactSums local_sums;
  // NaN and inf propagate through the sum of all pair forces: one add per contact replaces a pass over
  // every atom's force (FixRuninFiniteCheck skips its pass for this pair)
  double force_sum = 0.0;

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firsthistory = fix_history->firstvalue;

  // Centre distance at which two summits touch: worn summits sit lower by their wear depth (higher if material
  // was deposited). Both passes use it, so they agree bit for bit on which pairs touch.
  auto wear_depth = [state](int k) { return RESHAPE ? state[NCOL * k + DEPTH] : 0.0; };
  auto summit_reach = [](double radi, double radj, double depth_i, double depth_j) {
    return radi + radj - (depth_i + depth_j);
  };

  // Pass 1: the touching pairs of the neighbor list, compacted without a branch per pair (whether a
  // neighbor touches is close to random); pairs that separated lose their history.
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
      const double rsq = dot(del, del);
      const double reach = summit_reach(radi, radius[j], depth_i, wear_depth(j));
      const bool in_contact = (!RESHAPE || reach > 0.0) && rsq < reach * reach;
      out[ntouching] = {i, j, &allhistory[HISTORY_SIZE * jj]};
      ntouching += in_contact;
      // a pair that was not touching has a zero history already (fix NEIGH_HISTORY zeroes new pairs)
      if (touch[jj] && !in_contact)
        for (int k = 0; k < HISTORY_SIZE; k++) allhistory[HISTORY_SIZE * jj + k] = 0.0;
      touch[jj] = in_contact;
    }
  }

  // Pass 2: the contact forces.
  for (int c = 0; c < ntouching; c++) {
    const int i = touching[c].i, j = touching[c].j;
    double *history = touching[c].history;
    const int itype = type[i];
    const double radi = radius[i], radj = radius[j];
    const double radsum = radi + radj;
    const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
    const double rsq = dot(del, del);
    const double reach = summit_reach(radi, radj, wear_depth(i), wear_depth(j));
    const int jtype = type[j];
    const TypePairModel &model = *model_table[itype * ntypes1 + jtype];
    const double r = std::sqrt(rsq);
    const double rinv = 1.0 / r;
    const double overlap = reach - r;
    const double normal[3] = {del[0] * rinv, del[1] * rinv, del[2] * rinv};
    // m* = m_i m_j / (m_i + m_j) and R* = r_i r_j / (r_i + r_j) from one division
    const double mass_sum = rmass[i] + rmass[j], radius_product = radi * radj;
    const double inv_sums = 1.0 / (mass_sum * radsum);
    const double meff = rmass[i] * rmass[j] * radsum * inv_sums;
    const double r_eff = radius_product * mass_sum * inv_sums;

    // relative velocity of i w.r.t. j at the contact point
    const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
    const double vn = dot(vr, normal);
    const double spin[3] = {radi * omega[i][0] + radj * omega[j][0], radi * omega[i][1] + radj * omega[j][1],
                            radi * omega[i][2] + radj * omega[j][2]};
    double spin_velocity[3];
    cross(normal, spin, spin_velocity);
    double vt[3];
    for (int k = 0; k < 3; k++) vt[k] = vr[k] - vn * normal[k] + spin_velocity[k];

    const double flat =
        RESHAPE ? tribo::combined_flat_radius(state[NCOL * i + FLAT], state[NCOL * j + FLAT]) : 0.0;
    const tribo::FlatHertzContact contact =
        tribo::flat_hertz_contact(model.effective_modulus, r_eff, flat, overlap);
    double fn = contact.force + model.damping.force(contact.stiffness, meff, vn);
    if (fn < 0.0) fn = 0.0;    // damping must not glue asperities together

    const double kt = tribo::mindlin_stiffness(model.effective_shear_modulus, contact.contact_radius);
    double &slip = history[SLIP];
    tribo::FrictionStrengthParts strength;
    double limit;
    if (STRENGTH) {
      // the micro strength sets the kinetic level; mu_s - mu_k stays the static excess over d_c
      if (fn > 0.0) {
        strength = model.strength.strength(fn, contact.contact_radius, overlap);
        limit = model.friction.limit_force(slip, fn, strength.total());
      } else {
        limit = 0.0;
      }
    } else {
      limit = model.friction.coefficient(slip) * fn;
    }
    const tribo::TangentialUpdate tangential =
        tribo::mindlin_spring(kt, limit, normal, vt, step_dt, &history[SPRING_X], slip, advance);
    if (advance && tribo::resticks_squared(tangential, dot(vt, vt), restick))
      slip = 0.0;    // re-stuck: the contact heals to its static limit
    const double *ft = tangential.force;

    const double fpair[3] = {fn * normal[0] + ft[0], fn * normal[1] + ft[1], fn * normal[2] + ft[2]};
    force_sum += fpair[0] + fpair[1] + fpair[2];
    double tor[3];
    cross(normal, ft, tor);
    const bool j_here = newton_pair || j < nlocal;
    for (int k = 0; k < 3; k++) {
      f[i][k] += fpair[k];
      torque[i][k] -= radi * tor[k];
    }
    if (j_here)
      for (int k = 0; k < 3; k++) {
        f[j][k] -= fpair[k];
        torque[j][k] -= radj * tor[k];
      }

    // with newton off a contact with a ghost is computed on both ranks: count half on each
    const double weight = SUMS && !j_here ? 0.5 : 1.0;
    if (SUMS) {
      const bool j_is_counter = jtype > itype || (jtype == itype && tag[j] > tag[i]);
      const double orient = j_is_counter ? -weight : weight;
      local_sums.normal_force += weight * fn;
      for (int k = 0; k < 3; k++) local_sums.tangential_force[k] += orient * ft[k];
      local_sums.contacts += weight;
      if (!tangential.slipping) local_sums.sticking_contacts += weight;
      local_sums.contact_area += weight * MY_PI * contact.contact_radius * contact.contact_radius;
      local_sums.adhesion_force += weight * strength.adhesion;
      local_sums.ploughing_force += weight * strength.ploughing;
      local_sums.frictional_power += weight * tangential.force_magnitude * tangential.slip_increment * inv_dt;
    }

    if (WEAR && tangential.slip_increment > 0.0) {
      const double worn = model.wear.volume(fn, tangential.slip_increment);
      const tribo::WearExchange exchange = model.exchange.split(worn);
      add_wear(i, exchange.lost_a, exchange.gained_a, nlocal);
      if (j_here) add_wear(j, exchange.lost_b, exchange.gained_b, nlocal);
      if (SUMS) local_sums.wear_volume += weight * worn;
    }

    if (EVFLAG) {
      const double energy =
          eflag ? tribo::FlatHertzNormal(model.effective_modulus, r_eff, flat).elastic_energy(overlap) : 0.0;
      ev_tally_xyz(i, j, nlocal, newton_pair, energy, 0.0, fpair[0], fpair[1], fpair[2], del[0], del[1], del[2]);
    }
  }

  if (SUMS) sums = local_sums;
  if (!std::isfinite(force_sum)) runin_lammps::stop_on_non_finite_force(lmp, "pair runin/asperity");
}

void PairRuninAsperity::transfer_history(double *source, double *target)
{
  for (int k = SPRING_X; k <= SPRING_Z; k++) target[k] = -source[k];
  target[SLIP] = source[SLIP];
}

int PairRuninAsperity::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = increment[2 * (first + k)];
    if (comm_reverse == 2) buf[m++] = increment[2 * (first + k) + 1];
  }
  return m;
}

void PairRuninAsperity::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const double lost = buf[m++];
    const double gained = comm_reverse == 2 ? buf[m++] : 0.0;
    if (lost != 0.0 || gained != 0.0) add_wear(list[k], lost, gained, atom->nlocal);
  }
}

void PairRuninAsperity::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) fwrite(&coeff_of(i, j), sizeof(Coefficients), 1, fp);
    }
}

void PairRuninAsperity::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      Coefficients &c = coeff_of(i, j);
      if (comm->me == 0) utils::sfread(FLERR, &c, sizeof(Coefficients), 1, fp, nullptr, error);
      MPI_Bcast(&c, sizeof(Coefficients), MPI_BYTE, 0, world);
      Coefficients swapped = c;
      std::swap(swapped.hardness_i, swapped.hardness_j);
      coeff_of(j, i) = swapped;
    }
}

void PairRuninAsperity::write_restart_settings(FILE *fp)
{
  const int flags[4] = {wear_on ? 1 : 0, archard_form == tribo::ArchardForm::thesis ? 1 : 0, reshape ? 1 : 0,
                        friction_model == FrictionModel::strength ? 1 : 0};
  fwrite(flags, sizeof(int), 4, fp);
  const double values[2] = {transfer_fraction, restick_speed};
  fwrite(values, sizeof(double), 2, fp);
}

void PairRuninAsperity::read_restart_settings(FILE *fp)
{
  int flags[4] = {1, 0, 1, 0};
  double values[2] = {0.0, 0.0};
  if (comm->me == 0) {
    utils::sfread(FLERR, flags, sizeof(int), 4, fp, nullptr, error);
    utils::sfread(FLERR, values, sizeof(double), 2, fp, nullptr, error);
  }
  MPI_Bcast(flags, 4, MPI_INT, 0, world);
  MPI_Bcast(values, 2, MPI_DOUBLE, 0, world);
  wear_on = flags[0] == 1;
  archard_form = flags[1] == 1 ? tribo::ArchardForm::thesis : tribo::ArchardForm::plain;
  reshape = flags[2] == 1;
  friction_model = flags[3] == 1 ? FrictionModel::strength : FrictionModel::coulomb;
  transfer_fraction = values[0];
  restick_speed = values[1];
}

void PairRuninAsperity::reset_dt()
{
  dt = update->dt;
}

double PairRuninAsperity::memory_usage()
{
  return static_cast<double>(nmax_increment) * (2.0 * sizeof(double) + 2.0 * sizeof(int)) +
         static_cast<double>(touching.capacity()) * sizeof(TouchingPair);
}

double PairRuninAsperity::atom2cut(int i)
{
  return 2.0 * atom->radius[i];
}

double PairRuninAsperity::radii2cut(double r1, double r2)
{
  return r1 + r2;
}
