#include "cli/piston_ring_case.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cli/case_file.h"
#include "cli/case_reader.h"

namespace runin::cli {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

const Schema &schema() {
  static const Schema s = {
      {"", {"title", "kinematics", "ring", "ring_pack", "material", "gas", "friction", "wear", "run", "solver", "output",
            "sweep", "film"}},
      {"film", film_keys()},
      {"kinematics", {"motion", "crank_radius", "link_length", "start_angle_deg", "ramp_time", "crank_speed_rpm"}},
      {"ring", {"bore", "width", "thickness", "density", "mass", "elastic_pressure", "land_stiffness",
                "land_damping_ratio", "groove_diameter", "land_width"}},
      {"ring_pack", {"model", "groove_diameter", "groove_position", "elastic_pressure", "crown_height", "land_width",
                     "land_stiffness"}},
      {"material", {"youngs_modulus", "poisson_ratio", "materials", "ring_material", "liner_material"}},
      {"gas", {"crank_angle_deg", "pressure", "cycle_deg", "factor"}},
      {"friction", friction_keys()},
      {"wear", {"k", "hardness", "form", "hardness_ring", "hardness_liner", "crown_height", "ring_cells",
                "liner_cells", "step_safety", "fixed_step", "foundation_modulus", "contact"}},
      {"run", {"t_end", "output_interval", "max_events"}},
      {"solver", {"method", "rtol", "atol", "max_steps"}},
      {"output", {"vtk_times", "circumferential_points"}},
      {"sweep", {"mu0"}},
  };
  return s;
}

}  // namespace

continuum::SlidingFriction piston_ring_friction_with_mu0(const PistonRingCase &c, double mu0) {
  return friction_with_static_coefficient(*c.friction, c.friction_model, mu0);
}

// [gas]: crank angles (deg, increasing, in [0, cycle_deg)), pressures (>= 0), cycle_deg, factor.
continuum::GasPressureTable read_gas_pressure_table(const CaseReader &reader) {
  continuum::GasPressureTable gas;
  const auto angles = reader.numbers("gas.crank_angle_deg");
  const auto pressures = reader.numbers("gas.pressure");
  if (angles.size() != pressures.size())
    reader.fail("gas.pressure", "has " + std::to_string(pressures.size()) + " values, gas.crank_angle_deg has " +
                                    std::to_string(angles.size()));
  const double cycle_deg = reader.positive("gas.cycle_deg", 720.0);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (angles[i] < 0.0 || angles[i] >= cycle_deg)
      reader.fail("gas.crank_angle_deg", "element " + std::to_string(i) + ": must lie in [0, gas.cycle_deg)");
    if (i > 0 && angles[i] <= angles[i - 1])
      reader.fail("gas.crank_angle_deg", "element " + std::to_string(i) + ": angles must increase");
    if (pressures[i] < 0.0) reader.fail("gas.pressure", "element " + std::to_string(i) + ": must be >= 0");
    gas.crank_angle.push_back(angles[i] * kDeg);
    gas.pressure.push_back(pressures[i]);
  }
  gas.cycle = cycle_deg * kDeg;
  gas.factor = reader.non_negative("gas.factor", 1.0);
  return gas;
}

