// One asperity contact model for every host (pair runin/asperity, fix runin/wall, later hosts), after
// LAMMPS's GranularModel: the host supplies the geometry of a contact and its history; the model returns
// the normal and tangential forces, updates the history, and gives the friction-strength parts and the
// worn volumes of both bodies. Hosts keep only geometry and bookkeeping.
//
// The contact is a set of sub-models, one per kind: normal, damping, tangential, friction and wear. Each
// sub-model is a small class with a name, its coefficient names (their count), a validating constructor
// (throws InvalidCoefficient naming the coefficient) and a mixing rule for unset I,J type pairs. The
// registry below (one std::tuple per kind) is the one place to add a law: write the class, add it to its
// tuple. Hosts dispatch on the tuple index at compile time, so a switched-off feature costs nothing.
#pragma once

#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"
#include "tribo/elastic_plastic.h"
#include "tribo/friction_strength.h"
#include "tribo/model_citations.h"
#include "tribo/surface_film.h"
#include "tribo/wear.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <type_traits>
#include <tuple>
#include <utility>
#include <optional>
#include <vector>

namespace runin::tribo {

// What a host knows about one contact.
struct ContactGeometry {
  double overlap = 0.0;             // delta, measured from the current (worn) summits [m]
  double effective_radius = 0.0;    // R* [m]
  double effective_mass = 0.0;      // m* [kg]
  double flat_radius = 0.0;         // b, flat of a worn summit (0: intact sphere) [m]
  double summit_drop = 0.0;         // how far the summits sit below the intact spheres (wear and plastic
                                    // flattening, both bodies, >= 0): overlap + drop is the spheres' interference
  // The part of summit_drop that plastic flattening left (flattened_part_of_drop, both bodies) [m]. Read only
  // by the elastic-plastic model for a contact without plastic history (a reload), so hosts set it only then.
  double flattened_drop = 0.0;
  double normal[3] = {0.0, 0.0, 0.0};    // unit normal, from the counter-body towards body i
  double normal_velocity = 0.0;     // v_n of i relative to the counter-body (< 0: approach) [m/s]
  double tangential_velocity[3] = {0.0, 0.0, 0.0};    // v_t at the contact point, rolling included [m/s]
  // Mean film coverage of the two summits, in [0, 1]: read only by friction models with a film (HasFilm), so
  // hosts set it only for them.
  double film_coverage = 0.0;
};

// The kinematic part of a contact's geometry, shared by every host (pair loops, single(), wall). The arithmetic
// is fixed: hosts that must print the same digits call these, never a copy.
namespace geometry_detail {
inline double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline void cross3(const double *a, const double *b, double *out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
// v_n, then v_t = v_r - v_n n + n x spin (the contact point's velocity of i relative to the counter-body)
inline void relative_velocities(ContactGeometry &g, const double *vr, const double *spin)
{
  g.normal_velocity = dot3(vr, g.normal);
  double spin_velocity[3];
  cross3(g.normal, spin, spin_velocity);
  for (int k = 0; k < 3; k++) g.tangential_velocity[k] = vr[k] - g.normal_velocity * g.normal[k] + spin_velocity[k];
}
}    // namespace geometry_detail

// Spheres i and j (radius, mass, velocity, angular velocity) at centre distance 1 / rinv along del = x_i - x_j,
// interfering by `overlap`, with the flat radius `flat` of their worn summits: normal towards i, m*, R* and the
// relative velocities of i at the contact point. The summit drops are the host's.
inline ContactGeometry sphere_sphere_geometry(double overlap, double rinv, const double *del, double flat,
                                              double radi, double radj, double massi, double massj,
                                              const double *vi, const double *vj, const double *omegai,
                                              const double *omegaj)
{
  ContactGeometry g;
  const double radsum = radi + radj;
  g.overlap = overlap;
  g.flat_radius = flat;
  for (int k = 0; k < 3; k++) g.normal[k] = del[k] * rinv;
  // m* = m_i m_j / (m_i + m_j) and R* = r_i r_j / (r_i + r_j) from one division
  const double mass_sum = massi + massj;
  const double inv_sums = 1.0 / (mass_sum * radsum);
  g.effective_mass = massi * massj * radsum * inv_sums;
  g.effective_radius = radi * radj * mass_sum * inv_sums;
  const double vr[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
  const double spin[3] = {radi * omegai[0] + radj * omegaj[0], radi * omegai[1] + radj * omegaj[1],
                          radi * omegai[2] + radj * omegaj[2]};
  geometry_detail::relative_velocities(g, vr, spin);
  return g;
}

// A sphere (radius, mass, velocity, angular velocity) on a rigid flat moving at `flat_velocity`, with the unit
// normal from the flat to the sphere: R* is the sphere's radius, m* its mass.
inline ContactGeometry sphere_flat_geometry(double overlap, const double *normal, double flat, double radius,
                                            double mass, const double *v, const double *flat_velocity,
                                            const double *omega)
{
  ContactGeometry g;
  g.overlap = overlap;
  g.flat_radius = flat;
  g.effective_radius = radius;
  g.effective_mass = mass;
  for (int k = 0; k < 3; k++) g.normal[k] = normal[k];
  const double vr[3] = {v[0] - flat_velocity[0], v[1] - flat_velocity[1], v[2] - flat_velocity[2]};
  const double spin[3] = {radius * omega[0], radius * omega[1], radius * omega[2]};
  geometry_detail::relative_velocities(g, vr, spin);
  return g;
}

// Per-contact history: each model that keeps some declares its slots (`history_slots`, indexed from 0 by the model);
// the registry places them (the layout after the registry: kTangentialHistoryOffset, kNormalHistoryOffset).

// Output of a normal sub-model.
struct NormalContact {
  double force = 0.0;             // elastic (or elastic-plastic) force, no damping [N]
  double stiffness = 0.0;         // dF/d(delta) [N/m]
  double contact_radius = 0.0;    // a [m]
  // Area that carries the adhesion [m^2]: pi a^2, except on an elastically reloaded worn flat (below)
  double real_area = 0.0;
  // Ploughing force of the permanent groove (elastic-plastic models; 0 below yield) [N], and whether the
  // model knows plasticity at all (an elastic model leaves ploughing to the cone of friction_strength.h)
  double groove_ploughing = 0.0;
  bool plastic_model = false;
  // Growth of the residual (plastic) interference in this step [m]: the host lowers the summits by it
  double residual_increment = 0.0;
  // Full-stick critical load L_c of the equivalent sphere (Brizmer et al.; elastic-plastic models) [N]
  double stick_critical_load = 0.0;
  // Interference over the largest the law is checked to (elastic/plastic, on loading: omega / (1000
  // omega_c)); above 1 the contact is beyond the law's range and the hosts count it (a WARNING)
  double range_ratio = 0.0;
};

// ---------------------------------------------------------------------------------------------------
// Sub-models. Each: `name`, `coefficient_names` (their count is the coefficient count), a constructor
// from the values that validates them, `values()` giving them back, and `mix(ii, jj)`.
// ---------------------------------------------------------------------------------------------------

using Coefficients = std::vector<double>;

// Capabilities a sub-model class declares and hosts query (through these traits at compile time, or through
// SubModelInfo at run time), so no host names a concrete model.
// What an interface state (friction_strength.h: a friction factor m per state) sets in a friction law: nothing, its
// tau_s = m S_y / sqrt(3) (`shear_strength`) or its interface coefficient f = m (`interface_coefficient`).
enum class InterfaceUse { none, shear_strength, interface_coefficient };
template <class Model, class = void> struct InterfaceUseOf : std::integral_constant<InterfaceUse, InterfaceUse::none> {};
template <class Model>
struct InterfaceUseOf<Model, std::void_t<decltype(Model::interface_use)>>
    : std::integral_constant<InterfaceUse, Model::interface_use> {};
// A normal law whose plastic flattening lowers the summits (static constexpr bool flattens_summits = true): the hosts
// keep the wear state for it and seed its reloads.
template <class Model, class = void> struct FlattensSummits : std::false_type {};
template <class Model>
struct FlattensSummits<Model, std::void_t<decltype(Model::flattens_summits)>>
    : std::bool_constant<Model::flattens_summits> {};
// A friction law's cross-model check (`template <class Normal, class Wear> void check_with(const Normal &, const Wear &)
// const`), which ContactModel runs with the chosen normal and wear models.
template <class Model, class Normal, class Wear, class = void> struct HasCrossCheck : std::false_type {};
template <class Model, class Normal, class Wear>
struct HasCrossCheck<Model, Normal, Wear,
                     std::void_t<decltype(std::declval<const Model &>().check_with(std::declval<const Normal &>(),
                                                                                  std::declval<const Wear &>()))>>
    : std::true_type {};
// For a friction law's check_with: refuses a normal law that does not flatten the summits ("friction model '<name>'
// needs the normal model '<the first registered one that does>'"). Defined after the registry.
template <class Normal> void require_flattening_normal(const char *friction_name);
// For a junction law's from_parameters: which contacts are plastic junctions follows from S_y (Tabor's H / 2.8 guess
// is not taken for it), and the interface coefficient must be given. `yield_keys` and `f_keys` name where each is set.
template <class P>
void require_junction_inputs(const P &p, const char *name, const char *yield_keys, const char *f_name,
                             const char *f_keys)
{
  if (p.yield_from_hardness)
    throw InvalidCoefficient(std::string("S_y: friction model '") + name +
                             "' needs the yield strength of the softer body, not Tabor's H / 2.8 (" + yield_keys + ")");
  if (std::isnan(p.interface_coefficient))
    throw InvalidCoefficient(std::string("f: friction model '") + name + "' needs the " + f_name + " f, 0 <= f < 1 (" +
                             f_keys + ")");
}
// For a friction law's check_with: a film at the interface cannot shear harder than the bulk under it.
inline void check_shear_strength_below_hardness(double shear_strength, double softer_hardness)
{
  if (shear_strength <= softer_hardness) return;
  char message[160];
  std::snprintf(message, sizeof message,
                "tau_s: interfacial shear strength %.4g Pa exceeds the hardness of the softer body, %.4g Pa",
                shear_strength, softer_hardness);
  throw InvalidCoefficient(message);
}

// Harmonic mean of 1/X: exact for E* and G* of unlike materials from the like-pair values
// (1/E*_ij = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j = (1/E*_ii + 1/E*_jj) / 2; the same for G*).
inline double mix_compliance(double a, double b) { return 2.0 / (1.0 / a + 1.0 / b); }
// LAMMPS GRANULAR's rule for interface properties that no material fixes (friction, restitution).
inline double mix_geometric(double a, double b) { return std::sqrt(a * b); }

// Normal: Hertz, or Sneddon's flat punch + Hertz on a worn flat (asperity_geometry.h).
class HertzNormalModel {
 public:
  static constexpr const char *name = "hertz";
  static constexpr std::array<const char *, 1> citations{kCiteHertz};    // model_citations.h
  static constexpr std::array<const char *, 1> coefficient_names{"E*"};
  static constexpr int history_slots = 0;
  // the coefficients from the named parameters of the explicit and file forms (ContactParameters)
  template <class P> static Coefficients from_parameters(const P &p) { return {p.effective_modulus}; }
  explicit HertzNormalModel(const double *c) : e_eff_(c[0])
  {
    HertzNormal(c[0], 1.0);    // validates E*
    if (!std::isfinite(c[0])) throw InvalidCoefficient("E*: effective modulus must be finite");
  }
  Coefficients values() const { return {e_eff_}; }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    return {mix_compliance(ii[0], jj[0])};
  }

  NormalContact evaluate(const ContactGeometry &g, double *, bool) const
  {
    const FlatHertzContact c = flat_hertz_contact(e_eff_, g.effective_radius, g.flat_radius, g.overlap);
    NormalContact out;
    out.force = c.force;
    out.stiffness = c.stiffness;
    out.contact_radius = c.contact_radius;
    out.real_area = 3.14159265358979323846 * c.contact_radius * c.contact_radius;
    return out;
  }
  double elastic_energy(const ContactGeometry &g, const double *) const
  {
    return FlatHertzNormal(e_eff_, g.effective_radius, g.flat_radius).elastic_energy(g.overlap);
  }
  double effective_modulus() const { return e_eff_; }

 private:
  double e_eff_;
};

// Normal: elastic-plastic sphere on a flat (elastic_plastic.h): Jackson & Green (2005) loading, Etsion,
// Kligerman & Kadin (2005) unloading and elastic reloading up to the earlier maximum interference, kept per
// contact in its history slots. Coefficients: E*, and S_y, nu of the yielding (softer) body. The curves
// are self-similar in R* (omega_c ~ R, P ~ R^2), so one unit-radius curve per type pair serves every size.
// The interference is that of the intact spheres, omega = delta + summit drop. Where the residual
// interference of omega_max lies below the summits' drop, the difference is returned (residual_increment):
// the host lowers the summits by it (a flattened cap in the per-asperity truncated-sphere state), so later
// contacts see the flat. Reloading a plastically flattened summit retraces the EKK unloading curve (elastic
// reloading, Kadin, Kligerman & Etsion 2006): a contact that starts without plastic history on summits that
// plastic flattening lowered by g.flattened_drop starts on the curve of the omega_max whose residual
// interference that is (seed_reload_history: the same state a kept history holds). A flat that no plastic
// history explains (worn by Archard wear: a truncated sphere) reloads elastically (Sneddon's flat punch + Hertz)
// until it reaches the elastic-plastic force at omega. doc/elastic_plastic_contact.md, "Reloading".
class ElasticPlasticNormalModel {
 public:
  static constexpr const char *name = "elastic/plastic";
  static constexpr std::array<const char *, 2> citations{kCiteJacksonGreen, kCiteEtsionKligermanKadin};
  static constexpr std::array<const char *, 3> coefficient_names{"E*", "S_y", "nu"};
  // its history slots: the largest interference omega_max of this contact [m] (first: has_plastic_history), then
  // the values of its unloading curve, kept so that a contact below omega_max costs one power (R* = 1 units)
  enum Slot {
    MAX_OVERLAP = 0,
    RESIDUAL,      // omega_res / R
    MAX_FORCE,     // P(omega_max) / R^2
    MAX_RADIUS,    // a(omega_max) / R
    EXPONENT,      // EKK unloading exponent n
    GROOVE,        // ploughing force of the groove / R^2
    SLOTS
  };
  static constexpr int history_slots = SLOTS;
  static constexpr bool flattens_summits = true;
  template <class P> static Coefficients from_parameters(const P &p)
  {
    return {p.effective_modulus, p.yield_strength, p.poisson_ratio};
  }
  explicit ElasticPlasticNormalModel(const double *c)
      : e_eff_(c[0]), unit_(c[0], 1.0, c[1], c[2]), plastic_table_(unit_),
        inv_omega_c_(1.0 / unit_.critical_interference()),
        stick_critical_load_(BrizmerStaticFriction::critical_load_ratio(c[2]) * unit_.critical_force()),
        inv_flow_pressure_(1.0 / (JacksonGreen::kHardnessLimit * c[1]))
  {
  }
  Coefficients values() const
  {
    return {e_eff_, unit_.coefficients().yield_strength, unit_.coefficients().poisson_ratio};
  }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    // the softer body yields: its S_y and nu
    const Coefficients &soft = ii[1] <= jj[1] ? ii : jj;
    return {mix_compliance(ii[0], jj[0]), soft[1], soft[2]};
  }

