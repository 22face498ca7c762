#include "fix_runin_wall.h"
#include "runin_errors.h"
#include "runin_lammps_compat.h"

#include "fix_runin_wear_state.h"
#include "runin_material_file.h"
#include "runin_timestep_guard.h"
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"
#include "tribo/friction_strength.h"
#include "tribo/load_servo.h"
#include "tribo/wear.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "update.h"
#include "variable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace tribo = runin::tribo;

namespace {

// Values per keyword (after the keyword itself).
const std::map<std::string, int> kKeywordValues = {
    {"zplane", 1}, {"side", 1},     {"file", 3},  {"elastic", 3},  {"friction", 3}, {"wear", 3},
    {"archard", 1}, {"reshape", 1}, {"vel", 2},     {"vz", 1},    {"load", 1},     {"pressure", 1}, {"servo", 2},
    {"strength", 2}, {"restick", 1}, {"transfer", 1}, {"normal", 1}, {"yield", 2}, {"friction_model", 1}};

// Leads the global restart record that carries the contact model. Older records start with NaN (with the
// counterface gain) or with z_wall.
const double kRestartFormatMark = -7.0e77;

}    // namespace

FixRuninWall::FixRuninWall(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), reshape(true), body_groupbit(0), side_sign(0.0), wall_z(0.0), wall_dx(0.0), wall_dy(0.0), wall_wear(0.0), wall_gain(0.0),
    control(Control::displacement),
    load_target(0.0), servo_gain(-1.0), servo_vmax(-1.0), last_normal_force(0.0), last_stiffness(0.0),
    wall_velocity{0.0, 0.0, 0.0}, vz_given(false), dt(0.0), history(nullptr),
    fix_wear(nullptr)
{
  if (!runin_compat::sphere_atoms(atom)) error->all(FLERR, "fix runin/wall: requires atom_style sphere");

  bool yield_given = false;
  std::string friction_model_name;    // keyword friction_model; else 'strength' with keyword strength
  double yield_strength = 0.0, yield_poisson = 0.3;
  bool have_zplane = false, have_file = false, have_elastic = false, have_friction = false, have_wear = false;
  int iarg = 3;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    const auto known = kKeywordValues.find(keyword);
    if (known == kKeywordValues.end())
      error->all(FLERR,
                 "fix runin/wall: unknown keyword '{}' (expected zplane, side, file, elastic, friction, wear, "
                 "archard, reshape, vel, vz, load, pressure, servo, strength, restick, transfer, normal, yield or "
                 "friction_model)",
                 keyword);
    const int nvalues = known->second;
    if (iarg + nvalues >= narg)
      error->all(FLERR, "fix runin/wall: keyword '{}' needs {} value(s), got {}", keyword, nvalues, narg - iarg - 1);
    char **values = &arg[iarg + 1];
    auto number = [&](int k, const char *name) {
      return runin_lammps::finite_number(lmp, FLERR, "fix runin/wall", keyword + " " + name, values[k]);
    };

    if (keyword == "zplane") {
      wall_z = number(0, "Z");
      have_zplane = true;
    } else if (keyword == "side") {
      if (strcmp(values[0], "lo") == 0)
        side_sign = 1.0;
      else if (strcmp(values[0], "hi") == 0)
        side_sign = -1.0;
      else
        error->all(FLERR, "fix runin/wall: side must be 'lo' or 'hi', got '{}'", values[0]);
    } else if (keyword == "file") {
      parameters = contact_parameters(
          read_runin_material_pair(lmp, values[0], values[1], values[2], "fix runin/wall: file"));
      have_file = true;
    } else if (keyword == "elastic") {
      parameters.effective_modulus = number(0, "E*");
      parameters.effective_shear_modulus = number(1, "G*");
      parameters.restitution = number(2, "e");
      have_elastic = true;
    } else if (keyword == "friction") {
      parameters.mu_static = number(0, "mu_s");
      parameters.mu_kinetic = number(1, "mu_k");
      parameters.slip_weakening_distance = number(2, "d_c");
      have_friction = true;
    } else if (keyword == "wear") {
      parameters.wear_coefficient = number(0, "k");
      parameters.hardness_i = number(1, "H_asperity");
      parameters.hardness_j = number(2, "H_wall");
      have_wear = true;
    } else if (keyword == "archard") {
      if (strcmp(values[0], "plain") == 0)
        contact_settings.archard_form = tribo::ArchardForm::plain;
      else if (strcmp(values[0], "thesis") == 0)
        contact_settings.archard_form = tribo::ArchardForm::thesis;
      else
        error->all(FLERR, "fix runin/wall: archard must be 'plain' or 'thesis', got '{}'", values[0]);
    } else if (keyword == "reshape") {
      if (strcmp(values[0], "yes") == 0)
        reshape = true;
      else if (strcmp(values[0], "no") == 0)
        reshape = false;
      else
        error->all(FLERR, "fix runin/wall: reshape must be 'yes' or 'no', got '{}'", values[0]);
    } else if (keyword == "vel") {
      parse_setting(vel[0], values[0], "vel vx");
      parse_setting(vel[1], values[1], "vel vy");
    } else if (keyword == "vz") {
      parse_setting(vz, values[0], "vz");
      vz_given = true;
    } else if (keyword == "load" || keyword == "pressure") {
      load_target = number(0, keyword == "load" ? "F" : "p");
      if (!(load_target > 0.0)) error->all(FLERR, "fix runin/wall: {} must be > 0, got {}", keyword, load_target);
      control = keyword == "load" ? Control::force : Control::pressure;
    } else if (keyword == "servo") {
      servo_gain = number(0, "gain");
      servo_vmax = number(1, "vmax");
      if (!(servo_gain > 0.0 && servo_gain <= 1.0))
        error->all(FLERR, "fix runin/wall: servo gain must be in (0, 1], got {}", servo_gain);
      if (!(servo_vmax > 0.0)) error->all(FLERR, "fix runin/wall: servo vmax must be > 0, got {}", servo_vmax);
    } else if (keyword == "strength") {
      parameters.shear_strength = number(0, "tau_s");
      parameters.ploughing_factor = number(1, "plough");
      choice.index[static_cast<int>(tribo::SubModelKind::friction)] =
          tribo::find_sub_model(tribo::SubModelKind::friction, tribo::StrengthFrictionModel::name);
    } else if (keyword == "friction_model") {
      friction_model_name = values[0];
      runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", true,
                                [&] { tribo::find_sub_model(tribo::SubModelKind::friction, values[0]); });
    } else if (keyword == "normal") {
      choice.index[static_cast<int>(tribo::SubModelKind::normal)] =
          runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", true,
                                    [&] { return tribo::find_sub_model(tribo::SubModelKind::normal, values[0]); });
    } else if (keyword == "yield") {
      yield_given = true;
      yield_strength = number(0, "S_y");
      yield_poisson = number(1, "nu");
    } else if (keyword == "restick") {
      contact_settings.restick_speed = number(0, "v");
      if (!(contact_settings.restick_speed >= 0.0) || !std::isfinite(contact_settings.restick_speed))
        error->all(FLERR, "fix runin/wall: restick speed must be >= 0 m/s, got {}", contact_settings.restick_speed);
    } else if (keyword == "transfer") {
      contact_settings.transfer_fraction = number(0, "f");
      if (!(contact_settings.transfer_fraction >= 0.0 && contact_settings.transfer_fraction <= 1.0))
        error->all(FLERR, "fix runin/wall: transfer fraction must be in [0, 1], got {}",
                   contact_settings.transfer_fraction);
    }
    iarg += nvalues + 1;
  }

  if (!have_zplane) error->all(FLERR, "fix runin/wall: keyword 'zplane' is required");
  if (side_sign == 0.0) error->all(FLERR, "fix runin/wall: keyword 'side' (lo or hi) is required");
  if (have_file && (have_elastic || have_friction || have_wear))
    error->all(FLERR, "fix runin/wall: give either 'file' or 'elastic'/'friction'/'wear', not both");
  if (!have_file && !(have_elastic && have_friction && have_wear))
    error->all(FLERR, "fix runin/wall: coefficients missing: give 'file PATH ASPERITY WALL' or all of "
                      "'elastic', 'friction' and 'wear'");
  if (control != Control::displacement && servo_vmax < 0.0)
    error->all(FLERR, "fix runin/wall: load control needs 'servo GAIN VMAX'");
  if (control != Control::displacement && vz_given)
    error->all(FLERR, "fix runin/wall: 'vz' and 'load'/'pressure' exclude each other");

  if (!friction_model_name.empty())
    choice.index[static_cast<int>(tribo::SubModelKind::friction)] =
        tribo::find_sub_model(tribo::SubModelKind::friction, friction_model_name);
  // S_y and nu of the yielding body: keyword 'yield', else the material file, else Tabor's H / 2.8
  if (yield_given) {
    parameters.yield_strength = yield_strength;
    parameters.poisson_ratio = yield_poisson;
    parameters.yield_from_hardness = false;
  } else if (!have_file) {
    parameters.yield_strength = std::min(parameters.hardness_i, parameters.hardness_j) / tribo::kTaborConstraintFactor;
    parameters.yield_from_hardness = true;
  }
  const bool plastic =
      choice.of(tribo::SubModelKind::normal) ==
      tribo::find_sub_model(tribo::SubModelKind::normal, tribo::ElasticPlasticNormalModel::name);
  if (plastic && parameters.yield_from_hardness && comm->me == 0)
    error->warning(FLERR, "fix runin/wall: no yield strength given (keyword yield or material file): S_y = H / {} = "
                   "{:.4g} Pa (Tabor), nu = {}", tribo::kTaborConstraintFactor, parameters.yield_strength,
                   parameters.poisson_ratio);

  // the contact model validates its coefficients; the message names the offending one
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", true, [&] {
    if (!(parameters.hardness_i > 0.0))
      throw tribo::InvalidCoefficient(fmt::format("H_asperity: hardness must be > 0, got {}", parameters.hardness_i));
    if (!(parameters.hardness_j > 0.0))
      throw tribo::InvalidCoefficient(fmt::format("H_wall: hardness must be > 0, got {}", parameters.hardness_j));
    model.emplace(choice, tribo::contact_coefficients(choice, parameters), contact_settings);
  });

  vector_flag = 1;
  size_vector = NOUTPUT;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  std::fill(totals, totals + NOUTPUT, 0.0);

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixRuninWall::~FixRuninWall()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(history);
}

