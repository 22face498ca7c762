#include "cli/lubricated_ring_case.h"

#include <cmath>
#include <stdexcept>

#include "cli/case_file.h"
#include "cli/case_reader.h"
#include "cli/piston_ring_case.h"  // read_gas_pressure_table

namespace runin::cli {
namespace {

constexpr double kPi = 3.14159265358979323846;

const Schema &schema() {
  static const Schema s = {
      {"", {"title", "kinematics", "ring", "material", "gas", "friction", "lubrication", "stribeck", "output"}},
      {"kinematics", {"motion", "crank_radius", "link_length"}},
      {"ring", {"bore", "width", "elastic_pressure", "crown_height"}},
      {"material", {"youngs_modulus", "poisson_ratio", "materials", "ring_material", "liner_material"}},
      {"gas", {"crank_angle_deg", "pressure", "cycle_deg", "factor"}},
      {"friction", friction_keys()},
      {"lubrication", {"viscosity", "crank_speed_rpm", "cycles", "inlet", "oil_film_thickness", "nodes",
                       "steps_per_cycle", "liner_roughness", "liner_sigma", "jump_depth_fraction",
                       "jump_sigma_fraction", "worn_surface"}},
      {"stribeck", {"load", "speed_min", "speed_max", "points"}},
      {"output", {"frames_per_cycle"}},
  };
  return s;
}

}  // namespace

bool is_lubricated_ring_case(const std::string &path) {
  const toml::table root = parse_toml(path);
  return root.contains("lubrication") || root.contains("stribeck");
}

namespace {

// Kinematics (eq. 6.1 at constant crank speed, the cycle from TDC) and the ring; the ranges are those of a ring of an
// engine (beyond them the film and contact arithmetic leave double range).
void read_ring_geometry(const CaseReader &reader, continuum::MixedRingParameters &p) {
  reader.choice("kinematics.motion", {"crank"}, std::string("crank"));
  p.crank.crank_radius = reader.positive("kinematics.crank_radius");
  p.crank.link_length = reader.positive("kinematics.link_length");
  if (p.crank.link_length <= p.crank.crank_radius)
    reader.fail("kinematics.link_length",
                "must exceed kinematics.crank_radius (" + CaseReader::format(p.crank.crank_radius) + ")");
  const double rpm = reader.positive_at_most("lubrication.crank_speed_rpm", 1e5);
  if (rpm < 1.0) reader.fail("lubrication.crank_speed_rpm", "must be at least 1, got " + CaseReader::format(rpm));
  p.crank_speed = rpm * 2.0 * kPi / 60.0;

  p.bore = reader.positive_at_most("ring.bore", 10.0);
  p.face_width = reader.positive("ring.width");
  if (p.face_width >= p.bore) reader.fail("ring.width", "must be below ring.bore");
  if (p.face_width < 1e-5) reader.fail("ring.width", "must be at least 1e-5 m, got " + CaseReader::format(p.face_width));
  p.elastic_pressure = reader.positive_at_most("ring.elastic_pressure", 1e8);
  if (p.elastic_pressure < 1.0)
    reader.fail("ring.elastic_pressure", "must be at least 1 Pa, got " + CaseReader::format(p.elastic_pressure));
  p.crown_height = reader.non_negative("ring.crown_height", 0.0);
  if (p.crown_height > p.face_width) reader.fail("ring.crown_height", "must not exceed ring.width");
}

// [lubrication]: the oil, its inlet, the face grid, the liner's roughness and cycle jumping.
void read_ring_lubrication(const CaseReader &reader, LubricatedRingCase &c) {
  auto &p = c.parameters;
  p.viscosity = reader.positive_at_most("lubrication.viscosity", 100.0);
  if (p.viscosity < 1e-5)
    reader.fail("lubrication.viscosity", "must be at least 1e-5 Pa s (a gas, not an oil), got " + CaseReader::format(p.viscosity));
  // cycle jumping makes cycles cheap, not free: 1e5 revolutions of the shipped case take 15 s (45 computed)
  c.run.cycles = reader.positive_integer("lubrication.cycles", 0, 1000000000L);   // cycle jumping: a mild-wear run-in is millions of revolutions
  if (c.run.cycles == 0) reader.fail("lubrication.cycles", "missing (required): engine cycles to run in");
  const std::string inlet = reader.choice("lubrication.inlet", {"flooded", "starved"}, std::string("flooded"));
  p.supply = inlet == "flooded" ? continuum::OilSupply::Flooded : continuum::OilSupply::Starved;
  if (p.supply == continuum::OilSupply::Starved) {
    p.oil_film = reader.positive_at_most("lubrication.oil_film_thickness", 1e-2);
    if (p.oil_film < 1e-9)
      reader.fail("lubrication.oil_film_thickness", "must be at least 1e-9 m, got " + CaseReader::format(p.oil_film));
  }
  else if (reader.has("lubrication.oil_film_thickness"))
    reader.fail("lubrication.oil_film_thickness", "only used with lubrication.inlet = \"starved\"");
  p.nodes = static_cast<int>(reader.positive_integer("lubrication.nodes", 101, 2001));
  if (p.nodes < 11) reader.fail("lubrication.nodes", "must be at least 11");
  p.steps_per_cycle = static_cast<int>(reader.positive_integer("lubrication.steps_per_cycle", 360, 100000));
  if (p.steps_per_cycle < 36) reader.fail("lubrication.steps_per_cycle", "must be at least 36");
  c.liner_roughness = reader.choice("lubrication.liner_roughness", {"law", "fixed"}, std::string("law"));
  p.liner = c.liner_roughness == "law" ? continuum::LinerRoughness::Law : continuum::LinerRoughness::Fixed;
  if (p.liner == continuum::LinerRoughness::Fixed) p.liner_sigma = reader.positive_at_most("lubrication.liner_sigma", 1e-5);
  else if (reader.has("lubrication.liner_sigma"))
    reader.fail("lubrication.liner_sigma", "only used with lubrication.liner_roughness = \"fixed\"");
  p.worn_surface = reader.choice("lubrication.worn_surface", {"law_rq", "truncated"}, std::string("law_rq")) == "truncated"
                       ? continuum::WornSurface::TruncatedSummits
                       : continuum::WornSurface::LawRq;
  c.run.jump_depth_fraction = reader.positive_at_most("lubrication.jump_depth_fraction", 1.0, 0.5);
  c.run.jump_sigma_fraction = reader.positive_at_most("lubrication.jump_sigma_fraction", 1.0, 0.05);
  // below 1e-3 a mild run-in computes nearly every cycle (1e-300 ran 1e6 cycles one by one)
  for (const char *key : {"lubrication.jump_depth_fraction", "lubrication.jump_sigma_fraction"}) {
    const double f = reader.number(key, 0.5);
    if (f < 1e-3) reader.fail(key, "must be at least 1e-3 (smaller computes nearly every cycle), got " + CaseReader::format(f));
  }
}

LubricatedRingCase::Stribeck read_ring_stribeck(const CaseReader &reader, const continuum::MixedRingParameters &p) {
  LubricatedRingCase::Stribeck s;
  s.load = reader.positive_at_most("stribeck.load", 1e8 * p.face_width, p.elastic_pressure * p.face_width);
  s.speed_min = reader.positive_at_most("stribeck.speed_min", 1e3, 1e-3);
  s.speed_max = reader.positive_at_most("stribeck.speed_max", 1e3, 30.0);
  if (s.speed_min < 1e-9)
    reader.fail("stribeck.speed_min", "must be at least 1e-9 m/s, got " + CaseReader::format(s.speed_min));
  if (s.speed_max <= s.speed_min)
    reader.fail("stribeck.speed_max", "must exceed stribeck.speed_min (" + CaseReader::format(s.speed_min) + ")");
  s.points = static_cast<int>(reader.positive_integer("stribeck.points", 50, 10000));
  if (s.points < 2) reader.fail("stribeck.points", "must be at least 2");
  return s;
}

}  // namespace

LubricatedRingCase read_lubricated_ring_case(const std::string &path, const std::optional<std::string> &law_path) {
  const CaseReader reader(path, parse_toml(path), schema());
  reader.reject_unknown_keys();
  LubricatedRingCase c;
  c.path = path;
  c.title = reader.text("title", path);
  auto &p = c.parameters;
  if (!reader.has("lubrication"))
    reader.fail("lubrication", "missing: the lubricated mode ([stribeck]) needs the [lubrication] table");

  read_ring_geometry(reader, p);

  const double youngs = reader.positive_at_most("material.youngs_modulus", 1e13);
  if (youngs < 1e6) reader.fail("material.youngs_modulus", "must be at least 1e6 Pa, got " + CaseReader::format(youngs));
  const double poisson = reader.number("material.poisson_ratio", 0.3);
  if (poisson <= -1.0 || poisson >= 0.5) reader.fail("material.poisson_ratio", "must lie in (-1, 0.5)");
  p.effective_modulus = youngs / (2.0 * (1.0 - poisson * poisson));   // ring and liner of one material
  std::string ring_name, liner_name;
  if (const auto named = read_named_materials(reader, path, "material", "ring_material", "liner_material")) {
    ring_name = named->name_a;
    liner_name = named->name_b;
  }

  if (reader.has("gas")) {
    p.gas = read_gas_pressure_table(reader);
  }

  // friction: the state law on the face nodes (mu_body, rq, wear_rate), Archard outside its pressure grid
  if (reader.choice("friction.model", {"constant", "static_kinetic", "law_file", "feedback", "state_law"}) != "state_law")
    reader.fail("friction.model", "the lubricated mode ([lubrication]) needs \"state_law\"");
  if (reader.has("friction.mu_static")) reader.fail("friction.mu_static", "not used by the lubricated mode");
  const continuum::SlidingFriction friction = read_friction(reader, law_path);
  check_law_materials(reader, friction, law_path, "material.ring_material", ring_name, "material.liner_material",
                      liner_name);
  const auto *state = friction.state_law();
  c.law = state->law;
  c.law_path = state->path;
  c.policy = reader.has("friction.out_of_range") ? state->policy : coupling::OutOfRange::Archard;
  try {
    p.summits = continuum::summit_statistics(*c.law);
  } catch (const std::invalid_argument &e) {
    reader.fail(law_path ? "--law" : "friction.law", e.what());
  }

  read_ring_lubrication(reader, c);

  c.frames_per_cycle = static_cast<int>(reader.positive_integer("output.frames_per_cycle", 36, 360));
  if (p.steps_per_cycle % c.frames_per_cycle != 0)
    reader.fail("output.frames_per_cycle", "must divide lubrication.steps_per_cycle (" +
                                               std::to_string(p.steps_per_cycle) + ")");
  c.run.frame_every = p.steps_per_cycle / c.frames_per_cycle;

  if (reader.has("stribeck")) c.stribeck = read_ring_stribeck(reader, p);
  try {
    p.validate();
  } catch (const std::invalid_argument &e) {
    reader.fail("lubrication", e.what());
  }
  return c;
}

}  // namespace runin::cli