  NormalContact evaluate(const ContactGeometry &g, double *history, bool advance) const
  {
    const double R = g.effective_radius, inv_R = 1.0 / R;
    const double omega = (g.overlap + g.summit_drop) * inv_R;    // R = 1 units until the end
    // the plastic slots: this contact's, or, for a reload of flattened summits, the state that flattened them
    double seeded[history_slots];
    const double *plastic = history;
    if (!(history[MAX_OVERLAP] > 0.0) && g.flattened_drop > 0.0) {
      seed_reload_history(g.flattened_drop, R, seeded);
      if (advance)
        for (int k = 0; k < history_slots; ++k) history[k] = seeded[k];
      else
        plastic = seeded;
    }
    const double omega_max = plastic[0] * inv_R;
    const double cached_residual = plastic[RESIDUAL];
    NormalContact out;
    out.plastic_model = true;
    out.stick_critical_load = stick_critical_load_ * R * R;
    const bool loading = omega >= omega_max;
    double residual = cached_residual, exponent = 0.0;

    if (loading) {
      out.range_ratio = omega * inv_omega_c_ * (1.0 / JacksonGreen::kCheckedRange);
      load(omega, out, residual, exponent);
    } else if (!(cached_residual > 0.0)) {
      // an elastic history: unloading is the (Hertz) loading curve itself
      const ContactPoint p = unit_.evaluate(omega);
      out.force = p.force;
      out.contact_radius = p.contact_radius;
      out.stiffness = p.stiffness;
    } else {
      // EKK unloading / elastic reloading below omega_max, P = P_max s^n and a = a_max s^(n-1), from the
      // cached curve; 0 once the contact has opened (the groove stays)
      out.groove_ploughing = plastic[GROOVE];
      if (omega > cached_residual) {
        const double gap = omega - cached_residual;
        const double s = gap / (omega_max - cached_residual);
        const double n = plastic[EXPONENT];
        const double s_n = std::exp(n * std::log(s));
        out.force = plastic[MAX_FORCE] * s_n;
        out.stiffness = n * out.force / gap;
        out.contact_radius = plastic[MAX_RADIUS] * s_n / s;
      }
    }
    out.force *= R * R;
    out.contact_radius *= R;
    out.stiffness *= R;
    out.groove_ploughing *= R * R;
    out.real_area = kPi * out.contact_radius * out.contact_radius;

    // a flat that this contact's own plastic history does not explain (worn, or flattened by an earlier
    // contact) reloads elastically (Sneddon) until it reaches the elastic-plastic force
    if (g.flat_radius > 0.0 && g.summit_drop > cached_residual * R * (1.0 + 1e-12)) {
      const FlatHertzContact flat = flat_hertz_contact(e_eff_, R, g.flat_radius, g.overlap);
      if (flat.force < out.force) {
        out.force = flat.force;
        out.stiffness = flat.stiffness;
        out.contact_radius = flat.contact_radius;
        out.groove_ploughing = 0.0;    // an elastic flat ploughs nothing; no new plastic history
        out.real_area = worn_flat_real_area(flat.force, flat.contact_radius);
        return out;
      }
    }
    if (advance && loading && omega > omega_max) {
      history[MAX_OVERLAP] = omega * R;
      history[RESIDUAL] = residual;
      history[MAX_FORCE] = out.force * inv_R * inv_R;
      history[MAX_RADIUS] = out.contact_radius * inv_R;
      history[EXPONENT] = exponent;
      history[GROOVE] = out.groove_ploughing * inv_R * inv_R;
      // the summits sink to the residual interference where it lies below them (a new contact on a summit
      // that is already flat or worn flattens it only beyond that)
      const double sink = residual * R - g.summit_drop;
      out.residual_increment = sink > 0.0 ? sink : 0.0;
    }
    return out;
  }
  // The plastic history slots (history_slots values) that loading to the omega_max
  // whose EKK residual interference is `flattened_drop` leaves, for R* = R: what a contact that had made that
  // flat would hold (the same loading evaluation). The residual is flattened_drop itself.
  void seed_reload_history(double flattened_drop, double R, double *slots) const
  {
    const double residual = flattened_drop / R;
    const double omega_max =
        ElasticPlasticUnloading::max_interference_of_residual(residual * inv_omega_c_) * unit_.critical_interference();
    NormalContact peak;
    double ignored_residual, exponent;
    load(omega_max, peak, ignored_residual, exponent);
    slots[0] = omega_max * R;
    slots[RESIDUAL] = residual;
    slots[MAX_FORCE] = peak.force;
    slots[MAX_RADIUS] = peak.contact_radius;
    slots[EXPONENT] = exponent;
    slots[GROOVE] = peak.groove_ploughing;
  }
  double elastic_energy(const ContactGeometry &g, const double *history) const
  {
    // the energy an unloading would give back: the integral of the current (un)loading curve from its zero
    const double R = g.effective_radius;
    const double omega = (g.overlap + g.summit_drop) / R;
    double stored = history[MAX_OVERLAP];
    if (!(stored > 0.0) && g.flattened_drop > 0.0) {    // a reload, as evaluate() sees it
      double seeded[history_slots];
      seed_reload_history(g.flattened_drop, R, seeded);
      stored = seeded[0];
    }
    const double omega_max = std::max(stored / R, omega);
    const ElasticPlasticUnloading unloading(unit_, omega_max);
    if (!(omega > unloading.residual_interference())) return 0.0;
    // P = P_max s^n with s = (omega - omega_res) / (omega_max - omega_res): integral P_max s^(n+1) span / (n+1)
    const double span = omega_max - unloading.residual_interference();
    const double s = (omega - unloading.residual_interference()) / span;
    return unloading.max_force() * std::pow(s, unloading.exponent() + 1.0) * span / (unloading.exponent() + 1.0) *
           R * R * R;
  }
  double effective_modulus() const { return e_eff_; }
  double poisson_ratio() const { return unit_.coefficients().poisson_ratio; }
  const JacksonGreen &unit_curve() const { return unit_; }
  // Real area of a worn flat pressed elastically with force F over the contact radius a. Sneddon's solution
  // assumes the flat and its counter-surface conform over pi a^2 at any load; a real wear scar carries the
  // load on its own finer roughness, whose micro-contacts are fully plastic (their plasticity index is far
  // above 1): Bowden & Tabor's A = F / H with the small-contact limit of the Jackson-Green hardness,
  // H_G(a/R -> 0) = 2.84 S_y. Capped at pi a^2, which it reaches where the flat's mean pressure does.
  double worn_flat_real_area(double force, double contact_radius) const
  {
    const double conforming = kPi * contact_radius * contact_radius;
    const double plastic = force * inv_flow_pressure_;
    return plastic < conforming ? plastic : conforming;
  }
  double micro_contact_flow_pressure() const { return 1.0 / inv_flow_pressure_; }