namespace {

// Kinematics: eq. 6.1 with the crank angle measured from TDC; the start is start_angle before TDC.
void read_kinematics(const CaseReader &reader, continuum::PistonRingParameters &p) {
  const std::string motion = reader.choice("kinematics.motion", {"ramp", "crank"}, std::string("ramp"));
  p.motion = motion == "ramp" ? continuum::PistonMotion::Ramp : continuum::PistonMotion::Crank;
  p.crank.crank_radius = reader.positive("kinematics.crank_radius");
  p.crank.link_length = reader.positive("kinematics.link_length");
  if (p.crank.link_length <= p.crank.crank_radius)
    reader.fail("kinematics.link_length", "must exceed kinematics.crank_radius (" +
                                              CaseReader::format(p.crank.crank_radius) + ")");
  const double start_deg = reader.number("kinematics.start_angle_deg", 75.0);
  if (start_deg <= 0.0 || start_deg > 180.0)
    reader.fail("kinematics.start_angle_deg", "must lie in (0, 180] (degrees before TDC), got " +
                                                  CaseReader::format(start_deg));
  p.start_angle = start_deg * kDeg;
  if (p.motion == continuum::PistonMotion::Ramp) {
    if (reader.has("kinematics.crank_speed_rpm")) reader.fail("kinematics.crank_speed_rpm", "not used by motion 'ramp'");
    p.ramp_time = reader.positive("kinematics.ramp_time", 2.0);
  } else {
    if (reader.has("kinematics.ramp_time")) reader.fail("kinematics.ramp_time", "not used by motion 'crank'");
    p.crank_speed = reader.positive("kinematics.crank_speed_rpm") * 2.0 * kPi / 60.0;
  }
}

// The ring section and material the rings share.
struct RingSection {
  double thickness = 0.0, youngs = 0.0, poisson = 0.0;
};

// [ring] (bore, width, thickness, mass) and [material].
RingSection read_ring_and_material(const CaseReader &reader, const std::string &path, PistonRingCase &c) {
  auto &p = c.parameters;
  RingSection r;
  p.bore = reader.positive("ring.bore");
  p.ring_width = reader.positive("ring.width");
  r.thickness = reader.positive("ring.thickness");
  if (2.0 * r.thickness >= p.bore) reader.fail("ring.thickness", "must be below half the bore");
  if (reader.has("ring.mass") && reader.has("ring.density"))
    reader.fail("ring.mass", "give either ring.mass or ring.density, not both");
  p.ring_mass = reader.has("ring.mass")
                    ? reader.positive("ring.mass")
                    : reader.positive("ring.density", 7200.0) * kPi * (p.bore - r.thickness) * r.thickness * p.ring_width;
  c.land_damping_ratio = reader.non_negative("ring.land_damping_ratio");
  r.youngs = reader.positive("material.youngs_modulus", 66e9);
  r.poisson = reader.number("material.poisson_ratio", 0.27);
  if (r.poisson <= -1.0 || r.poisson >= 0.5) reader.fail("material.poisson_ratio", "must lie in (-1, 0.5)");
  for (auto *m : {&c.ring_material, &c.liner_material}) m->youngs_modulus = r.youngs, m->poisson_ratio = r.poisson;
  // The contact model's E and nu stay the case's; the file gives the yield verdict's S_y (or H).
  if (const auto named = read_named_materials(reader, path, "material", "ring_material", "liner_material")) {
    c.ring_material_name = named->name_a;
    c.liner_material_name = named->name_b;
    named->copy_strengths(c.ring_material, c.liner_material);
  }
  return r;
}

// One ring's own values.
struct Spec {
  double groove_diameter = 0.0, land_width = 0.0, tension = 0.0, crown = 0.0, position = 0.0, stiffness = 0.0;
  std::string stiffness_key;  // the key that set the stiffness by hand, empty: from geometry
};

// A [ring_pack] array with one value per ring (or `fallback` for each when absent and not required).
std::vector<double> per_ring(const CaseReader &reader, const std::string &key, std::size_t n, bool required,
                             double fallback) {
  if (!reader.has(key)) {
    if (required) reader.fail(key, "missing (required: one value per ring of ring_pack.groove_diameter)");
    return std::vector<double>(n, fallback);
  }
  const std::vector<double> values = reader.numbers(key);
  if (values.size() != n)
    reader.fail(key, "has " + std::to_string(values.size()) + " values, ring_pack.groove_diameter has " +
                         std::to_string(n));
  return values;
}

void check_elements(const CaseReader &reader, const std::string &key, const std::vector<double> &values,
                    bool allow_zero) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (allow_zero ? values[i] < 0.0 : !(values[i] > 0.0))
      reader.fail(key, "element " + std::to_string(i) + ": must be " + (allow_zero ? ">= 0" : "positive") +
                           ", got " + CaseReader::format(values[i]));
}

