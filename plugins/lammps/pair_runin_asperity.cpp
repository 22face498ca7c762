#include "pair_runin_asperity.h"
#include "coefficient_grammar.h"
#include "runin_errors.h"
#include "runin_citations.h"

#include "fix_runin_film.h"
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
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using MathConst::MY_PI;
namespace tribo = runin::tribo;

namespace {

const char *const kDummyId = "NEIGH_HISTORY_RUNIN_DUMMY";
const char *const kHistoryId = "NEIGH_HISTORY_RUNIN";
using tribo::SubModelKind;

}    // namespace

PairRuninAsperity::PairRuninAsperity(LAMMPS *lmp) : PairStyle(lmp), from_restart(false), fix_history(nullptr)
{
  finitecutflag = 1;
  restartinfo = 1;
  comm_reverse = 3;    // wear, transfer and flattening increments (set at init to those in use)
  comm_gained = comm_flattened = true;
  // slip distance and largest overlap are scalars: do not negate them when LAMMPS swaps i and j
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
  else if (runin_compat::fix_by_id(modify, kDummyId))
    modify->delete_fix(kDummyId);
  memory->destroy(centres);
  release();
}

// After read_restart the coefficients belong to the restart's sub-models.
void PairRuninAsperity::accept_sub_model(SubModelKind kind, const std::string &name, int index)
{
  if (from_restart && index != choice.of(kind))
    error->all(FLERR,
               "pair_style runin/asperity: the restart file's {} model is '{}', the input asks for '{}'; "
               "the restart's coefficients belong to its models",
               tribo::sub_model_kind_name(kind), tribo::registered_sub_models(kind)[choice.of(kind)].name, name);
}

void PairRuninAsperity::settings(int narg, char **arg)
{
  bool coverage_given = false;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (keyword == "caps") {
      parse_caps(narg, arg, iarg);
      iarg += 2;    // three values
      continue;
    }
    if (iarg + 1 >= narg)
      error->all(FLERR, "pair_style runin/asperity: keyword '{}' needs a value", keyword);
    const std::string value = arg[iarg + 1];
    if (setting(keyword, value)) continue;
    if (keyword == "rise") {
      rise_free = value == "free";
      rise_on = rise_free || runin_compat::logical(lmp, value, "pair_style runin/asperity: rise (yes, no or free)");
    } else if (keyword == "coverage") {
      const double theta =
          runin_lammps::finite_number(lmp, FLERR, "pair_style runin/asperity", "coverage", value.c_str());
      if (!(theta >= 0.0 && theta <= 1.0))
        error->all(FLERR, "pair_style runin/asperity: coverage: film coverage must be in [0, 1], got '{}'", value);
      initial_coverage = theta;
      coverage_given = true;
    } else if (keyword == "wear_scale") {
      const double factor =
          runin_lammps::finite_number(lmp, FLERR, "pair_style runin/asperity", "wear_scale factor", value.c_str());
      if (!(factor > 0.0))
        error->all(FLERR, "pair_style runin/asperity: wear_scale factor must be > 0 and finite, got '{}'", value);
      wear_scale = factor;
    } else {
      error->all(FLERR,
                 "pair_style runin/asperity: unknown keyword '{}' (expected wear, archard, reshape, rise, normal, "
                 "friction, transfer, restick, wear_scale, coverage or caps)",
                 keyword);
    }
  }
  if (rise_on && (!plastic_normal() || !reshape))
    error->all(FLERR, "pair_style runin/asperity: rise yes needs normal elastic/plastic and reshape yes (only "
                      "plastically flattened summits displace material); set rise no");
  if (coverage_given && !film_friction())
    error->all(FLERR,
               "pair_style runin/asperity: coverage: friction model '{}' has no surface film (film keywords need "
               "friction junction/film)",
               tribo::registered_sub_models(SubModelKind::friction)[choice.of(SubModelKind::friction)].name);
  if ((wear_on || plastic_normal()) && domain->box_exist) attach_wear_state();
  if (film_friction() && domain->box_exist) fix_film = FixRuninFilm::find_or_create(modify, initial_coverage);
}

