// The host-neutral part of fix runin/wall, shared by the LAMMPS host (fix_runin_wall.*) and the LIGGGHTS host
// (plugins/liggghts/fix_runin_wall_liggghts.*): keyword parsing into the contact model, the wall motion and
// servo, the per-asperity contact loop (geometry + runin::tribo::ContactModel::evaluate + bookkeeping), the
// messages of its checks and the global restart record. Nothing here touches a host class: the hosts hand in
// plain atom arrays, the wear-state fix (same column names and inline geometry update in both hosts) and
// callbacks for numbers, material files, warnings and errors; they keep the MPI reductions, the variables and
// the per-atom storage.
#ifndef RUNIN_WALL_CORE_H
#define RUNIN_WALL_CORE_H

#include "coefficient_grammar.h"
#include "runin_contact_sums.h"
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"
#include "tribo/contact_model.h"
#include "tribo/friction_strength.h"
#include "tribo/load_servo.h"
#include "tribo/wear.h"

#include "math_extra.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace runin_wall {

namespace tribo = runin::tribo;

inline constexpr int HISTORY_SIZE = tribo::CONTACT_HISTORY_SIZE;
enum class Control { displacement, force, pressure };

// A constant or an equal-style variable (v_name), evaluated every step by the host.
struct Setting {
  double value = 0.0;
  std::string variable;
  int ivar = -1;
};

// The host adaptor: plugins/common/coefficient_grammar.h (style "fix runin/wall", no film).
using Hooks = runin_coeff::Host;

// Everything the keywords of fix runin/wall set.
struct Config {
  tribo::ContactParameters parameters;    // the value groups' or file's (unused with the keyword block)
  tribo::ContactModelChoice choice;
  tribo::ContactCoefficients coefficients;    // checked, as the contact model holds them
  tribo::ContactSettings contact_settings;
  std::optional<tribo::ContactModel> model;
  bool wear = false;          // an Archard k > 0 (else no wear bookkeeping)
  bool reshape = true;        // worn geometry (summit drop, flat) of the wear state enters the normal force
  double side_sign = 0.0;     // +1 side lo (wall below the atoms), -1 side hi (wall above)
  double wall_z = 0.0;
  Setting vel[2], vz;
  bool vz_given = false;
  Control control = Control::displacement;
  double load_target = 0.0, servo_gain = -1.0, servo_vmax = -1.0;
};

// The wall's coefficient keywords other than `file` and `coeff`: groups of the grammar's named values
// (runin_coeff::set_named), the one place they map. `labels` name the values in messages; `selects_friction`: the
// values are a friction law's own, so the group selects that law (group_friction: the registry's first that takes
// them all).
struct ValueGroup {
  const char *keyword;
  int count;
  std::array<const char *, 3> names, labels;
  bool selects_friction;
};
inline constexpr ValueGroup kValueGroups[] = {
    {"elastic", 3, {"E*", "G*", "e"}, {"E*", "G*", "e"}, false},
    {"friction", 3, {"mu_s", "mu_k", "d_c"}, {"mu_s", "mu_k", "d_c"}, false},
    {"wear", 3, {"k", "H_i", "H_j"}, {"k", "H_asperity", "H_wall"}, false},
    {"strength", 2, {"tau_s", "plough"}, {"tau_s", "plough"}, true},
    {"junction", 2, {"f", "alpha"}, {"f", "alpha"}, true},
    {"yield", 2, {"S_y", "nu"}, {"S_y", "nu"}, false}};

inline const ValueGroup *value_group(const std::string &keyword)
{
  for (const ValueGroup &g : kValueGroups)
    if (keyword == g.keyword) return &g;
  return nullptr;
}

// The registry index of the first friction law whose coefficients include every value of group `g` (-1: none).
inline int group_friction(const ValueGroup &g)
{
  const auto &laws = tribo::registered_sub_models(tribo::SubModelKind::friction);
  for (std::size_t k = 0; k < laws.size(); ++k) {
    const auto &names = laws[k].coefficient_names;
    const auto takes = [&](const char *value) {
      return std::any_of(names.begin(), names.end(), [&](const char *n) { return std::strcmp(n, value) == 0; });
    };
    if (std::all_of(g.names.begin(), g.names.begin() + g.count, takes)) return static_cast<int>(k);
  }
  return -1;
}