// [ring_pack]: arrays, one element per ring, groove order A, B, ...
std::vector<Spec> read_pack_specs(const CaseReader &reader, PistonRingCase &c) {
  const auto &p = c.parameters;
  for (const char *key : {"ring.elastic_pressure", "ring.land_stiffness", "ring.groove_diameter", "ring.land_width",
                          "wear.crown_height"})
    if (reader.has(key)) reader.fail(key, "is set per ring in [ring_pack] when the case has one");
  c.ring_model = reader.choice("ring_pack.model", {"pack", "single"}, std::string("pack"));
  const std::vector<double> grooves = reader.numbers("ring_pack.groove_diameter");
  const std::size_t n = grooves.size();
  if (n > 8) reader.fail("ring_pack.groove_diameter", "at most 8 rings, got " + std::to_string(n));
  const bool by_hand = reader.has("ring_pack.land_stiffness");
  const auto positions = per_ring(reader, "ring_pack.groove_position", n, n > 1, 0.0);
  const auto tensions = per_ring(reader, "ring_pack.elastic_pressure", n, true, 0.0);
  const auto crowns = per_ring(reader, "ring_pack.crown_height", n, false, 0.0);
  const auto lands = per_ring(reader, "ring_pack.land_width", n, !by_hand, 0.0);
  const auto stiffness = per_ring(reader, "ring_pack.land_stiffness", n, false, 0.0);
  check_elements(reader, "ring_pack.groove_diameter", grooves, false);
  check_elements(reader, "ring_pack.elastic_pressure", tensions, false);
  check_elements(reader, "ring_pack.crown_height", crowns, true);
  if (by_hand) check_elements(reader, "ring_pack.land_stiffness", stiffness, false);
  else check_elements(reader, "ring_pack.land_width", lands, false);
  std::vector<Spec> specs;
  for (std::size_t i = 0; i < n; ++i) {
    if (grooves[i] >= p.bore)
      reader.fail("ring_pack.groove_diameter", "element " + std::to_string(i) + ": must be below ring.bore (" +
                                                   CaseReader::format(p.bore) + "), got " +
                                                   CaseReader::format(grooves[i]));
    for (std::size_t j = 0; j < i; ++j)
      if (std::abs(positions[i] - positions[j]) < p.ring_width)
        reader.fail("ring_pack.groove_position",
                    "grooves " + std::to_string(j) + " and " + std::to_string(i) + " overlap: centres " +
                        CaseReader::format(std::abs(positions[i] - positions[j])) +
                        " m apart, less than the ring width " + CaseReader::format(p.ring_width) + " m");
    specs.push_back(Spec{grooves[i], lands[i], tensions[i], crowns[i], positions[i], stiffness[i],
                         by_hand ? "ring_pack.land_stiffness" : ""});
  }
  if (c.ring_model == "single") specs.resize(1);
  return specs;
}

// The one ring of [ring].
Spec read_single_spec(const CaseReader &reader, const continuum::PistonRingParameters &p) {
  Spec spec;
  spec.tension = reader.positive("ring.elastic_pressure");
  spec.crown = reader.non_negative("wear.crown_height", 0.0);
  if (reader.has("ring.land_stiffness")) {
    for (const char *key : {"ring.groove_diameter", "ring.land_width"})
      if (reader.has(key)) reader.fail(key, "give either ring.land_stiffness or the land geometry, not both");
    spec.stiffness = reader.positive("ring.land_stiffness");
    spec.stiffness_key = "ring.land_stiffness";
    return spec;
  }
  if (!reader.has("ring.groove_diameter") || !reader.has("ring.land_width"))
    reader.fail(reader.has("ring.groove_diameter") ? "ring.land_width" : "ring.groove_diameter",
                "missing: the land stiffness is computed from ring.groove_diameter and ring.land_width "
                "(or give ring.land_stiffness)");
  spec.groove_diameter = reader.positive("ring.groove_diameter");
  spec.land_width = reader.positive("ring.land_width");
  if (spec.groove_diameter >= p.bore)
    reader.fail("ring.groove_diameter", "must be below ring.bore (" + CaseReader::format(p.bore) + "), got " +
                                            CaseReader::format(spec.groove_diameter));
  return spec;
}