 private:
  static constexpr double kPi = 3.14159265358979323846;
  // The loading curve at omega (R = 1 units): force, contact radius, stiffness and groove into out, and what
  // unloading from omega would follow (residual interference, EKK exponent).
  void load(double omega, NormalContact &out, double &residual, double &exponent) const
  {
    const double x = omega * inv_omega_c_;
    if (plastic_table_.covers(x)) {
      // the fully plastic Jackson-Green branch and what loading derives from it, tabulated
      const PlasticLoadingPoint p = plastic_table_.evaluate(x);
      residual = p.residual_ratio * omega;
      exponent = p.exponent;
      out.force = p.force;
      out.contact_radius = p.contact_radius;
      out.stiffness = p.stiffness;
      out.groove_ploughing = p.groove_ploughing;
    } else {
      // the Jackson-Green curve (Hertz and the bridge to the fit; the fit itself beyond the table)
      double log_x;    // ln(omega / omega_c) for omega > omega_c (the fit's own)
      const ContactPoint p = unit_.evaluate(omega, log_x);
      if (x > 1.0) {
        residual = ElasticPlasticUnloading::residual_ratio_of_log(log_x) * omega;
        exponent = ElasticPlasticUnloading::unloading_exponent_of_log(log_x);
      } else {
        residual = 0.0;
        exponent = 1.5;
      }
      out.force = p.force;
      out.contact_radius = p.contact_radius;
      out.stiffness = p.stiffness;
      if (residual > 0.0) out.groove_ploughing = groove_ploughing_force(p.force, p.contact_radius, 1.0, residual);
    }
  }
  double e_eff_;
  JacksonGreen unit_;    // the loading curve of a unit-radius sphere
  PlasticLoadingTable plastic_table_;    // its fully plastic branch, tabulated for the force loops
  double inv_omega_c_;   // 1 / omega_c of the unit sphere
  double stick_critical_load_;    // L_c of the unit sphere (fitted for 0.2 <= nu < 0.5; checked by its user)
  double inv_flow_pressure_;      // 1 / (2.84 S_y): the flow pressure of a worn flat's micro-contacts
};

// Damping: restitution-calibrated viscoelastic damping (contact.h).
class RestitutionDampingModel {
 public:
  static constexpr const char *name = "restitution";
  static constexpr std::array<const char *, 1> coefficient_names{"e"};
  template <class P> static Coefficients from_parameters(const P &p) { return {p.restitution}; }
  explicit RestitutionDampingModel(const double *c) : damping_(c[0]) {}
  Coefficients values() const { return {damping_.restitution()}; }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj) { return {mix_geometric(ii[0], jj[0])}; }
  double force(double normal_stiffness, double effective_mass, double normal_velocity) const
  {
    return damping_.force(normal_stiffness, effective_mass, normal_velocity);
  }