// caps UP DOWN INTERFERENCE: the types whose summits face +z and -z, and the largest interference of a summit of UP
// with one of DOWN (how far a top of UP may stand above a top of DOWN, their wear and flattening taken off) [m].
void PairRuninAsperity::parse_caps(int narg, char **arg, int iarg)
{
  if (iarg + 3 >= narg)
    error->all(FLERR, "pair_style runin/asperity: caps needs three values: the type whose summits face +z, the type "
                      "whose summits face -z, and the largest interference [m]");
  const auto type_of = [&](const char *text, const char *name) {
    char *end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 1 || (domain->box_exist && value > atom->ntypes))
      error->all(FLERR, "pair_style runin/asperity: caps {} type must be an atom type{}, got '{}'", name,
                 domain->box_exist ? fmt::format(" (1-{})", atom->ntypes) : "", text);
    return static_cast<int>(value);
  };
  caps_up = type_of(arg[iarg + 1], "up");
  caps_down = type_of(arg[iarg + 2], "down");
  if (caps_up == caps_down)
    error->all(FLERR, "pair_style runin/asperity: caps up and down types must differ, got {} for both", caps_up);
  caps_interference =
      runin_lammps::finite_number(lmp, FLERR, "pair_style runin/asperity", "caps interference", arg[iarg + 3]);
  if (!(caps_interference > 0.0))
    error->all(FLERR, "pair_style runin/asperity: caps interference must be > 0 m, got '{}'", arg[iarg + 3]);
}

// Two caps of radii R_i, R_j touch only where the top of one stands into the other (interference u > 0), within
// sqrt(2 (R_i + R_j) u) of each other: the list needs that reach at the largest u, not the spheres' diameter.
double PairRuninAsperity::caps_cutoff(int i, int j) const
{
  return std::sqrt(2.0 * (maxrad[i] + maxrad[j]) * caps_interference);
}

// Each atom is the top of its summit: the sphere's centre lies one radius below it (caps up) or above it (down).
void PairRuninAsperity::place_centres(int first, int last)
{
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *type = atom->type;
  for (int k = first; k < last; k++) {
    const double side = type[k] == caps_up ? -1.0 : 1.0;
    centres[k][0] = x[k][0];
    centres[k][1] = x[k][1];
    centres[k][2] = x[k][2] + side * radius[k];
  }
}