int FixRuninWall::setmask()
{
  return POST_FORCE;
}

// Adding a fix from the constructor would corrupt the fix list; here it is safe.
void FixRuninWall::post_constructor()
{
  fix_wear = FixRuninWearState::find_or_create(modify);
}

void FixRuninWall::parse_setting(Setting &s, const char *arg, const char *keyword)
{
  if (strncmp(arg, "v_", 2) == 0) {
    s.variable = arg + 2;
  } else {
    s.value =
        runin_lammps::finite_number(lmp, FLERR, "fix runin/wall", std::string(keyword) + " (a number or v_name)", arg);
    s.variable.clear();
  }
}

void FixRuninWall::resolve(Setting &s, const char *keyword)
{
  if (s.variable.empty()) return;
  s.ivar = input->variable->find(s.variable.c_str());
  if (s.ivar < 0) error->all(FLERR, "fix runin/wall: {} variable '{}' does not exist", keyword, s.variable);
  if (!input->variable->equalstyle(s.ivar))
    error->all(FLERR, "fix runin/wall: {} variable '{}' must be equal-style", keyword, s.variable);
}

double FixRuninWall::current(const Setting &s) const
{
  return s.ivar >= 0 ? input->variable->compute_equal(s.ivar) : s.value;
}

void FixRuninWall::init()
{
  resolve(vel[0], "vel vx");
  resolve(vel[1], "vel vy");
  resolve(vz, "vz");
  dt = update->dt;
  // the wear-state fix may have been redefined since this fix was created: look it up again
  fix_wear = FixRuninWearState::find(modify);
  if (!fix_wear) error->all(FLERR, "fix runin/wall: the per-atom wear state fix is missing");
  double local_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local_min = std::min(local_min, atom->radius[i]);
  MPI_Allreduce(&local_min, &smallest_radius, 1, MPI_DOUBLE, MPI_MIN, world);
  guard_timestep();
}