using runin_coeff::fail;

// fix ID group runin/wall <keywords>: arg[0..narg), the keywords from arg[3].
inline Config parse(int narg, char **arg, const Hooks &hooks)
{
  static const std::map<std::string, int> kKeywordValues = {
      {"zplane", 1}, {"side", 1},     {"file", 3},  {"archard", 1}, {"reshape", 1}, {"vel", 2},     {"vz", 1},
      {"load", 1},     {"pressure", 1}, {"servo", 2}, {"restick", 1}, {"transfer", 1}, {"normal", 1},
      {"friction_model", 1}, {"wear_scale", 1}, {"interface", 1}, {"coeff", 0}};
  const std::string style = "fix runin/wall";
  auto kernel = [&](auto &&body) -> decltype(body()) { return runin_coeff::kernel(hooks, style, body); };
  auto parse_setting = [&](Setting &s, const char *text, const char *keyword) {
    if (std::strncmp(text, "v_", 2) == 0) {
      s.variable = text + 2;
    } else {
      s.value = runin_coeff::number(hooks, style, std::string(keyword) + " (a number or v_name)", text);
      s.variable.clear();
    }
  };

  Config c;
  tribo::ContactParameters &parameters = c.parameters;
  std::vector<std::pair<std::string, double>> named;    // the value groups' values, applied after the file's
  bool yield_given = false;
  int interface_state = -1;    // keyword interface: tau_s or f from the coefficient file's line for this state
  std::string friction_model_name;    // keyword friction_model; else the model a value group selects
  double wear_scale = 1.0;    // keyword wear_scale: wear acceleration, a factor on Archard k of both bodies
  bool have_zplane = false, have_file = false, have_block = false, have_elastic = false, have_friction = false,
       have_wear = false;
  std::string other_coefficients;    // a coefficient keyword besides the keyword block (refused with it)
  tribo::ContactCoefficients block;
  int iarg = 3;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    const auto known = kKeywordValues.find(keyword);
    const ValueGroup *group = value_group(keyword);
    if (known == kKeywordValues.end() && !group)
      fail(hooks, fmt::format("fix runin/wall: unknown keyword '{}' (expected zplane, side, coeff, file, elastic, "
                              "friction, wear, archard, reshape, vel, vz, load, pressure, servo, strength, junction, "
                              "restick, transfer, normal, yield, friction_model, wear_scale or interface)", keyword));
    if (keyword == "coeff") {
      // the keyword block of pair_coeff: all five kinds, then the wall's keywords go on
      if (have_block) fail(hooks, "fix runin/wall: keyword 'coeff' is given twice");
      iarg++;
      block = runin_coeff::read_blocks(hooks, narg, arg, iarg, c.choice, false, true);
      have_block = true;
      continue;
    }
    const int nvalues = group ? group->count : known->second;
    if (iarg + nvalues >= narg)
      fail(hooks, fmt::format("fix runin/wall: keyword '{}' needs {} value(s), got {}", keyword, nvalues,
                              narg - iarg - 1));
    char **values = &arg[iarg + 1];
    auto number = [&](int k, const char *name) { return runin_coeff::number(hooks, style, keyword + " " + name, values[k]); };

    if (group) {
      for (int k = 0; k < group->count; k++) named.emplace_back(group->names[k], number(k, group->labels[k]));
      if (group->selects_friction) {
        const int law = group_friction(*group);
        if (law < 0)    // a registry without the law (a reduced build): say which values found none
          fail(hooks, fmt::format("fix runin/wall: keyword '{}': no registered friction model takes {} and {}", keyword,
                                  group->names[0], group->names[1]));
        c.choice.index[static_cast<int>(tribo::SubModelKind::friction)] = law;
      }
      have_elastic = have_elastic || keyword == "elastic";
      have_friction = have_friction || keyword == "friction";
      have_wear = have_wear || keyword == "wear";
      yield_given = yield_given || keyword == "yield";
      other_coefficients = keyword;
    } else if (keyword == "zplane") {
      c.wall_z = number(0, "Z");
      have_zplane = true;
    } else if (keyword == "side") {
      if (std::strcmp(values[0], "lo") == 0)
        c.side_sign = 1.0;
      else if (std::strcmp(values[0], "hi") == 0)
        c.side_sign = -1.0;
      else
        fail(hooks, fmt::format("fix runin/wall: side must be 'lo' or 'hi', got '{}'", values[0]));
    } else if (keyword == "file") {
      parameters = hooks.material(values[0], values[1], values[2]);
      have_file = true;
      other_coefficients = keyword;
    } else if (keyword == "archard") {
      if (std::strcmp(values[0], "plain") == 0)
        c.contact_settings.archard_form = tribo::ArchardForm::plain;
      else if (std::strcmp(values[0], "thesis") == 0)
        c.contact_settings.archard_form = tribo::ArchardForm::thesis;
      else
        fail(hooks, fmt::format("fix runin/wall: archard must be 'plain' or 'thesis', got '{}'", values[0]));
    } else if (keyword == "reshape") {
      if (std::strcmp(values[0], "yes") == 0)
        c.reshape = true;
      else if (std::strcmp(values[0], "no") == 0)
        c.reshape = false;
      else
        fail(hooks, fmt::format("fix runin/wall: reshape must be 'yes' or 'no', got '{}'", values[0]));
    } else if (keyword == "vel") {
      parse_setting(c.vel[0], values[0], "vel vx");
      parse_setting(c.vel[1], values[1], "vel vy");
    } else if (keyword == "vz") {
      parse_setting(c.vz, values[0], "vz");
      c.vz_given = true;
    } else if (keyword == "load" || keyword == "pressure") {
      c.load_target = number(0, keyword == "load" ? "F" : "p");
      if (!(c.load_target > 0.0))
        fail(hooks, fmt::format("fix runin/wall: {} must be > 0, got {}", keyword, c.load_target));
      c.control = keyword == "load" ? Control::force : Control::pressure;
    } else if (keyword == "servo") {
      c.servo_gain = number(0, "gain");
      c.servo_vmax = number(1, "vmax");
      if (!(c.servo_gain > 0.0 && c.servo_gain <= 1.0))
        fail(hooks, fmt::format("fix runin/wall: servo gain must be in (0, 1], got {}", c.servo_gain));
      if (!(c.servo_vmax > 0.0)) fail(hooks, fmt::format("fix runin/wall: servo vmax must be > 0, got {}", c.servo_vmax));
    } else if (keyword == "friction_model") {
      friction_model_name = values[0];
      kernel([&] { return tribo::find_sub_model(tribo::SubModelKind::friction, values[0]); });
      other_coefficients = keyword;
    } else if (keyword == "normal") {
      c.choice.index[static_cast<int>(tribo::SubModelKind::normal)] =
          kernel([&] { return tribo::find_sub_model(tribo::SubModelKind::normal, values[0]); });
      other_coefficients = keyword;
    } else if (keyword == "interface") {
      interface_state = kernel([&] { return tribo::find_interface_state(values[0]); });
      other_coefficients = keyword;
    } else if (keyword == "wear_scale") {
      wear_scale = number(0, "factor");
      if (!(wear_scale > 0.0) || !std::isfinite(wear_scale))
        fail(hooks, fmt::format("fix runin/wall: wear_scale factor must be > 0 and finite, got {}", wear_scale));
    } else if (keyword == "restick") {
      c.contact_settings.restick_speed = number(0, "v");
      if (!(c.contact_settings.restick_speed >= 0.0) || !std::isfinite(c.contact_settings.restick_speed))
        fail(hooks, fmt::format("fix runin/wall: restick speed must be >= 0 m/s, got {}",
                                c.contact_settings.restick_speed));
    } else if (keyword == "transfer") {
      c.contact_settings.transfer_fraction = number(0, "f");
      if (!(c.contact_settings.transfer_fraction >= 0.0 && c.contact_settings.transfer_fraction <= 1.0))
        fail(hooks, fmt::format("fix runin/wall: transfer fraction must be in [0, 1], got {}",
                                c.contact_settings.transfer_fraction));
    }
    iarg += nvalues + 1;
  }

  if (!have_zplane) fail(hooks, "fix runin/wall: keyword 'zplane' is required");
  if (c.side_sign == 0.0) fail(hooks, "fix runin/wall: keyword 'side' (lo or hi) is required");
  if (have_block && !other_coefficients.empty())
    fail(hooks, fmt::format("fix runin/wall: give either 'coeff' (the keyword block, which names every sub-model) or "
                            "'{}', not both", other_coefficients));
  if (have_file && (have_elastic || have_friction || have_wear))
    fail(hooks, "fix runin/wall: give either 'file' or 'elastic'/'friction'/'wear', not both");
  if (!have_block && !have_file && !(have_elastic && have_friction && have_wear))
    fail(hooks, "fix runin/wall: coefficients missing: give 'file PATH ASPERITY WALL', all of 'elastic', 'friction' "
                "and 'wear', or 'coeff' and the keyword block");
  if (c.control != Control::displacement && c.servo_vmax < 0.0)
    fail(hooks, "fix runin/wall: load control needs 'servo GAIN VMAX'");
  if (c.control != Control::displacement && c.vz_given)
    fail(hooks, "fix runin/wall: 'vz' and 'load'/'pressure' exclude each other");

  if (!friction_model_name.empty())
    c.choice.index[static_cast<int>(tribo::SubModelKind::friction)] =
        tribo::find_sub_model(tribo::SubModelKind::friction, friction_model_name);
  // the film coverage is a per-summit state that only pair runin/asperity keeps
  const tribo::SubModelInfo &friction =
      tribo::registered_sub_models(tribo::SubModelKind::friction)[c.choice.of(tribo::SubModelKind::friction)];
  if (friction.has_film)
    fail(hooks, fmt::format("fix runin/wall: {} '{}' is not supported on the wall (the film coverage is kept by pair "
                            "runin/asperity only); use a friction model without a film",
                            have_block ? "friction" : "friction_model", friction.name));

  runin_coeff::Read read;
  if (have_block) {
    read.origin = "keywords";
    read.values = block;
    for (const char *k : {"k_i", "k_j"})
      if (const int index = runin_coeff::named_index(c.choice, tribo::SubModelKind::wear, k); index >= 0)
        read.values.of(tribo::SubModelKind::wear)[index] *= wear_scale;
  } else {
    for (const auto &[name, value] : named) runin_coeff::set_named(parameters, name, value);
    // S_y and nu of the yielding body: keyword 'yield', else the material file, else Tabor's H / 2.8
    if (!yield_given && !have_file) runin_coeff::yield_from_hardness(parameters);
    parameters.wear_coefficient *= wear_scale;
    parameters.interface_state = interface_state;
    kernel([&] {
      if (!(parameters.hardness_i > 0.0))
        throw tribo::InvalidCoefficient(fmt::format("H_asperity: hardness must be > 0, got {}", parameters.hardness_i));
      if (!(parameters.hardness_j > 0.0))
        throw tribo::InvalidCoefficient(fmt::format("H_wall: hardness must be > 0, got {}", parameters.hardness_j));
    });
    read.parameters = parameters;
  }
  // the grammar's checks, once for every form; the contact model validates its coefficients and names the bad one
  c.coefficients = runin_coeff::checked(hooks, read, c.choice, c.contact_settings, style, style, "keyword yield");
  c.model.emplace(c.choice, c.coefficients, c.contact_settings);
  for (const char *k : {"k_i", "k_j"})
    if (const double *value = runin_coeff::named_coefficient(c.choice, c.coefficients, tribo::SubModelKind::wear, k))
      c.wear = c.wear || *value > 0.0;
  return c;
}