// A pair of caps outside the list touches only if a top of UP stands above a top of DOWN by more than the list's
// reach allows. The list holds every pair of tops within cutoff c; two caps touch where d^2 < (u - D)(2 R_s - u - D)
// at a lateral distance d, raw interference u of the tops and drop D of both (wear and flattening; below zero where
// material was deposited or the surface rose): their tops' distance^2 is below (u - D)(2 R_s - u - D) + u^2, largest
// at the largest u and smallest D over the bodies. ERROR if that exceeds c^2.
void PairRuninAsperity::check_caps()
{
  double **x = atom->x;
  const int *type = atom->type;
  const bool worn = reshape && fix_wear;
  double **state = worn ? fix_wear->state() : nullptr;
  const auto drop = [&](int k) {
    if (!worn) return 0.0;
    const double rise = rise_on ? state[k][FixRuninWearState::RISE] : 0.0;
    return state[k][FixRuninWearState::WEAR_DEPTH] - rise;
  };
  constexpr double inf = std::numeric_limits<double>::infinity();
  // highest top of UP, -lowest top of DOWN, -smallest drop of UP, -smallest drop of DOWN
  double local[4] = {-inf, -inf, -inf, -inf}, global[4];
  for (int k = 0; k < atom->nlocal; k++) {
    if (type[k] == caps_up) {
      local[0] = std::max(local[0], x[k][2]);
      local[2] = std::max(local[2], -drop(k));
    } else if (type[k] == caps_down) {
      local[1] = std::max(local[1], -x[k][2]);
      local[3] = std::max(local[3], -drop(k));
    }
  }
  MPI_Allreduce(local, global, 4, MPI_DOUBLE, MPI_MAX, world);
  if (!(global[0] > -inf && global[1] > -inf)) return;    // a body without summits
  const double u = global[0] + global[1], d_min = -(global[2] + global[3]);
  const double sum_radii = maxrad[caps_up] + maxrad[caps_down];
  if (!(u > d_min)) return;    // no top stands into the other body
  const double reach_sq = (u - d_min) * (2.0 * sum_radii - u - d_min) + u * u;
  const double cutoff = caps_cutoff(caps_up, caps_down);
  if (!(reach_sq <= cutoff * cutoff))
    error->all(FLERR,
               "pair runin/asperity: caps: at step {} a top of type {} stands {:.4g} m above one of type {} (their "
               "wear and flattening {:.4g} m); contacts may then lie beyond the list's reach {:.4g} m of caps "
               "interference {:.4g} m: raise the caps interference to at least {:.4g} m",
               update->ntimestep, caps_up, u, caps_down, d_min, cutoff, caps_interference,
               reach_sq / (2.0 * sum_radii));
}

bool PairRuninAsperity::film_friction() const
{
  return tribo::registered_sub_models(SubModelKind::friction)[choice.of(SubModelKind::friction)].has_film;
}

// pair_coeff I J <keyword block | explicit values | file ...> [options]: the one grammar of the contact hosts
// (plugins/common/coefficient_grammar.h), its checks and messages.
void PairRuninAsperity::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 2) error->all(FLERR, "pair_coeff runin/asperity: expected type I and type J");
  runin_lammps::require_si_units(lmp, FLERR, "pair runin/asperity");

  const runin_coeff::Host host = coefficient_host(lmp, "pair_coeff runin/asperity", "pair_coeff runin/asperity", true);
  const tribo::ContactCoefficients c = runin_coeff::pair_coeff(host, narg, arg, choice, contact_settings);

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  runin_coeff::store_type_pairs(host, arg, ilo, ihi, jlo, jhi, choice, c,
                                [this](int i, int j) -> tribo::ContactCoefficients & { return coeff_of(i, j); }, setflag);
  // here, before the first run's init prints the citation block (and again at init_style, after a restart)
  runin_lammps::cite(lmp, runin_lammps::model_citations(choice, wear_on, false));
}