// The rings: [ring_pack] or the one ring of [ring]; the land stiffness from geometry unless given.
void read_rings(const CaseReader &reader, PistonRingCase &c, const RingSection &section) {
  const auto &p = c.parameters;
  const std::vector<Spec> specs =
      reader.has("ring_pack") ? read_pack_specs(reader, c) : std::vector<Spec>{read_single_spec(reader, p)};
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const Spec &spec = specs[i];
    PistonRingOfPack ring;
    ring.name = std::string(1, static_cast<char>('A' + i));
    ring.position = spec.position;
    ring.parameters = p;
    ring.parameters.elastic_pressure = spec.tension;
    if (spec.stiffness_key.empty()) {
      continuum::RingLandGeometry geometry{p.bore, spec.groove_diameter, spec.land_width, p.ring_width,
                                           section.thickness, section.youngs, section.poisson};
      try {
        ring.land = continuum::land_stiffness(geometry);
      } catch (const std::invalid_argument &e) {
        reader.fail(reader.has("ring_pack") ? "ring_pack" : "ring", e.what());
      }
      ring.groove_diameter = spec.groove_diameter;
      ring.land_width = spec.land_width;
      ring.parameters.land_stiffness = ring.land->total;
    } else {
      ring.parameters.land_stiffness = spec.stiffness;
    }
    ring.parameters.land_damping = 2.0 * c.land_damping_ratio * std::sqrt(ring.parameters.land_stiffness * p.ring_mass);
    ring.wear_settings.crown_height = spec.crown;
    c.rings.push_back(ring);
  }
}

// Ring face on the liner: elastic half-plane line contact (E* of two equal bodies), or the former Winkler layer with
// the plane-strain modulus over the ring's radial thickness; its grid and wear step.
void read_face_contact(const CaseReader &reader, PistonRingCase &c, const RingSection &section) {
  const auto &p = c.parameters;
  auto &w = c.wear_settings;
  w.bore = p.bore;
  w.ring_width = p.ring_width;
  w.ring_thickness = section.thickness;  // wear-through limit of the ring face
  const double youngs = section.youngs, poisson = section.poisson;
  const bool winkler = reader.choice("wear.contact", {"half_plane", "winkler"}, std::string("half_plane")) == "winkler";
  w.contact = winkler ? continuum::FaceContact::Winkler : continuum::FaceContact::HalfPlane;
  w.contact_modulus = youngs / (2.0 * (1.0 - poisson * poisson));
  w.foundation_modulus =
      reader.positive("wear.foundation_modulus", youngs / (1.0 - poisson * poisson) / section.thickness);
  // below a 1 MPa elastomer over 1 m the face no longer carries the ring (1e-300 diverged to nan)
  if (w.foundation_modulus < 1e6)
    reader.fail("wear.foundation_modulus", "must be at least 1e6 Pa/m, got " + CaseReader::format(w.foundation_modulus));
  if (!winkler && reader.has("wear.foundation_modulus"))
    reader.fail("wear.foundation_modulus", "only used by wear.contact = \"winkler\"");
  w.ring_cells = static_cast<int>(reader.positive_integer("wear.ring_cells", 64));
  w.liner_cells = static_cast<int>(reader.positive_integer("wear.liner_cells", 512));
  // caps keep one run within seconds (measured, doc/hardening.md): 16384 ring cells 9 s, 1e5 liner cells 13 s
  if (w.ring_cells < 2 || w.ring_cells > 16384) reader.fail("wear.ring_cells", "must lie in [2, 16384]");
  if (w.liner_cells < 2 || w.liner_cells > 100000) reader.fail("wear.liner_cells", "must lie in [2, 100000]");
  w.step_safety = reader.positive("wear.step_safety", 0.5);
  if (w.step_safety >= 1.0) reader.fail("wear.step_safety", "must be below 1 (the stability bound)");
  w.fixed_step = reader.non_negative("wear.fixed_step", 0.0);
}