 private:
  RestitutionDamping damping_;
};

// Tangential: Mindlin spring k_t = 8 G* a with history (contact.h).
class MindlinTangentialModel {
 public:
  static constexpr const char *name = "mindlin";
  static constexpr std::array<const char *, 1> citations{kCiteMindlin};
  static constexpr std::array<const char *, 1> coefficient_names{"G*"};
  // its history slots: the spring (a vector in the tangent plane, so seen from the other body it changes sign:
  // `history_vector`, its first slot) and the slip distance accumulated since the contact last stuck, which the
  // friction laws' static -> kinetic weakening reads (limit(slip, ...)); ContactModel clears it on re-stick
  enum Slot { SPRING_X = 0, SPRING_Y, SPRING_Z, SLIP, SLOTS };
  static constexpr int history_slots = SLOTS;
  static constexpr int history_vector = SPRING_X;
  template <class P> static Coefficients from_parameters(const P &p) { return {p.effective_shear_modulus}; }
  explicit MindlinTangentialModel(const double *c) : g_eff_(c[0])
  {
    if (!(c[0] > 0.0) || !std::isfinite(c[0]))
      throw InvalidCoefficient("G*: effective shear modulus must be > 0 and finite");
  }
  Coefficients values() const { return {g_eff_}; }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    return {mix_compliance(ii[0], jj[0])};
  }
  double stiffness(double contact_radius) const { return mindlin_stiffness(g_eff_, contact_radius); }
  double effective_shear_modulus() const { return g_eff_; }

 private:
  double g_eff_;
};

// Friction limit: Coulomb, static mu_s falling to kinetic mu_k over the slip distance d_c.
class CoulombFrictionModel {
 public:
  static constexpr const char *name = "coulomb";
  static constexpr std::array<const char *, 3> coefficient_names{"mu_s", "mu_k", "d_c"};
  template <class P> static Coefficients from_parameters(const P &p)
  {
    return {p.mu_static, p.mu_kinetic, p.slip_weakening_distance};
  }
  explicit CoulombFrictionModel(const double *c) : friction_(c[0], c[1], c[2]) {}
  Coefficients values() const
  {
    return {friction_.mu_static(), friction_.mu_kinetic(), friction_.slip_weakening_distance()};
  }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    return {mix_geometric(ii[0], jj[0]), mix_geometric(ii[1], jj[1]), mix_geometric(ii[2], jj[2])};
  }
  double limit(double slip, double normal_force, const NormalContact &, double, FrictionStrengthParts &) const
  {
    return friction_.coefficient(slip) * normal_force;
  }

 private:
  StaticKineticFriction friction_;
};

// Friction limit from the micro strength: kinetic level tau_s A_r + ploughing (friction_strength.h); mu_s - mu_k
// stays the static excess over d_c.
class StrengthFrictionModel {
 public:
  static constexpr const char *name = "strength";
  static constexpr std::array<const char *, 5> coefficient_names{"mu_s", "mu_k", "d_c", "tau_s", "plough"};
  static constexpr InterfaceUse interface_use = InterfaceUse::shear_strength;
  template <class P> static Coefficients from_parameters(const P &p)
  {
    return {p.mu_static, p.mu_kinetic, p.slip_weakening_distance, p.shear_strength, p.ploughing_factor};
  }
  explicit StrengthFrictionModel(const double *c) : friction_(c[0], c[1], c[2]), strength_(c[3], c[4]) {}
  Coefficients values() const
  {
    return {friction_.mu_static(), friction_.mu_kinetic(), friction_.slip_weakening_distance(),
            strength_.shear_strength(), strength_.ploughing_factor()};
  }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    Coefficients out(ii.size());
    for (std::size_t k = 0; k < ii.size(); ++k) out[k] = mix_geometric(ii[k], jj[k]);
    return out;
  }
  double shear_strength() const { return strength_.shear_strength(); }
  template <class Normal, class Wear> void check_with(const Normal &, const Wear &wear) const
  {
    check_shear_strength_below_hardness(shear_strength(), wear.softer_hardness());
  }
  double limit(double slip, double normal_force, const NormalContact &normal, double overlap,
               FrictionStrengthParts &parts) const
  {
    if (!(normal_force > 0.0)) return 0.0;
    if (normal.plastic_model) {
      // adhesion over the elastic-plastic real area; ploughing only by the plastic groove (0 below yield)
      parts.adhesion = strength_.shear_strength() * normal.real_area;
      parts.ploughing = strength_.ploughing_factor() * normal.groove_ploughing;
    } else {
      parts = strength_.strength(normal_force, normal.contact_radius, overlap);
    }
    return friction_.limit_force(slip, normal_force, parts.total());
  }

 private:
  StaticKineticFriction friction_;
  AdhesionPloughing strength_;
};

// Friction limit of the elastic-plastic sphere: the static limit of Brizmer, Kligerman & Etsion (2007),
// mu_s = 0.27 coth(0.27 (P / L_c)^0.35) (full stick, L_c from the normal model), falls over the slip
// distance d_c to the kinetic strength tau_s A_r + groove ploughing (as 'strength' with an elastic-plastic
// normal model). Needs the elastic/plastic normal model with 0.2 <= nu < 0.5 (checked by ContactModel).
class BrizmerFrictionModel {
 public:
  static constexpr const char *name = "brizmer";
  static constexpr std::array<const char *, 1> citations{kCiteBrizmer};
  static constexpr std::array<const char *, 3> coefficient_names{"d_c", "tau_s", "plough"};
  static constexpr InterfaceUse interface_use = InterfaceUse::shear_strength;
  template <class P> static Coefficients from_parameters(const P &p)
  {
    return {p.slip_weakening_distance, p.shear_strength, p.ploughing_factor};
  }
  explicit BrizmerFrictionModel(const double *c) : d_c_(c[0]), strength_(c[1], c[2])
  {
    if (!(c[0] >= 0.0) || !std::isfinite(c[0])) throw InvalidCoefficient("d_c: slip distance must be >= 0");
  }
  Coefficients values() const { return {d_c_, strength_.shear_strength(), strength_.ploughing_factor()}; }
  double shear_strength() const { return strength_.shear_strength(); }
  template <class Normal, class Wear> void check_with(const Normal &normal, const Wear &wear) const
  {
    check_shear_strength_below_hardness(shear_strength(), wear.softer_hardness());
    require_flattening_normal<Normal>(name);
    if constexpr (FlattensSummits<Normal>::value) {
      const double nu = normal.poisson_ratio();
      if (!(nu >= 0.2 && nu < 0.5))
        throw InvalidCoefficient("nu: friction model 'brizmer' is fitted for a Poisson ratio in [0.2, 0.5), got " +
                                 std::to_string(nu));
    }
  }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    return {mix_geometric(ii[0], jj[0]), mix_geometric(ii[1], jj[1]), mix_geometric(ii[2], jj[2])};
  }
  double limit(double slip, double normal_force, const NormalContact &normal, double,
               FrictionStrengthParts &parts) const
  {
    if (!(normal_force > 0.0)) return 0.0;
    parts.adhesion = strength_.shear_strength() * normal.real_area;
    parts.ploughing = strength_.ploughing_factor() * normal.groove_ploughing;
    const double kinetic = parts.total();
    const double weight = slip <= 0.0 ? 1.0 : (d_c_ > 0.0 ? 1.0 - slip / d_c_ : 0.0);
    if (!(weight > 0.0) || !(normal.stick_critical_load > 0.0)) return kinetic;
    const double stick =
        BrizmerStaticFriction::coefficient_at(normal_force / normal.stick_critical_load) * normal_force;
    return stick > kinetic ? kinetic + (stick - kinetic) * weight : kinetic;
  }

 private:
  double d_c_;
  AdhesionPloughing strength_;
};