void PairRuninAsperity::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "pair runin/asperity: requires atom attributes radius and rmass (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair runin/asperity: requires ghost velocities (comm_modify vel yes)");
  runin_lammps::require_si_units(lmp, FLERR, "pair runin/asperity");
  runin_lammps::cite(lmp, runin_lammps::model_citations(choice, wear_on, false));

  if (caps()) {
    if (caps_up > atom->ntypes || caps_down > atom->ntypes)
      error->all(FLERR, "pair_style runin/asperity: caps types {} and {}: the box has {} atom types", caps_up,
                 caps_down, atom->ntypes);
    for (int t = 1; t <= atom->ntypes; t++)
      if (t != caps_up && t != caps_down)
        error->all(FLERR, "pair_style runin/asperity: caps: type {} is neither the up ({}) nor the down ({}) type; "
                          "with caps every summit is a cap of one of the two bodies", t, caps_up, caps_down);
    if (domain->zperiodic)
      error->all(FLERR, "pair_style runin/asperity: caps face along z: the box must not be periodic in z");
    if (runin_compat::fix_by_style(modify, "runin/wall"))
      error->all(FLERR, "pair_style runin/asperity: caps and fix runin/wall: the wall sees whole spheres at the atoms; "
                        "use caps only between two bodies of summits");
    // the tops' distance decides the list (no size list: the spheres' diameters would set its reach); such a list
    // does not mark the pairs within reach, so the history fix looks every listed pair up
    runin_compat::request_history_list(this, neighbor, instance_me);
    beyond_contact = 1;
  } else {
    runin_compat::request_size_history_list(this, neighbor, instance_me);
    beyond_contact = 0;
  }
  dt = update->dt;

  size_history(fix_history != nullptr);
  if (!fix_history) {
    auto cmd = fmt::format("{} all NEIGH_HISTORY {}", kHistoryId, history_size);
    fix_history = dynamic_cast<FixNeighHistory *>(modify->replace_fix(kDummyId, cmd, 1));
    fix_history->pair = this;
    fix_dummy = nullptr;
  }
  // after read_restart, pair_style settings did not run; plastic flattening needs the state too
  if (wear_on || plastic_normal()) attach_wear_state();
  if (fix_wear) fix_wear->forward_flattened(plastic_normal());    // the ghosts' part for reloads
  if (rise_on) {
    if (!plastic_normal() || !reshape)
      error->all(FLERR, "pair_style runin/asperity: rise yes needs normal elastic/plastic and reshape yes (only "
                        "plastically flattened summits displace material); set rise no");
    if (!domain->xperiodic || !domain->yperiodic)
      error->all(FLERR, "pair_style runin/asperity: rise yes needs a box periodic in x and y (the nominal area of "
                        "a body is lx ly); set rise no or make x and y periodic");
  }
  if (fix_wear) fix_wear->forward_rise(rise_on);
  // the film coverage (from the restart file after read_restart: the fix of the same ID takes its values)
  fix_film = film_friction() ? FixRuninFilm::find_or_create(modify, initial_coverage) : nullptr;

  runin_pair::largest_radius_per_type(atom->radius, atom->type, atom->nlocal, atom->ntypes, world, maxrad);

  models.assign(coeffs.size(), std::nullopt);

  // transferred volume is communicated only with transfer > 0, flattening only with a plastic normal model;
  // reallocate at the first step
  comm_gained = contact_settings.transfer_fraction > 0.0;
  comm_flattened = plastic_normal();
  comm_reverse = 1 + comm_gained + comm_flattened;
  increments.release();

  request_sums();

  // --- timestep guard hook (runin_timestep_guard.h): WARNING/ERROR on dt vs the Rayleigh time ---
  runin_lammps::guard_timestep(lmp, "pair runin/asperity", [this](int i, int j) {
    if (!setflag[i][j]) return runin_lammps::PairModuli{};
    const tribo::ContactModel model(choice, coeff_of(i, j), contact_settings);
    return runin_lammps::PairModuli{model.effective_modulus(), model.effective_shear_modulus()};
  });
  // --- end timestep guard hook ---
}