// The wall's state between steps (and in the global restart record).
struct Motion {
  double wall_z = 0.0, wall_dx = 0.0, wall_dy = 0.0, wall_wear = 0.0, wall_gain = 0.0;
  double last_normal_force = 0.0;    // elastic sum F_n (no damping) of the last evaluation (servo)
  double last_stiffness = 0.0;       // sum dF_n/d(overlap) of the last evaluation (servo)
  double velocity[3] = {0.0, 0.0, 0.0};
};

// A wall that moves further than a summit radius in one step skips whole contacts. Every rank evaluates the
// same variables, so the check is collective: the message, or empty.
inline std::string wall_step_problem(const double *v, double dt, double smallest_radius, long long step_number)
{
  if (!std::isfinite(v[0] + v[1] + v[2]))
    return fmt::format("fix runin/wall: wall velocity ({}, {}, {}) m/s is not finite at step {} (vel/vz values or "
                       "variables)", v[0], v[1], v[2], step_number);
  const double step = std::hypot(v[0], v[1], v[2]) * dt;
  if (step > smallest_radius)
    return fmt::format("fix runin/wall: at step {} the wall moves {:.4g} m per step (speed {:.4g} m/s, dt = {} s), "
                       "more than the smallest asperity radius {:.4g} m: contacts are not resolved in time (lower the "
                       "speed or the timestep)", step_number, step, step / dt, dt, smallest_radius);
  return {};
}