// The timestep guard of pair runin/asperity (runin_timestep_guard.h), applied to the atom types of this
// fix's group against the wall's E* and G*. The wall's own non-finite check is in compute_contacts: the
// guard's finite-force fix runs before post_force, so it never sees the wall force.
void FixRuninWall::guard_timestep()
{
  const int ntypes = atom->ntypes;
  std::vector<int> local(ntypes + 1, 0), in_group(ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local[atom->type[i]] = 1;
  MPI_Allreduce(local.data(), in_group.data(), ntypes + 1, MPI_INT, MPI_MAX, world);
  runin_lammps::guard_timestep(lmp, "fix runin/wall", [&](int i, int j) {
    return i == j && in_group[i]
               ? runin_lammps::PairModuli{model->effective_modulus(), model->effective_shear_modulus()}
               : runin_lammps::PairModuli{};
  }, groupbit);
}

void FixRuninWall::post_run()
{
  if (past_centre_count > 0 && comm->me == 0)
    error->warning(FLERR, "fix runin/wall: {} asperity evaluations in this run were past the centre of their summit "
                   "(outside every contact law's validity; the first is reported above)", past_centre_count);
  past_centre_count = 0;
  contact_range.report(lmp, "fix runin/wall");
}

void FixRuninWall::reset_dt()
{
  dt = update->dt;
}

void FixRuninWall::setup(int)
{
  update_wall_velocity();
  if (control != Control::displacement) wall_velocity[2] = 0.0;
  compute_contacts(false);
}

void FixRuninWall::post_force(int)
{
  update_wall_velocity();
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", true, [&] { move_wall(); });    // the servo: every rank alike
  compute_contacts(true);
}

void FixRuninWall::update_wall_velocity()
{
  modify->clearstep_compute();
  wall_velocity[0] = current(vel[0]);
  wall_velocity[1] = current(vel[1]);
  wall_velocity[2] = control == Control::displacement ? current(vz) : 0.0;
  modify->addstep_compute(update->ntimestep + 1);
  check_wall_step();
}

// Every rank evaluates the same variables, so the checks are collective. A wall that moves further than a
// summit radius in one step skips whole contacts: the contact laws are not resolved in time.
void FixRuninWall::check_wall_step() const
{
  const double *v = wall_velocity;
  if (!std::isfinite(v[0] + v[1] + v[2]))
    error->all(FLERR, "fix runin/wall: wall velocity ({}, {}, {}) m/s is not finite at step {} (vel/vz values or "
               "variables)", v[0], v[1], v[2], update->ntimestep);
  const double step = std::hypot(v[0], v[1], v[2]) * dt;
  if (step > smallest_radius)
    error->all(FLERR, "fix runin/wall: at step {} the wall moves {:.4g} m per step (speed {:.4g} m/s, dt = {} s), "
               "more than the smallest asperity radius {:.4g} m: contacts are not resolved in time (lower the "
               "speed or the timestep)", update->ntimestep, step, step / dt, dt, smallest_radius);
}

// Displacement control: z += vz dt. Load control: runin::tribo::LoadServo moves the wall toward the
// asperities from the previous step's total normal force and contact stiffness (monotone approach).
void FixRuninWall::move_wall()
{
  wall_dx += wall_velocity[0] * dt;
  wall_dy += wall_velocity[1] * dt;
  if (control == Control::displacement) {
    wall_z += wall_velocity[2] * dt;
    return;
  }
  const double target = control == Control::force ? load_target : load_target * domain->xprd * domain->yprd;
  const tribo::LoadServo servo(servo_gain, servo_vmax * dt);
  const double approach = servo.approach(last_normal_force, last_stiffness, target);
  wall_z += side_sign * approach;
  wall_velocity[2] = side_sign * approach / dt;
}

void FixRuninWall::compute_contacts(bool advance)
{
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall", false, [&] {
    tribo::with_sub_models(choice, [&](auto normal, auto friction) {
      compute_contacts<decltype(normal)::value, decltype(friction)::value>(advance);
    });
  });
}