void PairRuninAsperity::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  const bool advance = update->setupflag == 0;
  // wear and plastic flattening both change the per-atom state through the increments
  const bool track_wear = (wear_on || (plastic_normal() && reshape)) && advance;

  // worn geometry of owned atoms (all of them at setup: radii or volumes may have been set), then ghosts
  if (fix_wear && !advance) fix_wear->refresh_geometry_all();
  const bool worn_geometry = reshape && fix_wear;
  if (worn_geometry) fix_wear->forward_geometry();
  if (rise_on && worn_geometry) {
    // owned and ghost summits' drop less their body's rise, one per row of the wear state's stride (eval)
    constexpr int NCOL = FixRuninWearState::NCOLUMNS;
    const int nall = atom->nlocal + atom->nghost;
    if (static_cast<int>(reach_drop.size()) < NCOL * nall) reach_drop.resize(NCOL * static_cast<size_t>(atom->nmax));
    double **state = fix_wear->state();
    for (int k = 0; k < nall; k++)
      reach_drop[NCOL * k] = state[k][FixRuninWearState::WEAR_DEPTH] - state[k][FixRuninWearState::RISE];
  }
  if (track_wear) increments.reserve(atom->nmax);
  if (caps()) {
    if (atom->nmax > centres_nmax) {
      centres_nmax = atom->nmax;
      memory->destroy(centres);
      memory->create(centres, centres_nmax, 3, "pair:centres");
    }
    place_centres(0, atom->nlocal + atom->nghost);
    check_caps();
  }

  if (fix_film) {
    // the film of each type: its own I,I pair's removal distance and growth rate
    const int ntypes = atom->ntypes;
    film_growth.assign(ntypes + 1, 0.0);
    film_inverse_removal_.assign(ntypes + 1, 0.0);
    for (int t = 1; t <= ntypes; t++)
      if (const tribo::FilmKinetics *kinetics = models[t * (ntypes + 1) + t]->film_kinetics()) {
        film_growth[t] = kinetics->growth(dt);
        film_inverse_removal_[t] = kinetics->removal(1.0);
      }
    fix_film->begin_step();
  }
  evaluate(eflag, advance, worn_geometry);
  // every summit: removed by its contacts' slip, regrown by its type's growth rate
  if (fix_film && advance) fix_film->end_step(force->newton_pair, film_growth.data());

  if (track_wear) {
    if (force->newton_pair) runin_compat::reverse_comm(comm, this);
    // before the increments are applied (it reads them and the current drops); a pass of its own, since a test
    // inside the application's loop cost about 2 % of a plastic step without the rise
    if (rise_on) raise_free_surfaces();
    apply_increments();
  }
}

// Volume-conserving flattening (Pullen and Williamson 1972): the cap volume a body's summits lost to plastic
// flattening in this step reappears as a uniform rise of that body's surface, by volume / nominal area (lx ly). A
// body is the atoms of one type. rise yes: all summits rise, those in contact too, so the body's surface moves as a
// whole: exact for its volume, but under load control the counter-body backs off by the rise and the contacts do
// not see P&W's rise of the free surface relative to them. rise free: only the summits out of contact rise, by
// V / (A N_free / N) (P&W's V / (A - A_r) with equal summit cells; the volume to within the cells' spread).
void PairRuninAsperity::raise_free_surfaces()
{
  double **state = fix_wear->state();
  const double *radius = atom->radius;
  const int *type = atom->type;
  const int nlocal = atom->nlocal, ntypes1 = atom->ntypes + 1;
  // per type: flattened volume, summits, summits out of contact
  std::vector<double> local(3 * ntypes1, 0.0), total(3 * ntypes1, 0.0);
  for (int k = 0; k < increments.nowned(); k++) {
    const int i = increments.owned()[k];
    const double depth = increments.of(i)[runin_pair::Increments::FLATTENED];
    if (depth > 0.0)
      local[type[i]] += FixRuninWearState::flattened_volume(radius[i], state[i][FixRuninWearState::WEAR_DEPTH], depth);
  }
  if (rise_free) {
    // the summits in contact this step: the touch flags pass 1 left in the neighbor list, owners told of ghosts'
    const int nall = nlocal + atom->nghost;
    contact_flag.assign(std::max(nall, atom->nmax), 0.0);
    int **firsttouch = fix_history->firstflag;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++)
        if (firsttouch[i][jj]) contact_flag[i] = contact_flag[jlist[jj] & NEIGHMASK] = 1.0;
    }
    if (force->newton_pair) {
      reverse_contacts = true;
      runin_compat::reverse_comm(comm, this);
      reverse_contacts = false;
    }
  }
  for (int i = 0; i < nlocal; i++) {
    local[ntypes1 + type[i]] += 1.0;
    if (!rise_free || contact_flag[i] == 0.0) local[2 * ntypes1 + type[i]] += 1.0;
  }
  MPI_Allreduce(local.data(), total.data(), static_cast<int>(total.size()), MPI_DOUBLE, MPI_SUM, world);
  // the rise of the summits that rise: volume / (A x their share of the body's summits), so that with equal
  // summit cells the volume is conserved (exactly with rise yes, where all rise)
  const double inv_area = 1.0 / (domain->xprd * domain->yprd);
  std::vector<double> rise(ntypes1, 0.0);
  bool any = false;
  for (int t = 1; t < ntypes1; t++) {
    const double summits = total[ntypes1 + t], free = total[2 * ntypes1 + t];
    if (total[t] > 0.0 && free > 0.0) rise[t] = total[t] * inv_area * (summits / free);
    any = any || rise[t] > 0.0;
  }
  if (!any) return;
  for (int i = 0; i < nlocal; i++)
    if (!rise_free || contact_flag[i] == 0.0) state[i][FixRuninWearState::RISE] += rise[type[i]];
}

