#include "pair_runin_asperity.h"

#include "fix_runin_wear_state.h"
#include "runin_lammps_compat.h"
#include "runin_timestep_guard.h"    // timestep guard hook (micro-bench)
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"

#include "atom.h"
#include "comm.h"
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
#include "tokenizer.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <map>

using namespace LAMMPS_NS;
using MathConst::MY_PI;
namespace tribo = runin::tribo;

namespace {

const char *const kDummyId = "NEIGH_HISTORY_RUNIN_DUMMY";
const char *const kHistoryId = "NEIGH_HISTORY_RUNIN";

using TypePairModel = PairRuninAsperity::TypePairModel;

TypePairModel make_model(const PairRuninAsperity::Coefficients &c, tribo::ArchardForm form)
{
  tribo::HertzNormal(c.effective_modulus, 1.0);    // validates E*
  if (!(c.effective_shear_modulus > 0.0))
    throw tribo::InvalidCoefficient("G*: effective shear modulus must be > 0");
  if (!(c.hardness_j > 0.0)) throw tribo::InvalidCoefficient("H: hardness must be > 0");
  const double softer = std::min(c.hardness_i, c.hardness_j);
  return TypePairModel{tribo::RestitutionDamping(c.restitution),
                       tribo::StaticKineticFriction(c.mu_static, c.mu_kinetic, c.slip_weakening_distance),
                       tribo::ArchardWear(c.wear_coefficient, softer, form),
                       tribo::AdhesionPloughing(c.shear_strength, c.ploughing_factor),
                       tribo::wear_share(c.hardness_i, c.hardness_j)};
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
    friction_model(FrictionModel::coulomb), transfer_fraction(0.0), restick_speed(0.0),
    wear_increment(nullptr), gain_increment(nullptr), nmax_increment(0), maxrad(nullptr), fix_history(nullptr),
    fix_wear(nullptr)
{
  single_enable = 0;
  no_virial_fdotr_compute = 1;
  finitecutflag = 1;
  restartinfo = 1;
  comm_reverse = 2;    // wear and transfer increments
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
  memory->destroy(wear_increment);
  memory->destroy(gain_increment);
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
  if (fix_wear) return;
  const int ifix = modify->find_fix(FixRuninWearState::default_id);
  if (ifix >= 0)
    fix_wear = dynamic_cast<FixRuninWearState *>(modify->fix[ifix]);
  else
    fix_wear = dynamic_cast<FixRuninWearState *>(
        modify->add_fix(fmt::format("{} all RUNIN/WEAR_STATE", FixRuninWearState::default_id)));
}

void PairRuninAsperity::validate(const Coefficients &c, const char *origin)
{
  try {
    make_model(c, archard_form);
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

// File format (potentials/*.runin), SI units, '#' comments:
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
PairRuninAsperity::Coefficients PairRuninAsperity::read_coefficients_file(
    const std::string &file, const std::string &material_i, const std::string &material_j)
{
  std::string problem;
  double packed[Coefficients::NPACKED] = {0};
  if (comm->me == 0) {
    FILE *fp = utils::open_potential(file, lmp, nullptr);
    if (!fp) {
      problem = fmt::format("cannot open coefficient file '{}'", file);
    } else {
      std::map<std::string, tribo::Material> materials;
      std::optional<std::vector<double>> pair_values;
      char line[1024];
      int lineno = 0;
      try {
        while (fgets(line, sizeof(line), fp)) {
          lineno++;
          ValueTokenizer words(utils::trim_comment(line));
          if (!words.has_next()) continue;
          const std::string kind = words.next_string();
          if (kind == "material") {
            if (words.count() != 6) throw TokenizerException("material needs NAME E nu rho H", "");
            const std::string name = words.next_string();
            tribo::Material m;
            m.youngs_modulus = words.next_double();
            m.poisson_ratio = words.next_double();
            words.next_double();    // density: used by the timestep guard, not by the force
            m.hardness = words.next_double();
            m.validate(fmt::format("{} line {}: material {}", file, lineno, name));
            materials[name] = m;
          } else if (kind == "pair") {
            if (words.count() != 8) throw TokenizerException("pair needs A B e mu_s mu_k d_c k", "");
            const std::string a = words.next_string(), b = words.next_string();
            if ((a == material_i && b == material_j) || (a == material_j && b == material_i)) {
              std::vector<double> v;
              for (int k = 0; k < 5; k++) v.push_back(words.next_double());
              pair_values = v;
            }
          } else {
            throw TokenizerException(fmt::format("unknown entry '{}'", kind), "");
          }
        }
        if (!materials.count(material_i))
          problem = fmt::format("material '{}' not found in '{}'", material_i, file);
        else if (!materials.count(material_j))
          problem = fmt::format("material '{}' not found in '{}'", material_j, file);
        else if (!pair_values)
          problem = fmt::format("no 'pair {} {}' entry in '{}'", material_i, material_j, file);
        else {
          const auto &mi = materials[material_i], &mj = materials[material_j];
          const auto &v = *pair_values;
          const double values[Coefficients::NPACKED] = {
              tribo::effective_modulus(mi, mj), tribo::effective_shear_modulus(mi, mj),
              v[0], v[1], v[2], v[3], v[4], mi.hardness, mj.hardness};
          std::copy(values, values + Coefficients::NPACKED, packed);
        }
      } catch (const TokenizerException &e) {
        problem = fmt::format("{} line {}: {}", file, lineno, e.what());
      } catch (const tribo::InvalidCoefficient &e) {
        problem = e.what();
      }
      fclose(fp);
    }
  }
  int length = problem.size();
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  problem.resize(length);
  MPI_Bcast(&problem[0], length, MPI_CHAR, 0, world);
  if (length) error->all(FLERR, "pair_coeff runin/asperity: {}", problem);
  MPI_Bcast(packed, Coefficients::NPACKED, MPI_DOUBLE, 0, world);
  return Coefficients::unpack(packed);
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
  models[i * n + j].emplace(make_model(coeff_of(i, j), archard_form));
  models[j * n + i].emplace(make_model(coeff_of(j, i), archard_form));
  return maxrad[i] + maxrad[j];
}

void PairRuninAsperity::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  sums = RuninContactSums();
  const bool advance = update->setupflag == 0;
  const bool track_wear = wear_on && advance;

  // worn geometry of owned atoms (all of them at setup: radii or volumes may have been set), then ghosts
  double **state = fix_wear ? fix_wear->state() : nullptr;
  if (fix_wear) {
    if (!advance) fix_wear->refresh_geometry_all();
    fix_wear->forward_geometry();
  }
  const bool worn_geometry = reshape && state;

  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **omega = atom->omega, **torque = atom->torque;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const int ntypes1 = atom->ntypes + 1;

  if (track_wear) {
    if (atom->nmax > nmax_increment) {
      nmax_increment = atom->nmax;
      memory->destroy(wear_increment);
      memory->destroy(gain_increment);
      memory->create(wear_increment, nmax_increment, "pair:wear_increment");
      memory->create(gain_increment, nmax_increment, "pair:gain_increment");
    }
    std::fill(wear_increment, wear_increment + nall, 0.0);
    std::fill(gain_increment, gain_increment + nall, 0.0);
  }

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firsthistory = fix_history->firstvalue;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const double radi = radius[i];
    int *touch = firsttouch[i];
    double *allhistory = firsthistory[i];
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double *history = &allhistory[HISTORY_SIZE * jj];
      double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = dot(del, del);
      const double radj = radius[j];
      const double radsum = radi + radj;
      // worn summits sit lower by their wear depth (higher if material was deposited)
      const double summit_drop =
          worn_geometry ? state[i][FixRuninWearState::WEAR_DEPTH] + state[j][FixRuninWearState::WEAR_DEPTH] : 0.0;
      const double reach = radsum - summit_drop;

      if (reach <= 0.0 || rsq >= reach * reach) {
        touch[jj] = 0;
        for (int k = 0; k < HISTORY_SIZE; k++) history[k] = 0.0;
        continue;
      }
      touch[jj] = 1;

      const int jtype = type[j];
      const Coefficients &c = coeffs[itype * ntypes1 + jtype];
      const TypePairModel &model = *models[itype * ntypes1 + jtype];
      const double r = std::sqrt(rsq);
      const double overlap = reach - r;
      const double normal[3] = {del[0] / r, del[1] / r, del[2] / r};
      const double meff = rmass[i] * rmass[j] / (rmass[i] + rmass[j]);

      // relative velocity of i w.r.t. j at the contact point
      const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
      const double vn = dot(vr, normal);
      const double spin[3] = {radi * omega[i][0] + radj * omega[j][0], radi * omega[i][1] + radj * omega[j][1],
                              radi * omega[i][2] + radj * omega[j][2]};
      double spin_velocity[3];
      cross(normal, spin, spin_velocity);
      double vt[3];
      for (int k = 0; k < 3; k++) vt[k] = vr[k] - vn * normal[k] + spin_velocity[k];

      const double flat = worn_geometry ? tribo::combined_flat_radius(state[i][FixRuninWearState::FLAT_RADIUS],
                                                                      state[j][FixRuninWearState::FLAT_RADIUS])
                                        : 0.0;
      const tribo::FlatHertzNormal contact(c.effective_modulus, radi * radj / radsum, flat);
      const double contact_radius = contact.contact_radius(overlap);
      const double stiffness = contact.stiffness(overlap);
      double fn = contact.force(overlap) + model.damping.force(stiffness, meff, vn);
      if (fn < 0.0) fn = 0.0;    // damping must not glue asperities together

      const double kt = tribo::mindlin_stiffness(c.effective_shear_modulus, contact_radius);
      tribo::FrictionStrengthParts strength;
      tribo::TangentialUpdate tangential;
      if (friction_model == FrictionModel::strength && fn > 0.0) {
        // the micro strength sets the kinetic level; mu_s - mu_k stays the static excess over d_c
        strength = model.strength.strength(fn, contact_radius, overlap);
        const double mu_kinetic = strength.total() / fn;
        const tribo::StaticKineticFriction limit(mu_kinetic + c.mu_static - c.mu_kinetic, mu_kinetic,
                                                 c.slip_weakening_distance);
        tangential = tribo::mindlin_coulomb(kt, fn, limit, normal, vt, dt, &history[SPRING_X], history[SLIP],
                                            advance);
      } else {
        tangential = tribo::mindlin_coulomb(kt, fn, model.friction, normal, vt, dt, &history[SPRING_X],
                                            history[SLIP], advance);
      }
      if (advance && tribo::resticks(tangential, std::sqrt(dot(vt, vt)), restick_speed))
        history[SLIP] = 0.0;    // re-stuck: the contact heals to its static limit
      const double *ft = tangential.force;

      const double fpair[3] = {fn * normal[0] + ft[0], fn * normal[1] + ft[1], fn * normal[2] + ft[2]};
      double tor[3];
      cross(normal, ft, tor);
      const bool j_here = newton_pair || j < nlocal;
      for (int k = 0; k < 3; k++) {
        f[i][k] += fpair[k];
        torque[i][k] -= radi * tor[k];
        if (j_here) {
          f[j][k] -= fpair[k];
          torque[j][k] -= radj * tor[k];
        }
      }

      // with newton off a contact with a ghost is computed on both ranks: count half on each
      const double weight = j_here ? 1.0 : 0.5;
      const bool j_is_counter = jtype > itype || (jtype == itype && tag[j] > tag[i]);
      const double orient = j_is_counter ? -weight : weight;
      sums.normal_force += weight * fn;
      for (int k = 0; k < 3; k++) sums.tangential_force[k] += orient * ft[k];
      sums.contacts += weight;
      if (!tangential.slipping) sums.sticking_contacts += weight;
      sums.contact_area += weight * MY_PI * contact_radius * contact_radius;
      sums.adhesion_force += weight * strength.adhesion;
      sums.ploughing_force += weight * strength.ploughing;
      if (dt > 0.0) sums.frictional_power += weight * std::sqrt(dot(ft, ft)) * tangential.slip_increment / dt;

      if (track_wear && tangential.slip_increment > 0.0) {
        const double worn = model.wear.volume(fn, tangential.slip_increment);
        const tribo::WearExchange exchange = tribo::exchange_wear(worn, model.share_i, transfer_fraction);
        wear_increment[i] += exchange.lost_a;
        gain_increment[i] += exchange.gained_a;
        if (j_here) {
          wear_increment[j] += exchange.lost_b;
          gain_increment[j] += exchange.gained_b;
        }
        sums.wear_volume += weight * worn;
      }

      if (evflag) {
        const double energy = eflag ? contact.elastic_energy(overlap) : 0.0;
        ev_tally_xyz(i, j, nlocal, newton_pair, energy, 0.0, fpair[0], fpair[1], fpair[2], del[0], del[1],
                     del[2]);
      }
    }
  }

  if (track_wear) {
    if (newton_pair) runin_compat::reverse_comm(comm, this);
    for (int i = 0; i < nlocal; i++) {
      if (wear_increment[i] == 0.0 && gain_increment[i] == 0.0) continue;
      state[i][FixRuninWearState::VOLUME_LOST] += wear_increment[i];
      state[i][FixRuninWearState::VOLUME_GAINED] += gain_increment[i];
      fix_wear->refresh_geometry(i);
    }
  }
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
    buf[m++] = wear_increment[first + k];
    buf[m++] = gain_increment[first + k];
  }
  return m;
}

void PairRuninAsperity::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    wear_increment[list[k]] += buf[m++];
    gain_increment[list[k]] += buf[m++];
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
  return 2.0 * static_cast<double>(nmax_increment) * sizeof(double);
}

double PairRuninAsperity::atom2cut(int i)
{
  return 2.0 * atom->radius[i];
}

double PairRuninAsperity::radii2cut(double r1, double r2)
{
  return r1 + r2;
}