// Friction limit of a plastic junction with junction growth (Tabor 1959, Proc. R. Soc. A 251:378; McFarlane &
// Tabor 1950): a junction at yield under the normal load keeps p^2 + alpha tau^2 = p_m^2 (p = F_n / A,
// tau = F_t / A) as the tangential force grows, so its real area grows, A = sqrt(F_n^2 + alpha F_t^2) / p_m,
// until tau reaches the interface strength tau_i = f k. k is the shear flow stress the criterion itself gives
// at p = 0, p_m^2 = alpha k^2, and p_m the junction's mean pressure under the normal load alone (the normal
// model's F_n / A_r), so gross sliding comes at the closed form mu = f / sqrt(alpha (1 - f^2)) whatever p_m.
// A contact that has not yielded (no plastic history: no groove; no flat, on whose plastic micro-contacts a worn
// summit carries its load) does not grow: it shears at tau_i over its area, mu = tau_i / p = f / sqrt(alpha) (Bowden & Tabor's adhesion
// without growth). No ploughing term, no
// static excess. Needs the elastic/plastic normal model (checked by ContactModel). doc/junction_growth.md.
class JunctionFrictionModel {
 public:
  static constexpr const char *name = "junction";
  static constexpr std::array<const char *, 1> citations{kCiteTabor};
  static constexpr std::array<const char *, 2> coefficient_names{"f", "alpha"};
  // alpha of the explicit and file forms when not given: McFarlane & Tabor's (1950) measured value
  static constexpr double kDefaultAlpha = 12.0;
  static constexpr InterfaceUse interface_use = InterfaceUse::interface_coefficient;
  template <class P> static Coefficients from_parameters(const P &p)
  {
    require_junction_inputs(p, name,
                            "pair_coeff keyword 'S_y X', fix runin/wall keyword 'yield', or the material's 6th value "
                            "in a coefficient file",
                            "interface coefficient", "pair_coeff keyword 'f X', fix runin/wall keyword 'junction f alpha'");
    return {p.interface_coefficient, p.junction_alpha};
  }
  // junction growth needs the plastic history and mean pressure of a flattening normal model
  template <class Normal, class Wear> void check_with(const Normal &, const Wear &) const
  {
    require_flattening_normal<Normal>(name);
  }
  explicit JunctionFrictionModel(const double *c) : f_(c[0]), alpha_(c[1])
  {
    char got[32];
    if (!(c[0] >= 0.0 && c[0] < 1.0)) {
      std::snprintf(got, sizeof got, "%.6g", c[0]);
      throw InvalidCoefficient(std::string("f: interface coefficient must be in [0, 1) (at 1 a clean junction grows "
                                           "without bound), got ") + got);
    }
    if (!(c[1] > 0.0) || !std::isfinite(c[1])) {
      std::snprintf(got, sizeof got, "%.6g", c[1]);
      throw InvalidCoefficient(std::string("alpha: junction growth constant must be > 0 and finite, got ") + got);
    }
    elastic_ratio_ = f_ / std::sqrt(alpha_);
    sliding_ratio_ = tabor_sliding_ratio(f_, alpha_);
  }
  // Tabor's closed form for a plastic junction at gross sliding, f / sqrt(alpha (1 - f^2)): the one formula the
  // junction models and the elements' surface film (continuum/node_film.h) share.
  static double tabor_sliding_ratio(double f, double alpha) { return f / std::sqrt(alpha * (1.0 - f * f)); }
  Coefficients values() const { return {f_, alpha_}; }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    return {mix_geometric(ii[0], jj[0]), mix_geometric(ii[1], jj[1])};
  }
  // Tabor's F_t / F_n at gross sliding of a plastic junction, and of a junction that cannot grow.
  double sliding_ratio() const { return sliding_ratio_; }
  double elastic_ratio() const { return elastic_ratio_; }
  // A plastic junction: a contact that has yielded (the elastic/plastic model gives it a groove then), or one on
  // a flat summit (worn or flattened, flat_radius > 0), whose load the plastic micro-contacts of the scar carry
  // (doc/elastic_plastic_contact.md, section 6).
  static bool plastic_junction(const NormalContact &normal, double flat_radius)
  {
    return normal.groove_ploughing > 0.0 || flat_radius > 0.0;
  }
  // The limit (ContactModel::evaluate calls it in place of the other laws' limit(), at compile time: it needs the
  // flat of the contact).
  double junction_limit(double normal_force, const NormalContact &normal, double flat_radius,
                        FrictionStrengthParts &parts) const
  {
    if (!(normal_force > 0.0)) return 0.0;
    parts.adhesion = (plastic_junction(normal, flat_radius) ? sliding_ratio_ : elastic_ratio_) * normal_force;
    return parts.adhesion;
  }
  // Real area of the junction under the tangential force F_t: A_r sqrt(1 + alpha (F_t / F_n)^2), which is
  // sqrt(F_n^2 + alpha F_t^2) / p_m with p_m = F_n / A_r; A_r / sqrt(1 - f^2) at gross sliding.
  double junction_area(const NormalContact &normal, double flat_radius, double normal_force,
                       double tangential_force) const
  {
    if (!plastic_junction(normal, flat_radius) || !(normal_force > 0.0)) return normal.real_area;
    const double ratio = tangential_force / normal_force;
    return normal.real_area * std::sqrt(1.0 + alpha_ * ratio * ratio);
  }

 private:
  double f_, alpha_;
  double elastic_ratio_ = 0.0, sliding_ratio_ = 0.0;
};

// Junction growth with a surface film (doc/surface_films.md): Tabor's junction (JunctionFrictionModel) whose
// interface coefficient follows the film coverage theta of the contact's two summits (their mean, given by the host
// in ContactGeometry::film_coverage), f = theta f_film + (1 - theta) f_clean; the coverage itself is the hosts'
// per-summit state, advanced with kinetics() (surface_film.h: removal distance s_r, growth rate k_g), those of the
// film of each body: the pair host takes a summit's from its type's own I,I pair.
class JunctionFilmFrictionModel {
 public:
  static constexpr const char *name = "junction/film";
  static constexpr std::array<const char *, 1> citations{kCiteTabor};
  static constexpr std::array<const char *, 5> coefficient_names{"f_clean", "f_film", "alpha", "s_r", "k_g"};
  template <class P> static Coefficients from_parameters(const P &p)
  {
    require_junction_inputs(p, name, "pair_coeff keyword 'S_y X' or the material's 6th value in a coefficient file",
                            "clean interface coefficient", "pair_coeff keyword 'f X'");
    if (std::isnan(p.film_interface_coefficient))
      throw InvalidCoefficient("f_film: friction model 'junction/film' needs the film's interface coefficient, "
                               "0 <= f_film < 1 (pair_coeff keyword 'f_film X')");
    const auto off_unless_given = [](double v) { return std::isnan(v) ? 0.0 : v; };
    return {p.interface_coefficient, p.film_interface_coefficient, p.junction_alpha,
            off_unless_given(p.film_removal_distance), off_unless_given(p.film_growth_rate)};
  }
  template <class Normal, class Wear> void check_with(const Normal &, const Wear &) const
  {
    require_flattening_normal<Normal>(name);
  }
  explicit JunctionFilmFrictionModel(const double *c)
      : clean_(checked_junction(c[0], c[2], "f_clean")), film_(checked_junction(c[1], c[2], "f_film")),
        kinetics_(c[3], c[4]), f_clean_(c[0]), f_film_(c[1]), alpha_(c[2])
  {
  }
  Coefficients values() const
  {
    return {f_clean_, f_film_, alpha_, kinetics_.removal_distance(), kinetics_.growth_rate()};
  }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj)
  {
    Coefficients out(ii.size());
    for (std::size_t k = 0; k < ii.size(); ++k) out[k] = mix_geometric(ii[k], jj[k]);
    return out;
  }
  const FilmKinetics &kinetics() const { return kinetics_; }
  const JunctionFrictionModel &clean() const { return clean_; }
  const JunctionFrictionModel &film() const { return film_; }
  // The interface coefficient at coverage theta.
  double interface_coefficient(double theta) const
  {
    return FilmKinetics::interpolate(theta, f_clean_, f_film_);
  }
  double film_limit(double theta, double normal_force, const NormalContact &normal, double flat_radius,
                    FrictionStrengthParts &parts) const
  {
    if (!(normal_force > 0.0)) return 0.0;
    const double f = interface_coefficient(theta);
    const double ratio = JunctionFrictionModel::plastic_junction(normal, flat_radius)
                             ? JunctionFrictionModel::tabor_sliding_ratio(f, alpha_)
                             : f / std::sqrt(alpha_);
    parts.adhesion = ratio * normal_force;
    return parts.adhesion;
  }
  // The grown area does not depend on f (the criterion's alpha only).
  double junction_area(const NormalContact &normal, double flat_radius, double normal_force,
                       double tangential_force) const
  {
    return clean_.junction_area(normal, flat_radius, normal_force, tangential_force);
  }

 private:
  static JunctionFrictionModel checked_junction(double f, double alpha, const char *what)
  {
    try {
      const double c[2] = {f, alpha};
      return JunctionFrictionModel(c);
    } catch (const InvalidCoefficient &e) {
      const std::string message = e.what();
      // the junction's own message names f: name the film model's coefficient instead
      throw InvalidCoefficient(message.rfind("f:", 0) == 0 ? what + message.substr(1) : message);
    }
  }
  JunctionFrictionModel clean_, film_;    // the limits at theta = 0 and 1 (checks, closed forms)
  FilmKinetics kinetics_;
  double f_clean_, f_film_, alpha_;
};