runin_pair::Atoms<tagint> PairRuninAsperity::loop_atoms() const
{
  return {caps() ? centres : atom->x, atom->v,  atom->omega, atom->f,   atom->torque, atom->radius,
          atom->rmass,                 atom->type, atom->mask, atom->tag, atom->nlocal};
}

runin_pair::Neighbours PairRuninAsperity::neighbours() const
{
  return {list->inum,       list->ilist,           list->numneigh,
          list->firstneigh, fix_history->firstflag, fix_history->firstvalue};
}

// One force evaluation: the shared pass (pair_contacts.h) on this host's arrays, then its reports.
template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG>
void PairRuninAsperity::eval(int eflag)
{
  using W = FixRuninWearState;
  runin_pair::Step step =
      runin_pair::step_of<W>(models.data(), atom->ntypes + 1, dt, update->ntimestep, update->setupflag == 0,
                             force->newton_pair, increments.reserved(), body_groupbit,
                             RESHAPE ? fix_wear->state() : nullptr, atom->nmax);
  // with rise yes the reach sees the drop less the rise, from rows of the same stride that compute() filled
  if (rise_on) step.reach_rows = reach_drop.data();
  const bool film = tribo::HasFilm<std::tuple_element_t<FRICTION, tribo::FrictionModels>>::value;
  step.coverage = film ? fix_film->coverage() : nullptr;
  step.film_removal = film ? fix_film->exposure() : nullptr;
  step.film_inverse_removal = film ? film_inverse_removal_.data() : nullptr;
  runin_pair::PairHost<PairRuninAsperity, true> host{*this, increments, atom->nlocal, force->newton_pair,
                                                      caps() ? atom->x : nullptr};
  const runin_pair::Outcome outcome = runin_pair::contacts<NORMAL, FRICTION, WEAR, RESHAPE, SUMS, EVFLAG, W>(
      host, loop_atoms(), neighbours(), step, eflag, touching, contact_range);
  if (SUMS) sums = outcome.sums;
  if (!outcome.invalid.empty()) error->one(FLERR, outcome.invalid);    // only this rank knows
  if (!std::isfinite(outcome.force_sum)) runin_lammps::stop_on_non_finite_force(lmp, "pair runin/asperity");
}

// The history as seen from j (reverse transfer of newton-on contacts): the slots of a vector (the spring) turn, the
// rest is shared.
#ifdef RUNIN_TRANSFER_HISTORY_TYPES
void PairRuninAsperity::transfer_history(double *source, double *target, int, int)
#else
void PairRuninAsperity::transfer_history(double *source, double *target)
#endif
{
  for (int k = 0; k < history_size; k++) target[k] = tribo::history_flips_with_bodies(k) ? -source[k] : source[k];
}