template <int NORMAL, int FRICTION> void FixRuninWall::compute_contacts(bool advance)
{
  sums = RuninContactSums();
  const bool track_wear = advance && parameters.wear_coefficient > 0.0;

  double **x = atom->x, **v = atom->v, **f = atom->f;
  double **omega = atom->omega, **torque = atom->torque;
  const double *radius = atom->radius, *rmass = atom->rmass;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  double **wear_state = fix_wear ? fix_wear->state() : nullptr;
  const bool worn_geometry = reshape && wear_state;
  if (worn_geometry && !advance) fix_wear->refresh_geometry_all();    // volumes may have been set or restarted
  const double normal[3] = {0.0, 0.0, side_sign};    // from the wall to the asperity

  // force on the wall xyz, contacts, elastic normal force and stiffness (servo), wall wear and gain this step
  // LOCAL_CHECK sums every contact output (NaN and inf propagate); LOCAL_THROUGH counts walls past a centre
  enum {
    LOCAL_FX = 0, LOCAL_FY, LOCAL_FZ, LOCAL_CONTACTS, LOCAL_FN, LOCAL_STIFFNESS, LOCAL_LOST, LOCAL_GAINED,
    LOCAL_CHECK, LOCAL_THROUGH, NLOCAL
  };
  double local[NLOCAL] = {};
  tagint first_bad = std::numeric_limits<tagint>::max();        // lowest atom ID with a non-finite output
  tagint first_through = std::numeric_limits<tagint>::max();    // lowest atom ID the wall passed the centre of
  tagint worst_atom = 0;                                         // furthest beyond its normal law's range
  double worst_range = 1.0, beyond_range = 0.0;                  // its range ratio; contacts beyond (ratio > 1)
  const double pi = std::acos(-1.0);
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double r = radius[i];
    // a worn summit sits lower by its wear depth and carries a flat (pair runin/asperity reshape)
    const double summit_drop = worn_geometry ? wear_state[i][FixRuninWearState::WEAR_DEPTH] : 0.0;
    tribo::ContactGeometry g;
    g.overlap = r - summit_drop - side_sign * (x[i][2] - wall_z);
    if (g.overlap <= 0.0) {
      // the spring and slip belong to one contact; the largest interference belongs to the asperity under
      // this flat and stays, so a reload retraces the elastic unloading curve up to it
      for (int k = 0; k < HISTORY_SIZE; k++)
        if (!tribo::is_plastic_history(k)) history[i][k] = 0.0;
      continue;
    }
    if (g.overlap + std::max(summit_drop, 0.0) > r) {
      // past the centre of the intact sphere (worn or flattened summits included): no sphere contact law
      // holds (the run stops after the reduction)
      local[LOCAL_THROUGH] += 1.0;
      first_through = std::min(first_through, tag[i]);
    }
    g.flat_radius = worn_geometry ? wear_state[i][FixRuninWearState::FLAT_RADIUS] : 0.0;
    g.summit_drop = std::max(summit_drop, 0.0);
    g.effective_radius = r;    // a flat wall: the asperity's own radius
    g.effective_mass = rmass[i];
    for (int k = 0; k < 3; k++) g.normal[k] = normal[k];
    const double vr[3] = {v[i][0] - wall_velocity[0], v[i][1] - wall_velocity[1], v[i][2] - wall_velocity[2]};
    g.normal_velocity = MathExtra::dot3(vr, normal);
    const double spin[3] = {r * omega[i][0], r * omega[i][1], r * omega[i][2]};
    double spin_velocity[3];
    MathExtra::cross3(normal, spin, spin_velocity);
    for (int k = 0; k < 3; k++) g.tangential_velocity[k] = vr[k] - g.normal_velocity * normal[k] + spin_velocity[k];

    const tribo::ContactResult contact = model->evaluate<NORMAL, FRICTION, 1>(g, history[i], dt, advance);
    const double fn = contact.normal_force;
    const double *ft = contact.tangential.force;
    const double outputs = fn + ft[0] + ft[1] + ft[2] + contact.normal.contact_radius + contact.strength.adhesion +
                           contact.strength.ploughing + contact.wear.lost_a + contact.wear.lost_b;
    local[LOCAL_CHECK] += outputs;
    if (!std::isfinite(outputs)) first_bad = std::min(first_bad, tag[i]);
    const double range = contact.normal.range_ratio;
    beyond_range += range > 1.0;
    worst_atom = range > worst_range ? tag[i] : worst_atom;
    worst_range = std::max(range, worst_range);

    double tor[3];
    MathExtra::cross3(normal, ft, tor);
    const bool in_body = (mask[i] & body_groupbit) != 0;
    for (int k = 0; k < 3; k++) {
      const double fk = fn * normal[k] + ft[k];
      f[i][k] += fk;
      torque[i][k] -= r * tor[k];
      local[LOCAL_FX + k] -= fk;
      if (in_body) sums.body_force[k] += fk;
    }
    if (worn_geometry && contact.normal.residual_increment > 0.0) {
      // the rigid flat does not yield: the asperity's summit sinks by the whole residual growth
      wear_state[i][FixRuninWearState::VOLUME_FLATTENED] +=
          FixRuninWearState::flattened_volume(r, summit_drop, contact.normal.residual_increment);
      fix_wear->refresh_geometry(i);
    }
    local[LOCAL_CONTACTS] += 1.0;
    // the servo regulates the elastic load: with the damping term its own wall speed would feed back
    // into the force it measures and, for e < 1, make it ring with period 2 steps
    local[LOCAL_FN] += contact.normal.force;
    local[LOCAL_STIFFNESS] += contact.normal.stiffness;

    sums.normal_force += fn;
    for (int k = 0; k < 3; k++) sums.tangential_force[k] -= ft[k];
    sums.contacts += 1.0;
    if (!contact.tangential.slipping) sums.sticking_contacts += 1.0;
    sums.contact_area += pi * contact.normal.contact_radius * contact.normal.contact_radius;
    sums.adhesion_force += contact.strength.adhesion;
    sums.ploughing_force += contact.strength.ploughing;
    if (advance && dt > 0.0)
      sums.frictional_power += contact.tangential.force_magnitude * contact.tangential.slip_increment / dt;
    if (track_wear && contact.tangential.slip_increment > 0.0) {
      const tribo::WearExchange &exchange = contact.wear;
      if (wear_state) {
        wear_state[i][FixRuninWearState::VOLUME_LOST] += exchange.lost_a;
        wear_state[i][FixRuninWearState::VOLUME_GAINED] += exchange.gained_a;
        if (worn_geometry) fix_wear->refresh_geometry(i);
      }
      local[LOCAL_LOST] += exchange.lost_b;
      local[LOCAL_GAINED] += exchange.gained_b;
      sums.wear_volume += contact.worn_volume;
    }
  }
  for (int k = 0; k < 3; k++) sums.counterface_force[k] = local[LOCAL_FX + k];
  if (advance && worst_atom > 0) contact_range.note(update->ntimestep, beyond_range, worst_range, worst_atom, 0);

  double global[NLOCAL];
  MPI_Allreduce(local, global, NLOCAL, MPI_DOUBLE, MPI_SUM, world);
  if (global[LOCAL_THROUGH] > 0.0) {
    // counted, not fatal: a first-loading sweep may press summits that far on purpose; the count is
    // reported at the end of the run (post_run)
    tagint culprit = first_through;
    MPI_Allreduce(&first_through, &culprit, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (past_centre_count == 0 && comm->me == 0)
      error->warning(FLERR, "fix runin/wall: at step {} the wall (z = {}) has passed the centre of {:.0f} intact "
                     "asperity sphere(s), first atom {}: the interference exceeds the summit radius, where no "
                     "contact law holds (load or wall travel too high for these asperities)", update->ntimestep,
                     wall_z, global[LOCAL_THROUGH], culprit);
    past_centre_count += static_cast<bigint>(global[LOCAL_THROUGH]);
  }
  if (!std::isfinite(global[LOCAL_FX] + global[LOCAL_FY] + global[LOCAL_FZ] + global[LOCAL_CHECK] + wall_z)) {
    tagint culprit = first_bad;
    MPI_Allreduce(&first_bad, &culprit, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    const std::string atoms = culprit == std::numeric_limits<tagint>::max() ? std::string("no atom")
                                                                            : fmt::format("atom {}", culprit);
    error->all(FLERR, "fix runin/wall: non-finite contact force, area, strength or wear at step {} (first: {}, "
               "z_wall = {}, wall velocity {} {} {}); the run is unstable (a timestep too large: dt = {} s) or a "
               "coefficient overflows", update->ntimestep, atoms, wall_z, wall_velocity[0], wall_velocity[1],
               wall_velocity[2], update->dt);
  }
  totals[FX] = global[LOCAL_FX];
  totals[FY] = global[LOCAL_FY];
  totals[FZ] = global[LOCAL_FZ];
  totals[CONTACTS] = global[LOCAL_CONTACTS];
  last_normal_force = global[LOCAL_FN];
  last_stiffness = global[LOCAL_STIFFNESS];
  wall_wear += global[LOCAL_LOST];
  wall_gain += global[LOCAL_GAINED];
}

double FixRuninWall::compute_vector(int n)
{
  switch (n) {
    case WALL_Z: return wall_z;
    case WALL_DX: return wall_dx;
    case WALL_DY: return wall_dy;
    case WALL_WEAR: return wall_wear;
    case WALL_GAIN: return wall_gain;
    default: return totals[n];
  }
}

// Global restart state: the wall position, its in-plane travel, the counterface wear and gain and the
// servo's last force and stiffness, so a restarted load-controlled run continues smoothly; then the contact
// model record (sub-model names, coefficient counts and values), checked against the input's on reading.
void FixRuninWall::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> state = {kRestartFormatMark, wall_z,    wall_dx,           wall_dy,
                               wall_wear,          wall_gain, last_normal_force, last_stiffness};
  const std::vector<double> record = tribo::serialize(choice, tribo::contact_coefficients(choice, parameters));
  state.push_back(static_cast<double>(record.size()));
  state.insert(state.end(), record.begin(), record.end());
  const int size = static_cast<int>(state.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(state.data(), sizeof(double), state.size(), fp);
}

void FixRuninWall::restart(char *buf)
{
  const auto *record = reinterpret_cast<const double *>(buf);
  const bool with_model = record[0] == kRestartFormatMark;
  const bool with_gain = with_model || std::isnan(record[0]);    // else written before the counterface gain existed
  const double *state = with_gain ? record + 1 : record;
  wall_z = state[0];
  wall_dx = state[1];
  wall_dy = state[2];
  wall_wear = state[3];
  if (with_gain) ++state;
  wall_gain = with_gain ? state[3] : 0.0;
  last_normal_force = state[4];
  last_stiffness = state[5];
  if (!with_model) return;
  const int size = static_cast<int>(state[6]);
  runin_lammps::kernel_call(lmp, FLERR, "fix runin/wall: restart file", true, [&] {
    const auto stored = tribo::deserialize(state + 7, size);
    if (!(stored.first == choice))
      error->all(FLERR, "fix runin/wall: restart file: {}", tribo::describe_difference(stored.first, choice));
  });
}

void FixRuninWall::grow_arrays(int nmax)
{
  memory->grow(history, nmax, HISTORY_SIZE, "fix_runin_wall:history");
}

void FixRuninWall::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < HISTORY_SIZE; k++) history[j][k] = history[i][k];
}

void FixRuninWall::set_arrays(int i)
{
  for (int k = 0; k < HISTORY_SIZE; k++) history[i][k] = 0.0;
}

int FixRuninWall::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < HISTORY_SIZE; k++) buf[k] = history[i][k];
  return HISTORY_SIZE;
}

int FixRuninWall::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < HISTORY_SIZE; k++) history[nlocal][k] = buf[k];
  return HISTORY_SIZE;
}

int FixRuninWall::pack_restart(int i, double *buf)
{
  buf[0] = HISTORY_SIZE + 1;    // LAMMPS skips per-fix blocks by this count
  for (int k = 0; k < HISTORY_SIZE; k++) buf[k + 1] = history[i][k];
  return HISTORY_SIZE + 1;
}

void FixRuninWall::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < HISTORY_SIZE; k++) history[nlocal][k] = extra[nlocal][m++];
}

double FixRuninWall::memory_usage()
{
  return static_cast<double>(atom->nmax) * HISTORY_SIZE * sizeof(double);
}