// A friction law that reads the film coverage of the contact (film_limit) and whose summits carry a film the host
// advances (kinetics()): the hosts keep the per-summit coverage only for these, at compile time.
template <class Model, class = void> struct HasFilm : std::false_type {};
template <class Model>
struct HasFilm<Model, std::void_t<decltype(&Model::film_limit)>> : std::true_type {};

// A friction law whose limit needs the contact's flat and whose real area grows with the tangential force
// (junction_limit, junction_area): ContactModel::evaluate calls them at compile time, so the other laws do not
// pay for it.
template <class Model, class = void> struct GrowsJunction : std::false_type {};
template <class Model>
struct GrowsJunction<Model, std::void_t<decltype(&Model::junction_area)>> : std::true_type {};

// Wear: Archard for each body with its own coefficient and hardness, V_i = k_i W s / H_i (the thesis's form
// divides by 3). A fraction 'transfer' of what one body loses is deposited on the other; the rest is debris.
class ArchardWearModel {
 public:
  static constexpr const char *name = "archard";
  static constexpr std::array<const char *, 1> citations{kCiteArchard};
  static constexpr std::array<const char *, 4> coefficient_names{"k_i", "H_i", "k_j", "H_j"};
  template <class P> static Coefficients from_parameters(const P &p)
  {
    return {p.wear_coefficient, p.hardness_i, p.wear_coefficient, p.hardness_j};
  }
  ArchardWearModel(const double *c, ArchardForm form, double transfer)
      : body_i_(c[0], checked_hardness(c[1], "H_i"), form), body_j_(c[2], checked_hardness(c[3], "H_j"), form),
        transfer_(checked_transfer(transfer))
  {
  }
  Coefficients values() const
  {
    return {body_i_.coefficient(), body_i_.hardness(), body_j_.coefficient(), body_j_.hardness()};
  }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj) { return {ii[0], ii[1], jj[2], jj[3]}; }
  static Coefficients swap_bodies(const Coefficients &c) { return {c[2], c[3], c[0], c[1]}; }

  // What one slip increment under the normal force takes from each body, and where it goes.
  WearExchange wear(double normal_force, double slip_increment) const
  {
    WearExchange out;
    out.lost_a = body_i_.volume(normal_force, slip_increment);
    out.lost_b = body_j_.volume(normal_force, slip_increment);
    out.gained_a = transfer_ * out.lost_b;
    out.gained_b = transfer_ * out.lost_a;
    out.debris = (1.0 - transfer_) * (out.lost_a + out.lost_b);
    return out;
  }
  const ArchardWear &body_i() const { return body_i_; }
  const ArchardWear &body_j() const { return body_j_; }
  double softer_hardness() const { return std::min(body_i_.hardness(), body_j_.hardness()); }

 private:
  static double checked_hardness(double hardness, const char *name)
  {
    if (!(hardness > 0.0) || !std::isfinite(hardness))
      throw InvalidCoefficient(std::string(name) + ": hardness must be > 0 and finite");
    return hardness;
  }
  static double checked_transfer(double transfer)
  {
    if (!(transfer >= 0.0 && transfer <= 1.0)) throw InvalidCoefficient("transfer: fraction must be in [0, 1]");
    return transfer;
  }
  ArchardWear body_i_, body_j_;
  double transfer_;
};

// ---------------------------------------------------------------------------------------------------
// The registry: one tuple per kind. Add a law by adding its class here.
// ---------------------------------------------------------------------------------------------------
// A test build may register laws of its own (RUNIN_TEST_SUB_MODELS: a header defining RUNIN_TEST_FRICTION_MODELS,
// the classes to append to FrictionModels with a leading comma); the shipped build has none.
#ifdef RUNIN_TEST_SUB_MODELS
#include RUNIN_TEST_SUB_MODELS
#else
#define RUNIN_TEST_FRICTION_MODELS
#endif
using NormalModels = std::tuple<HertzNormalModel, ElasticPlasticNormalModel>;
using DampingModels = std::tuple<RestitutionDampingModel>;
using TangentialModels = std::tuple<MindlinTangentialModel>;
using FrictionModels = std::tuple<CoulombFrictionModel, StrengthFrictionModel, BrizmerFrictionModel,
                                  JunctionFrictionModel, JunctionFilmFrictionModel RUNIN_TEST_FRICTION_MODELS>;
using WearModels = std::tuple<ArchardWearModel>;

// The per-contact history the host stores (zero for a new contact), placed from the slots the models declare: the
// tangential model's (one law, not dispatched), then the chosen normal model's; each model sees its own from 0.
// contact_history_size<NORMAL> values in all, at most CONTACT_HISTORY_SIZE. Hertz keeps none, so its contacts carry
// the tangential 4 (the neighbour-list history of a pair style is copied for every neighbour: its size costs time).
using TangentialHistory = std::tuple_element_t<0, TangentialModels>;
constexpr int kTangentialHistoryOffset = 0;
constexpr int TANGENTIAL_HISTORY_SIZE = TangentialHistory::history_slots;
constexpr int kNormalHistoryOffset = kTangentialHistoryOffset + TANGENTIAL_HISTORY_SIZE;
// The slip distance the friction laws weaken over (the tangential model's slot).
constexpr int kSlipHistorySlot = kTangentialHistoryOffset + TangentialHistory::SLIP;
// Whether a slot holds a component of a vector that changes sign with the order of the two bodies (the tangential
// model's `history_vector`): a host that swaps a contact's bodies negates it and copies the others.
constexpr bool history_flips_with_bodies(int slot)
{
  return slot >= kTangentialHistoryOffset + TangentialHistory::history_vector &&
         slot < kTangentialHistoryOffset + TangentialHistory::history_vector + 3;
}
// The normal model's slots belong to the surface of the asperity under a rigid flat rather than to one contact
// (kept by fix runin/wall when the contact opens).
constexpr bool is_normal_history(int slot) { return slot >= kNormalHistoryOffset; }
// Whether a contact of a normal model that flattens the summits (FlattensSummits) has plastic history: such a model
// keeps its largest interference, > 0 once loaded, in its first slot. Without it, a contact on flattened summits is
// a reload (the host sets ContactGeometry::flattened_drop).
inline bool has_plastic_history(const double *history) { return history[kNormalHistoryOffset] > 0.0; }
// History values a contact keeps with the NORMAL-th normal model.
template <int NORMAL>
constexpr int contact_history_size = kNormalHistoryOffset + std::tuple_element_t<NORMAL, NormalModels>::history_slots;
// The same for a choice made at run time.
int contact_history_size_of(int normal_index);
// The most history values a contact keeps (the largest normal model's).
namespace detail {
template <std::size_t... I> constexpr int most_normal_history_slots(std::index_sequence<I...>)
{
  return std::max({0, std::tuple_element_t<I, NormalModels>::history_slots...});
}
}    // namespace detail
constexpr int CONTACT_HISTORY_SIZE =
    kNormalHistoryOffset + detail::most_normal_history_slots(std::make_index_sequence<std::tuple_size_v<NormalModels>>{});