// The force of the contact of i and j as the force loop computes it, without changing its history: for
// compute pair/local. fforce * del is the normal force on i; svector: tangential force on i (3), contact
// radius, overlap.
double PairRuninAsperity::single(int i, int j, int itype, int jtype, double rsq, double, double, double &fforce)
{
  fforce = 0.0;
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  if (!models[itype * (atom->ntypes + 1) + jtype])
    error->one(FLERR, "pair runin/asperity: single() before the pair was initialised");
  double **state_rows = fix_wear && reshape ? fix_wear->state() : nullptr;
  const double *state = state_rows ? state_rows[0] : nullptr;
  // this contact's history in i's neighbor list (a copy: single() must not advance it)
  auto history_of = [&](double *history) {
    if (!fix_history || !fix_history->firstvalue)
      error->one(FLERR, "pair runin/asperity: single() needs the contact history (run setup first)");
    runin_pair::copy_history(neighbours(), i, j, history_size, history);
  };
  if (caps()) {
    // LAMMPS measured rsq between the tops; the contact is between the centres
    if (std::max(i, j) >= centres_nmax) error->one(FLERR, "pair runin/asperity: single() before the first run");
    place_centres(i, i + 1);
    place_centres(j, j + 1);
    rsq = 0.0;
    for (int k = 0; k < 3; k++) rsq += (centres[i][k] - centres[j][k]) * (centres[i][k] - centres[j][k]);
  }
  runin_pair::SingleContact contact;
  runin_lammps::kernel_call(lmp, FLERR, "pair runin/asperity: single()", false, [&] {
    contact = runin_pair::single_contact<FixRuninWearState>(loop_atoms(), state,
                                                            *models[itype * (atom->ntypes + 1) + jtype], choice,
                                                            plastic_normal(), i, j, rsq, history_of);
  });
  return contact.returned(fforce, svector);
}

int PairRuninAsperity::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  if (reverse_contacts) {
    for (int k = 0; k < n; k++) buf[m++] = contact_flag[first + k];
    return m;
  }
  for (int k = 0; k < n; k++) {
    const double *inc = increments.of(first + k);
    buf[m++] = inc[runin_pair::Increments::LOST];
    if (comm_gained) buf[m++] = inc[runin_pair::Increments::GAINED];
    if (comm_flattened) buf[m++] = inc[runin_pair::Increments::FLATTENED];
  }
  return m;
}

void PairRuninAsperity::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  const int nlocal = atom->nlocal;
  if (reverse_contacts) {
    for (int k = 0; k < n; k++) contact_flag[list[k]] = std::max(contact_flag[list[k]], buf[m++]);
    return;
  }
  for (int k = 0; k < n; k++) {
    const double lost = buf[m++];
    const double gained = comm_gained ? buf[m++] : 0.0;
    const double flattened = comm_flattened ? buf[m++] : 0.0;
    if (lost != 0.0 || gained != 0.0) increments.add_wear(list[k], lost, gained, nlocal);
    if (flattened != 0.0) increments.add_flattening(list[k], flattened, nlocal);
  }
}

// Restart: the settings and the sub-model choice, then per set type pair a self-describing record (sub-model
// names, coefficient counts and values), so a file written with other sub-models is recognised on reading.
void PairRuninAsperity::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      const std::vector<double> record = tribo::serialize(choice, coeff_of(i, j));
      const int size = static_cast<int>(record.size());
      fwrite(&size, sizeof(int), 1, fp);
      fwrite(record.data(), sizeof(double), size, fp);
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
      int size = 0;
      if (comm->me == 0) utils::sfread(FLERR, &size, sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&size, 1, MPI_INT, 0, world);
      if (size <= 0 || size > 4096)
        error->all(FLERR, "pair runin/asperity: restart file: damaged coefficient record for types {} {}", i, j);
      std::vector<double> record(size);
      if (comm->me == 0) utils::sfread(FLERR, record.data(), sizeof(double), size, fp, nullptr, error);
      MPI_Bcast(record.data(), size, MPI_DOUBLE, 0, world);
      const std::string where = fmt::format("pair runin/asperity: restart file: types {} {}", i, j);
      runin_lammps::kernel_call(lmp, FLERR, where, true, [&] {
        const auto stored = tribo::deserialize(record.data(), size);
        if (!(stored.first == choice)) error->all(FLERR, "{}: {}", where, tribo::describe_difference(stored.first, choice));
        coeff_of(i, j) = stored.second;
        coeff_of(j, i) = tribo::swap_bodies(choice, stored.second);
      });
    }
  from_restart = true;
}