// Displacement control: z += vz dt. Load control: runin::tribo::LoadServo moves the wall toward the
// asperities from the previous step's total normal force and contact stiffness (monotone approach).
// `area`: the nominal area x * y (pressure control). Throws on a bad servo state (host: collective ERROR).
inline void move_wall(const Config &c, Motion &m, double dt, double area)
{
  m.wall_dx += m.velocity[0] * dt;
  m.wall_dy += m.velocity[1] * dt;
  if (c.control == Control::displacement) {
    m.wall_z += m.velocity[2] * dt;
    return;
  }
  const double target = c.control == Control::force ? c.load_target : c.load_target * area;
  const tribo::LoadServo servo(c.servo_gain, c.servo_vmax * dt);
  const double approach = servo.approach(m.last_normal_force, m.last_stiffness, target);
  m.wall_z += c.side_sign * approach;
  m.velocity[2] = c.side_sign * approach / dt;
}

// Per-rank outputs of one contact evaluation, before the host reduces them.
enum LocalIndex {
  LOCAL_FX = 0, LOCAL_FY, LOCAL_FZ, LOCAL_CONTACTS, LOCAL_FN, LOCAL_STIFFNESS, LOCAL_LOST, LOCAL_GAINED,
  LOCAL_CHECK, LOCAL_THROUGH, NLOCAL
};
template <class Tag> struct StepLocal {
  // force on the wall xyz, contacts, elastic normal force and stiffness (servo), wall wear and gain this step;
  // LOCAL_CHECK sums every contact output (NaN and inf propagate); LOCAL_THROUGH counts walls past a centre
  double local[NLOCAL] = {};
  Tag first_bad = std::numeric_limits<Tag>::max();        // lowest atom ID with a non-finite output
  Tag first_through = std::numeric_limits<Tag>::max();    // lowest atom ID the wall passed the centre of
  Tag worst_atom = 0;                                      // furthest beyond its normal law's range
  double worst_range = 1.0, beyond_range = 0.0;            // its range ratio; contacts beyond (ratio > 1)
};