// Only the tangential and normal kinds have their slots placed; a law of another kind that declared some would have
// them silently ignored, so the registry refuses it until its kind gets a placement (an offset, the hosts' sizes,
// the wall's rule for what a contact keeps when it opens: is_normal_history).
namespace detail {
template <class Model, class = void> struct DeclaresHistory : std::false_type {};
template <class Model> struct DeclaresHistory<Model, std::void_t<decltype(Model::history_slots)>> : std::true_type {};
template <class Tuple> struct NoneDeclaresHistory;
template <class... Models>
struct NoneDeclaresHistory<std::tuple<Models...>> : std::bool_constant<(!DeclaresHistory<Models>::value && ...)> {};
}    // namespace detail
static_assert(detail::NoneDeclaresHistory<DampingModels>::value && detail::NoneDeclaresHistory<FrictionModels>::value &&
                  detail::NoneDeclaresHistory<WearModels>::value,
              "the registry places no history slots for damping, friction or wear laws yet: give the kind a placement "
              "(contact_model.h, after TangentialHistory) before a law of it declares history_slots");

namespace detail {
template <std::size_t... I> constexpr const char *first_flattening_normal(std::index_sequence<I...>)
{
  const char *out = nullptr;
  ((out == nullptr && FlattensSummits<std::tuple_element_t<I, NormalModels>>::value
        ? (void)(out = std::tuple_element_t<I, NormalModels>::name)
        : void()),
   ...);
  return out;
}
}    // namespace detail
template <class Normal> void require_flattening_normal(const char *friction_name)
{
  if constexpr (!FlattensSummits<Normal>::value)
    throw InvalidCoefficient(
        std::string("friction model '") + friction_name + "' needs the normal model '" +
        detail::first_flattening_normal(std::make_index_sequence<std::tuple_size_v<NormalModels>>{}) + "'");
}

enum class SubModelKind { normal = 0, damping, tangential, friction, wear };
constexpr int kSubModelKinds = 5;
const char *sub_model_kind_name(SubModelKind kind);

// Name and coefficient names of one registered sub-model.
struct SubModelInfo {
  const char *name;
  std::vector<const char *> coefficient_names;
  // the capabilities the class declares (the traits above): hosts ask these, never a name
  bool flattens_summits = false;    // normal: plastic flattening lowers the summits
  bool has_film = false;            // friction: the summits carry a film the host keeps
  InterfaceUse interface_use = InterfaceUse::none;    // friction: what an interface state sets
  std::vector<const char *> citations;    // the papers the class lists (`citations`; none without)
  int coefficient_count() const { return static_cast<int>(coefficient_names.size()); }
};
// The registered sub-models of a kind, in registry order (the index is the compile-time dispatch index).
const std::vector<SubModelInfo> &registered_sub_models(SubModelKind kind);
// The kind's registered names in registry order, as messages list them ("hertz, elastic/plastic").
std::string registered_names(SubModelKind kind);
// Index of `name` among the kind's sub-models; throws InvalidCoefficient listing the known names.
int find_sub_model(SubModelKind kind, const std::string &name);
// The friction laws whose interface strength an interface state sets (SubModelInfo::interface_use), in registry
// order: the laws of a cell whose friction follows a material file's interface line (runin homogenise); the first
// that takes it as a shear strength is such a cell's default.
std::vector<std::string> interface_friction_models();
std::string default_interface_friction_model();
// The coefficients the explicit and file forms give friction law `index` (its from_parameters) from `p`.
struct ContactParameters;
Coefficients friction_coefficients_from(int index, const ContactParameters &p);

// The sub-models chosen for a contact (indices into the registry) and their coefficient values.
struct ContactModelChoice {
  std::array<int, kSubModelKinds> index{0, 0, 0, 0, 0};
  int of(SubModelKind kind) const { return index[static_cast<int>(kind)]; }
  bool operator==(const ContactModelChoice &o) const { return index == o.index; }
};
struct ContactCoefficients {
  std::array<Coefficients, kSubModelKinds> values;
  Coefficients &of(SubModelKind kind) { return values[static_cast<int>(kind)]; }
  const Coefficients &of(SubModelKind kind) const { return values[static_cast<int>(kind)]; }
};
// Checks every kind's coefficient count against the registry (InvalidCoefficient: "<kind> model '<name>'
// takes N coefficients (...), got M").
void check_coefficient_counts(const ContactModelChoice &choice, const ContactCoefficients &coefficients);
// The counts, then every value finite (InvalidCoefficient: "<coefficient>: must be a finite number, got inf").
void check_coefficients(const ContactModelChoice &choice, const ContactCoefficients &coefficients);
// Mixing of an unset I,J pair from the I,I and J,J coefficients, sub-model by sub-model.
ContactCoefficients mix_coefficients(const ContactModelChoice &choice, const ContactCoefficients &ii,
                                     const ContactCoefficients &jj);
// Self-describing record (names, counts, values) for restart files, and its reader; the reader throws
// InvalidCoefficient when the record is damaged.
std::vector<double> serialize(const ContactModelChoice &choice, const ContactCoefficients &coefficients);
std::pair<ContactModelChoice, ContactCoefficients> deserialize(const double *record, int size);
// What differs between two choices, in words ("normal model: restart 'hertz', input 'elastic/plastic'"),
// or empty.
std::string describe_difference(const ContactModelChoice &stored, const ContactModelChoice &current);
std::string describe(const ContactModelChoice &choice);

// The named parameters of one contact as decks give them (pair_coeff's explicit and file forms, the
// keywords of fix runin/wall); contact_coefficients() maps them onto the chosen sub-models, so every host
// reads the same set the same way.
struct ContactParameters {
  double effective_modulus = 0.0;          // E* [Pa]
  double effective_shear_modulus = 0.0;    // G* [Pa]
  double restitution = 1.0;                // e [-]
  double mu_static = 0.0, mu_kinetic = 0.0, slip_weakening_distance = 0.0;
  double wear_coefficient = 0.0;           // k [-]
  double hardness_i = 0.0, hardness_j = 0.0;    // H of body i and of the counter-body j [Pa]
  double shear_strength = 0.0;             // tau_s [Pa] (friction strength)
  double ploughing_factor = 1.0;           // scales the ploughing term [-] (friction strength)
  double yield_strength = 0.0;             // S_y of the yielding (softer) body [Pa] (elastic-plastic)
  double poisson_ratio = 0.3;              // nu of the yielding body [-] (elastic-plastic)
  bool yield_from_hardness = false;        // S_y was Tabor's H / 2.8 (no S_y given): hosts say so
  // friction junction: interface coefficient f (NaN: not given, refused) and growth constant alpha
  double interface_coefficient = std::numeric_limits<double>::quiet_NaN();
  double junction_alpha = JunctionFrictionModel::kDefaultAlpha;
  // interface state (friction_strength.h): m per state from a coefficient file, and the state a deck chose
  // (-1: none): tau_s = m S_y / sqrt(3) for strength and brizmer, f = m for junction
  InterfaceFactors interface_factors = no_interface_factors();
  int interface_state = -1;
  // friction junction/film: f is f_clean; the film's f, removal distance and growth rate (NaN: not given; refused
  // for a friction model without a film, f_film needed, s_r and k_g 0 = off by default)
  double film_interface_coefficient = std::numeric_limits<double>::quiet_NaN();
  double film_removal_distance = std::numeric_limits<double>::quiet_NaN();
  double film_growth_rate = std::numeric_limits<double>::quiet_NaN();
};
// Tabor's fallback S_y = H / 2.8 where a material gives no yield strength: the one place it is computed (the hosts
// say so in one WARNING, plugins/common/coefficient_grammar.h).
constexpr double kTaborConstraintFactor = 2.8;
constexpr double tabor_yield_strength(double hardness) { return hardness / kTaborConstraintFactor; }
// E* and G* of two materials, the hardnesses and the pair's interface values.
ContactParameters contact_parameters(const Material &i, const Material &j, double restitution, double mu_static,
                                     double mu_kinetic, double slip_weakening_distance, double wear_coefficient);
ContactCoefficients contact_coefficients(const ContactModelChoice &choice, const ContactParameters &p);
// The same contact seen from the counter-body (the per-body values swapped).
ContactCoefficients swap_bodies(const ContactModelChoice &choice, const ContactCoefficients &c);