void PairRuninAsperity::write_restart_settings(FILE *fp)
{
  // rise rides on the reshape flag as its second bit: files without it read as before; caps (flag 8) appends its
  // types and interference
  const int flags[3] = {wear_on ? 1 : 0, contact_settings.archard_form == tribo::ArchardForm::thesis ? 1 : 0,
                        (reshape ? 1 : 0) | (rise_on ? 2 : 0) | (rise_free ? 4 : 0) | (caps() ? 8 : 0)};
  fwrite(flags, sizeof(int), 3, fp);
  fwrite(choice.index.data(), sizeof(int), tribo::kSubModelKinds, fp);
  const double values[2] = {contact_settings.transfer_fraction, contact_settings.restick_speed};
  fwrite(values, sizeof(double), 2, fp);
  if (caps()) {
    const int types[2] = {caps_up, caps_down};
    fwrite(types, sizeof(int), 2, fp);
    fwrite(&caps_interference, sizeof(double), 1, fp);
  }
}

void PairRuninAsperity::read_restart_settings(FILE *fp)
{
  int flags[3] = {1, 0, 1};
  double values[2] = {0.0, 0.0};
  if (comm->me == 0) {
    utils::sfread(FLERR, flags, sizeof(int), 3, fp, nullptr, error);
    utils::sfread(FLERR, choice.index.data(), sizeof(int), tribo::kSubModelKinds, fp, nullptr, error);
    utils::sfread(FLERR, values, sizeof(double), 2, fp, nullptr, error);
  }
  MPI_Bcast(flags, 3, MPI_INT, 0, world);
  MPI_Bcast(choice.index.data(), tribo::kSubModelKinds, MPI_INT, 0, world);
  MPI_Bcast(values, 2, MPI_DOUBLE, 0, world);
  int types[2] = {0, 0};
  double interference = 0.0;
  if ((flags[2] & 8) == 8) {
    if (comm->me == 0) {
      utils::sfread(FLERR, types, sizeof(int), 2, fp, nullptr, error);
      utils::sfread(FLERR, &interference, sizeof(double), 1, fp, nullptr, error);
    }
    MPI_Bcast(types, 2, MPI_INT, 0, world);
    MPI_Bcast(&interference, 1, MPI_DOUBLE, 0, world);
  }
  caps_up = types[0];
  caps_down = types[1];
  caps_interference = interference;
  for (int k = 0; k < tribo::kSubModelKinds; k++) {
    const int n = static_cast<int>(tribo::registered_sub_models(static_cast<SubModelKind>(k)).size());
    if (choice.index[k] < 0 || choice.index[k] >= n)
      error->all(FLERR, "pair runin/asperity: restart file: unknown {} model (written by another version?)",
                 tribo::sub_model_kind_name(static_cast<SubModelKind>(k)));
  }
  wear_on = flags[0] == 1;
  contact_settings.archard_form = flags[1] == 1 ? tribo::ArchardForm::thesis : tribo::ArchardForm::plain;
  reshape = (flags[2] & 1) == 1;
  rise_on = (flags[2] & 2) == 2;
  rise_free = (flags[2] & 4) == 4;
  contact_settings.transfer_fraction = values[0];
  contact_settings.restick_speed = values[1];
}

double PairRuninAsperity::atom2cut(int i)
{
  return 2.0 * atom->radius[i];
}

double PairRuninAsperity::radii2cut(double r1, double r2)
{
  return r1 + r2;
}