// The host's per-atom arrays (owned atoms 0..nlocal).
template <class Tag> struct Atoms {
  double **x, **v, **f, **omega, **torque;
  const double *radius, *rmass;
  const int *mask;
  const Tag *tag;
  int nlocal;
};

// The contacts of the group's asperities with the wall: forces and torques added to the atoms, the per-atom
// contact history advanced (advance), wear and plastic flattening added to the wear state, the contact sums
// filled. WearFix: FixRuninWearState (LAMMPS) or FixRuninWearStateLiggghts (the same columns and inline
// geometry update).
template <int NORMAL, int FRICTION, class WearFix, class Tag>
void contacts(const Config &c, const Motion &m, const Atoms<Tag> &a, double **history, WearFix *fix_wear,
              int groupbit, int body_groupbit, double dt, bool advance, LAMMPS_NS::RuninContactSums &sums,
              StepLocal<Tag> &out)
{
  using ::MathExtra::cross3;
  sums = LAMMPS_NS::RuninContactSums();
  const bool track_wear = advance && c.wear;
  const tribo::ContactModel &model = *c.model;
  double **x = a.x, **v = a.v, **f = a.f, **omega = a.omega, **torque = a.torque;
  const double *radius = a.radius, *rmass = a.rmass;
  const int *mask = a.mask;
  const Tag *tag = a.tag;
  const double side_sign = c.side_sign, wall_z = m.wall_z;
  const double *wall_velocity = m.velocity;
  double **wear_state = fix_wear ? fix_wear->state() : nullptr;
  const bool worn_geometry = c.reshape && wear_state;
  if (worn_geometry && !advance) fix_wear->refresh_geometry_all();    // volumes may have been set or restarted
  const double normal[3] = {0.0, 0.0, side_sign};    // from the wall to the asperity
  double *local = out.local;
  for (int i = 0; i < a.nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double r = radius[i];
    // a worn summit sits lower by its wear depth and carries a flat (pair runin/asperity reshape)
    const double summit_drop = worn_geometry ? wear_state[i][WearFix::WEAR_DEPTH] : 0.0;
    const double overlap = r - summit_drop - side_sign * (x[i][2] - wall_z);
    if (overlap <= 0.0) {
      // the spring and slip belong to one contact; the largest interference belongs to the asperity under
      // this flat and stays, so a reload retraces the elastic unloading curve up to it
      for (int k = 0; k < HISTORY_SIZE; k++)
        if (!tribo::is_normal_history(k)) history[i][k] = 0.0;
      continue;
    }
    if (overlap + std::max(summit_drop, 0.0) > r) {
      // past the centre of the intact sphere (worn or flattened summits included): no sphere contact law
      // holds (the run stops after the reduction)
      local[LOCAL_THROUGH] += 1.0;
      out.first_through = std::min(out.first_through, tag[i]);
    }
    const double flat = worn_geometry ? wear_state[i][WearFix::FLAT_RADIUS] : 0.0;
    tribo::ContactGeometry g =
        tribo::sphere_flat_geometry(overlap, normal, flat, r, rmass[i], v[i], wall_velocity, omega[i]);
    g.summit_drop = std::max(summit_drop, 0.0);
    // a flattened summit under a contact without plastic history is a reload: the model restores the state
    // that flattened it (the history kept below normally holds it already)
    if (worn_geometry && summit_drop > 0.0 && !tribo::has_plastic_history(history[i]))
      g.flattened_drop = tribo::flattened_part_of_drop(r, summit_drop, wear_state[i][WearFix::VOLUME_FLATTENED]);

    const tribo::ContactResult contact = model.evaluate<NORMAL, FRICTION, 1>(g, history[i], dt, advance);
    const double fn = contact.normal_force;
    const double *ft = contact.tangential.force;
    const double outputs = fn + ft[0] + ft[1] + ft[2] + contact.normal.contact_radius + contact.strength.adhesion +
                           contact.strength.ploughing + contact.wear.lost_a + contact.wear.lost_b;
    local[LOCAL_CHECK] += outputs;
    if (!std::isfinite(outputs)) out.first_bad = std::min(out.first_bad, tag[i]);
    const double range = contact.normal.range_ratio;
    out.beyond_range += range > 1.0;
    out.worst_atom = range > out.worst_range ? tag[i] : out.worst_atom;
    out.worst_range = std::max(range, out.worst_range);

    double tor[3];
    cross3(normal, ft, tor);
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
      wear_state[i][WearFix::VOLUME_FLATTENED] +=
          WearFix::flattened_volume(r, summit_drop, contact.normal.residual_increment);
      fix_wear->refresh_geometry(i, r);
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
    sums.contact_area += contact.normal.real_area;
    sums.adhesion_force += contact.strength.adhesion;
    sums.ploughing_force += contact.strength.ploughing;
    if (advance && dt > 0.0)
      sums.frictional_power += contact.tangential.force_magnitude * contact.tangential.slip_increment / dt;
    if (track_wear && contact.tangential.slip_increment > 0.0) {
      const tribo::WearExchange &exchange = contact.wear;
      if (wear_state) {
        wear_state[i][WearFix::VOLUME_LOST] += exchange.lost_a;
        wear_state[i][WearFix::VOLUME_GAINED] += exchange.gained_a;
        if (worn_geometry) fix_wear->refresh_geometry(i, r);
      }
      local[LOCAL_LOST] += exchange.lost_b;
      local[LOCAL_GAINED] += exchange.gained_b;
      sums.wear_volume += contact.worn_volume;
    }
  }
  for (int k = 0; k < 3; k++) sums.counterface_force[k] = local[LOCAL_FX + k];
}