// Settings that are the host's (pair_style / fix keywords), shared by every type pair.
struct ContactSettings {
  ArchardForm archard_form = ArchardForm::plain;
  double transfer_fraction = 0.0;    // part of a body's lost volume deposited on the other
  double restick_speed = 0.0;        // below this tangential speed a non-slipping contact heals (0: never)
};

// What one contact evaluation returns to the host.
struct ContactResult {
  double normal_force = 0.0;      // total normal force (elastic + damping, clamped >= 0) on body i [N]
  NormalContact normal;           // the normal sub-model's output (elastic force, stiffness, contact radius)
  TangentialUpdate tangential;    // tangential force on body i, slip increment, slipping
  FrictionStrengthParts strength; // adhesion and ploughing parts of the friction limit (strength model)
  WearExchange wear;              // volumes lost and gained by body i (a) and the counter-body (b)
  double worn_volume = 0.0;       // volume removed from the contact in this step (lost by both bodies)
};

// Storage for the chosen alternative of a kind: one std::optional per registered class, exactly one set.
// Access in the force loop is *std::get<INDEX>(...), unchecked, with INDEX a compile-time constant.
template <class Tuple> struct SubModelSlots;
template <class... Models> struct SubModelSlots<std::tuple<Models...>> {
  using type = std::tuple<std::optional<Models>...>;
};

// The kernel objects of one type pair, built (and so validated) from its coefficients.
class ContactModel {
 public:
  ContactModel(const ContactModelChoice &choice, const ContactCoefficients &coefficients,
               const ContactSettings &settings);

  // One contact. NORMAL, FRICTION: registry indices, equal to the choice's (the host dispatches on them once
  // per step); WEAR: compute the worn volumes. `history` holds CONTACT_HISTORY_SIZE values; with
  // advance = false (LAMMPS setup) it is read but not changed.
  template <int NORMAL, int FRICTION, int WEAR>
  ContactResult evaluate(const ContactGeometry &g, double *history, double dt, bool advance) const
  {
    ContactResult out;
    out.normal = std::get<NORMAL>(normal_)->evaluate(g, history + kNormalHistoryOffset, advance);
    double fn = out.normal.force + damping().force(out.normal.stiffness, g.effective_mass, g.normal_velocity);
    if (fn < 0.0) fn = 0.0;    // damping must not glue the bodies together
    out.normal_force = fn;

    const double kt = tangential().stiffness(out.normal.contact_radius);
    double &slip = history[kSlipHistorySlot];
    using Friction = std::tuple_element_t<FRICTION, FrictionModels>;
    const double limit = [&] {
      if constexpr (HasFilm<Friction>::value)
        return std::get<FRICTION>(friction_)->film_limit(g.film_coverage, fn, out.normal, g.flat_radius,
                                                         out.strength);
      else if constexpr (GrowsJunction<Friction>::value)
        return std::get<FRICTION>(friction_)->junction_limit(fn, out.normal, g.flat_radius, out.strength);
      else
        return std::get<FRICTION>(friction_)->limit(slip, fn, out.normal, g.overlap, out.strength);
    }();
    out.tangential = mindlin_spring(kt, limit, g.normal, g.tangential_velocity, dt,
                                    &history[kTangentialHistoryOffset + TangentialHistory::SPRING_X], slip, advance);
    if (advance) {
      const double *vt = g.tangential_velocity;
      if (resticks_squared(out.tangential, vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2], restick_speed_))
        slip = 0.0;    // re-stuck: the contact heals to its static limit
    }
    if constexpr (GrowsJunction<Friction>::value)
      out.normal.real_area =
          std::get<FRICTION>(friction_)->junction_area(out.normal, g.flat_radius, fn, out.tangential.force_magnitude);
    if (WEAR && out.tangential.slip_increment > 0.0) {
      out.wear = wear().wear(fn, out.tangential.slip_increment);
      out.worn_volume = out.wear.lost_a + out.wear.lost_b;
    }
    return out;
  }
  // The force the last evaluate() applied, from the stored history and without changing it (pair single()):
  // the stored spring already holds the tangential force of that step (-k_t spring), so no friction limit is
  // applied again (the slip distance has moved on since, and the limit with it).
  template <int NORMAL> ContactResult stored_force(const ContactGeometry &g, const double *history) const
  {
    double copy[CONTACT_HISTORY_SIZE] = {0.0};
    for (int k = 0; k < contact_history_size<NORMAL>; ++k) copy[k] = history[k];
    ContactResult out;
    out.normal = std::get<NORMAL>(normal_)->evaluate(g, copy + kNormalHistoryOffset, false);
    double fn = out.normal.force + damping().force(out.normal.stiffness, g.effective_mass, g.normal_velocity);
    out.normal_force = fn < 0.0 ? 0.0 : fn;
    const double kt = tangential().stiffness(out.normal.contact_radius);
    out.tangential = mindlin_spring(kt, HUGE_VAL, g.normal, g.tangential_velocity, 0.0,
                                    &copy[kTangentialHistoryOffset + TangentialHistory::SPRING_X],
                                    copy[kSlipHistorySlot], false);
    return out;
  }
  // Elastic energy stored in the normal contact (eflag tallies).
  template <int NORMAL> double elastic_energy(const ContactGeometry &g, const double *history) const
  {
    return std::get<NORMAL>(normal_)->elastic_energy(g, history + kNormalHistoryOffset);
  }

  const ContactModelChoice &choice() const { return choice_; }
  double effective_modulus() const;
  double effective_shear_modulus() const { return tangential().effective_shear_modulus(); }
  const ArchardWearModel &wear() const { return *std::get<0>(wear_); }
  // Part of a contact's plastic flattening taken by body i: the softer body flattens more (1/H, as the wear
  // of equal k_i).
  double flattening_share_i() const
  {
    const double hi = wear().body_i().hardness(), hj = wear().body_j().hardness();
    return hj / (hi + hj);
  }
  // The film kinetics of the chosen friction model, or nullptr when it has no film.
  const FilmKinetics *film_kinetics() const
  {
    const FilmKinetics *out = nullptr;
    std::apply([&](const auto &...slot) { (film_of(slot, out), ...); }, friction_);
    return out;
  }
  const RestitutionDampingModel &damping() const { return *std::get<0>(damping_); }
  const MindlinTangentialModel &tangential() const { return *std::get<0>(tangential_); }

 private:
  // Kinds with one registered law are not dispatched: a second law there needs a dispatch index too.
  static_assert(std::tuple_size_v<DampingModels> == 1 && std::tuple_size_v<TangentialModels> == 1 &&
                    std::tuple_size_v<WearModels> == 1,
                "add a dispatch index to ContactModel::evaluate and the hosts' eval tables");
  ContactModelChoice choice_;
  SubModelSlots<NormalModels>::type normal_;
  SubModelSlots<DampingModels>::type damping_;
  SubModelSlots<TangentialModels>::type tangential_;
  SubModelSlots<FrictionModels>::type friction_;
  SubModelSlots<WearModels>::type wear_;
  double restick_speed_;
  template <class Slot> static void film_of(const Slot &slot, const FilmKinetics *&out)
  {
    if constexpr (HasFilm<typename Slot::value_type>::value)
      if (slot) out = &slot->kinetics();
  }
};

namespace detail {
template <class F, int... I> void dispatch_sub_models(int index, F &&f, std::integer_sequence<int, I...>)
{
  constexpr int NF = std::tuple_size_v<FrictionModels>;
  ((index == I ? (void)f(std::integral_constant<int, I / NF>{}, std::integral_constant<int, I % NF>{}) : void()),
   ...);
}
}    // namespace detail

// Calls f(std::integral_constant<int, NORMAL>, std::integral_constant<int, FRICTION>) with the choice's
// indices: the compile-time dispatch for hosts that do not keep an eval table of their own.
template <class F> void with_sub_models(const ContactModelChoice &choice, F &&f)
{
  constexpr int NF = std::tuple_size_v<FrictionModels>;
  detail::dispatch_sub_models(choice.of(SubModelKind::normal) * NF + choice.of(SubModelKind::friction), f,
                              std::make_integer_sequence<int, std::tuple_size_v<NormalModels> * NF>{});
}

}    // namespace runin::tribo