// The wear law: Archard's (k, hardnesses, form), or none besides the state law's.
void read_wear_law(const CaseReader &reader, PistonRingCase &c, bool state_law) {
  if (state_law) {
    // One wear law: the state law's wear_rate wears the ring face, its counterface_wear_rate the liner.
    for (const char *key : {"wear.k", "wear.hardness", "wear.hardness_ring", "wear.hardness_liner", "wear.form"})
      if (reader.has(key))
        reader.fail(key, "not used with friction.model = \"state_law\" (the law's wear_rate wears the ring face, "
                         "its counterface_wear_rate the liner)");
    c.archard.emplace(0.0, 1.0, tribo::ArchardForm::plain);
    return;
  }
  const double hardness = reader.positive("wear.hardness");
  const double hardness_ring = reader.positive("wear.hardness_ring", hardness);
  const double hardness_liner = reader.positive("wear.hardness_liner", hardness);
  c.wear_settings.ring_share = tribo::wear_share(hardness_ring, hardness_liner);
  const auto form = reader.choice("wear.form", {"plain", "thesis"}, std::string("plain")) == "plain"
                        ? tribo::ArchardForm::plain
                        : tribo::ArchardForm::thesis;
  c.archard.emplace(reader.non_negative("wear.k"), hardness, form);
}

void read_run(const CaseReader &reader, PistonRingCase &c) {
  auto &run = c.run;
  run.t_end = reader.positive("run.t_end");
  run.output_interval = reader.positive("run.output_interval", 1e-3);
  if (run.t_end / run.output_interval > 1e7) reader.fail("run.output_interval", "gives more than 1e7 samples");
  run.max_events = static_cast<int>(std::min<long>(reader.positive_integer("run.max_events", 20000), 1L << 30));
  continuum::CvodeIntegrator::Settings defaults;
  defaults.rtol = 1e-8;
  defaults.atol = 1e-12;
  defaults.max_steps = 100000;
  run.integrator = read_solver(reader, defaults);
}

// [output] and [sweep]; returns the largest static coefficient a run can have (it sizes the liner grid).
double read_output_and_sweep(const CaseReader &reader, PistonRingCase &c, bool state_law) {
  if (reader.has("output.vtk_times")) {
    c.vtk_times = reader.times_within("output.vtk_times", c.run.t_end);
  } else {
    for (int i = 0; i <= 4; ++i) c.vtk_times.push_back(c.run.t_end * i / 4.0);
  }
  c.circumferential_points = static_cast<int>(reader.positive_integer("output.circumferential_points", 48));
  if (c.circumferential_points < 3 || c.circumferential_points > 4096)
    reader.fail("output.circumferential_points", "must lie in [3, 4096]");
  double mu_static_max = c.friction->static_coefficient();
  if (const auto *law = c.friction->state_law()) {  // the held value is set at run time: bound it by the law
    for (const auto &row : law->law->table(coupling::StateField::MuBody).mean)
      for (double mu : row) mu_static_max = std::max(mu_static_max, mu);
    if (law->mu_static) mu_static_max = std::max(mu_static_max, *law->mu_static);
  }
  if (!reader.has("sweep.mu0")) return mu_static_max;
  if (state_law) reader.fail("sweep.mu0", "not available with friction.model = \"state_law\" (mu_static is the law's)");
  c.sweep_mu0 = reader.numbers_at_most("sweep.mu0", CaseReader::kMaxSweepValues);
  if (c.friction_model == "law_file")
    reader.fail("sweep.mu0", "needs friction.model constant, static_kinetic or feedback, not 'law_file'");
  for (std::size_t i = 0; i < c.sweep_mu0.size(); ++i) {
    if (c.sweep_mu0[i] < 0.0) reader.fail("sweep.mu0", "element " + std::to_string(i) + ": must be >= 0");
    try {
      piston_ring_friction_with_mu0(c, c.sweep_mu0[i]);
    } catch (const std::invalid_argument &e) {
      reader.fail("sweep.mu0", "element " + std::to_string(i) + ": " + e.what());
    }
    mu_static_max = std::max(mu_static_max, c.sweep_mu0[i]);
  }
  return mu_static_max;
}