// After the host summed StepLocal::local over ranks into `global`: the wall's totals and state.
inline void take_totals(const double *global, Motion &m, double *fx3, double &contacts)
{
  for (int k = 0; k < 3; k++) fx3[k] = global[LOCAL_FX + k];
  contacts = global[LOCAL_CONTACTS];
  m.last_normal_force = global[LOCAL_FN];
  m.last_stiffness = global[LOCAL_STIFFNESS];
  m.wall_wear += global[LOCAL_LOST];
  m.wall_gain += global[LOCAL_GAINED];
}

inline bool step_finite(const double *global, const Motion &m)
{
  return std::isfinite(global[LOCAL_FX] + global[LOCAL_FY] + global[LOCAL_FZ] + global[LOCAL_CHECK] + m.wall_z);
}

inline std::string past_centre_message(long long step, double wall_z, double count, long long culprit)
{
  return fmt::format("fix runin/wall: at step {} the wall (z = {}) has passed the centre of {:.0f} intact "
                     "asperity sphere(s), first atom {}: the interference exceeds the summit radius, where no "
                     "contact law holds (load or wall travel too high for these asperities)", step, wall_z, count,
                     culprit);
}

inline std::string past_centre_summary(long long count)
{
  return fmt::format("fix runin/wall: {} asperity evaluations in this run were past the centre of their summit "
                     "(outside every contact law's validity; the first is reported above)", count);
}

inline std::string non_finite_message(long long step, bool have_culprit, long long culprit, const Motion &m, double dt)
{
  const std::string atoms = have_culprit ? fmt::format("atom {}", culprit) : std::string("no atom");
  return fmt::format("fix runin/wall: non-finite contact force, area, strength or wear at step {} (first: {}, "
                     "z_wall = {}, wall velocity {} {} {}); the run is unstable (a timestep too large: dt = {} s) or a "
                     "coefficient overflows", step, atoms, m.wall_z, m.velocity[0], m.velocity[1], m.velocity[2], dt);
}

// Global restart record: the wall position, its in-plane travel, the counterface wear and gain and the
// servo's last force and stiffness, so a restarted load-controlled run continues smoothly; then the contact
// model record (sub-model names, coefficient counts and values), checked against the input's on reading.
// Leads the record: older records start with NaN (with the counterface gain) or with z_wall.
inline constexpr double kRestartFormatMark = -7.0e77;

inline std::vector<double> restart_record(const Config &c, const Motion &m)
{
  std::vector<double> state = {kRestartFormatMark, m.wall_z,    m.wall_dx,           m.wall_dy,
                               m.wall_wear,        m.wall_gain, m.last_normal_force, m.last_stiffness};
  const std::vector<double> record = tribo::serialize(c.choice, c.coefficients);
  state.push_back(static_cast<double>(record.size()));
  state.insert(state.end(), record.begin(), record.end());
  return state;
}

// Reads the record into `m`; returns a problem (the stored contact model differs from the input's) or empty.
// Throws (a RunIn kernel exception) on a malformed model record.
inline std::string read_restart_record(const char *buf, const Config &c, Motion &m)
{
  const auto *record = reinterpret_cast<const double *>(buf);
  const bool with_model = record[0] == kRestartFormatMark;
  const bool with_gain = with_model || std::isnan(record[0]);    // else written before the counterface gain existed
  const double *state = with_gain ? record + 1 : record;
  m.wall_z = state[0];
  m.wall_dx = state[1];
  m.wall_dy = state[2];
  m.wall_wear = state[3];
  if (with_gain) ++state;
  m.wall_gain = with_gain ? state[3] : 0.0;
  m.last_normal_force = state[4];
  m.last_stiffness = state[5];
  if (!with_model) return {};
  const int size = static_cast<int>(state[6]);
  const auto stored = tribo::deserialize(state + 7, size);
  if (!(stored.first == c.choice)) return tribo::describe_difference(stored.first, c.choice);
  return {};
}

}    // namespace runin_wall

#endif