// Liner grid: the travel of every ring plus its half width, its land deflection at the static limit and 1 mm; every
// ring gets the case's wear settings with its own crown.
void set_liner_grid(PistonRingCase &c, double mu_static_max) {
  auto &p = c.parameters;
  auto &w = c.wear_settings;
  const double x_low = p.motion == continuum::PistonMotion::Ramp ? p.crank.position(p.start_angle)
                                                                  : p.crank.bottom_dead_centre();
  const double x_high = p.crank.top_dead_centre();
  double gas_max = 0.0;
  for (double g : p.gas.pressure) gas_max = std::max(gas_max, p.gas.factor * g);
  double low = x_low, high = x_high;
  for (const auto &ring : c.rings) {
    const auto &rp = ring.parameters;
    const double load_max = (rp.elastic_pressure + gas_max) * rp.contact_area();
    const double margin = 0.5 * p.ring_width + 1e-3 + 4.0 * mu_static_max * load_max / rp.land_stiffness;
    low = std::min(low, x_low + ring.position - margin);
    high = std::max(high, x_high + ring.position + margin);
  }
  w.liner_begin = low;
  w.liner_end = high;
  for (auto &ring : c.rings) {
    const double crown = ring.wear_settings.crown_height;
    ring.wear_settings = w;
    ring.wear_settings.crown_height = crown;
  }
  p = c.rings.front().parameters;
  w = c.rings.front().wear_settings;
}

}  // namespace

PistonRingCase read_piston_ring_case(const std::string &path, const std::optional<std::string> &law_path) {
  const CaseReader reader(path, parse_toml(path), schema());
  reader.reject_unknown_keys();

  PistonRingCase c;
  c.path = path;
  c.title = reader.text("title", path);
  auto &p = c.parameters;
  read_kinematics(reader, p);
  const RingSection section = read_ring_and_material(reader, path, c);
  read_rings(reader, c, section);

  // Gas pressure behind the ring (crank motion only).
  if (reader.has("gas")) {
    if (p.motion != continuum::PistonMotion::Crank) reader.fail("gas", "needs kinematics.motion = \"crank\"");
    p.gas = read_gas_pressure_table(reader);
  }

  c.friction = read_friction(reader, law_path);
  check_law_materials(reader, *c.friction, law_path, "material.ring_material", c.ring_material_name, "material.liner_material", c.liner_material_name);
  // the liner is one surface under every ring of the pack and along the stroke: its film is not held per face cell
  read_film(reader, *c.friction,
            "a film on the liner is not modelled in the piston ring (the ring face's film is: drop the counterface_* "
            "keys)");
  c.friction_model =
      reader.choice("friction.model", {"constant", "static_kinetic", "law_file", "feedback", "state_law"});
  const bool state_law = c.friction_model == "state_law";

  for (auto &ring : c.rings) ring.parameters.gas = p.gas;

  read_face_contact(reader, c, section);
  read_wear_law(reader, c, state_law);
  read_run(reader, c);
  set_liner_grid(c, read_output_and_sweep(reader, c, state_law));

  for (const auto &ring : c.rings) {
    try {
      ring.parameters.validate();
      ring.wear_settings.validate();
    } catch (const std::invalid_argument &e) {
      reader.fail(c.rings.size() > 1 ? "ring_pack" : "ring", e.what());
    }
  }
  return c;
}

}  // namespace runin::cli
