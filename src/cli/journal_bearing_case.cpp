#include "cli/journal_bearing_case.h"

#include <cmath>

#include "cli/case_file.h"
#include "cli/case_reader.h"

namespace runin::cli {
namespace {

const Schema kSchema = {
    {"", {"title", "bearing", "shaft", "contact", "drive", "wear", "friction", "run", "solver", "sweep", "output",
          "film"}},
    {"film", film_keys()},
    {"bearing", {"shaft_radius", "clearance", "length", "youngs_modulus", "poisson_ratio", "load", "halves",
                 "second_half_load"}},
    {"shaft", {"diameter", "length", "youngs_modulus", "poisson_ratio"}},
    {"contact", {"arc_half_angle", "nodes", "materials", "bearing_material", "shaft_material"}},
    {"drive", {"ramp_angle", "ramp_time", "run_speed", "inertia", "stiffness", "damping_ratio"}},
    {"wear", {"coefficient", "hardness", "form", "step_fraction", "fixed_step"}},
    {"friction", friction_keys()},
    {"run", {"t_end", "output_interval", "frame_times"}},
    {"solver", {"method", "rtol", "atol", "max_steps"}},
    {"sweep", {"mu0"}},
    {"output", {"axial_points", "one_contact_comparison"}},
};

}  // namespace

continuum::SlidingFriction friction_with_mu0(const JournalBearingCase &c, double mu0) {
  return friction_with_static_coefficient(*c.friction, c.friction_model, mu0);
}

namespace {

// [bearing] and [contact]: the bore, the load on each half, the contact arc and its nodes, the named materials.
void read_bearing(const CaseReader &reader, const std::string &path, JournalBearingCase &c) {
  auto &p = c.parameters;
  auto &b = p.bore;
  b.shaft_radius = reader.positive("bearing.shaft_radius");
  b.clearance = reader.positive("bearing.clearance");
  b.axial_width = reader.positive("bearing.length");
  b.youngs_modulus = reader.positive("bearing.youngs_modulus");
  b.poisson_ratio = reader.number("bearing.poisson_ratio");
  if (!(b.poisson_ratio > -1.0 && b.poisson_ratio < 0.5))
    reader.fail("bearing.poisson_ratio", "must be in (-1, 0.5), got " + CaseReader::format(b.poisson_ratio));
  p.load = reader.positive("bearing.load");
  // Thesis ch. 5: "a 1 kg vertical load is applied equally and in opposite directions to each bearing half".
  const long halves = reader.positive_integer("bearing.halves", 2);
  if (halves != 1 && halves != 2)
    reader.fail("bearing.halves", "must be 2 (two opposite bearing halves, the thesis) or 1 (one contact), got " +
                                      std::to_string(halves));
  p.halves = static_cast<int>(halves);
  if (reader.has("bearing.second_half_load")) {
    if (p.halves != 2) reader.fail("bearing.second_half_load", "needs bearing.halves = 2");
    p.second_half_load = reader.positive("bearing.second_half_load");
  }

  b.arc_half_angle = reader.positive("contact.arc_half_angle", 0.5);
  if (!(b.arc_half_angle < 0.5 * M_PI))
    reader.fail("contact.arc_half_angle", "must be below pi/2 rad, got " + CaseReader::format(b.arc_half_angle));
  const long nodes = reader.positive_integer("contact.nodes", 256);
  if (nodes < 3 || nodes > 2048) reader.fail("contact.nodes", "must be in [3, 2048], got " + std::to_string(nodes));
  b.nodes = static_cast<int>(nodes);

  // The contact model's E and nu stay the case's; the file gives the yield verdict's S_y (or H).
  if (const auto named = read_named_materials(reader, path, "contact", "bearing_material", "shaft_material")) {
    c.bearing_material_name = named->name_a;
    c.shaft_material_name = named->name_b;
    named->copy_strengths(c.bearing_material, c.shaft_material);
  }
}

// [drive] and [shaft]: the prescribed rotation and the torsional coupling (the shaft's G J / L unless overridden).
void read_drive(const CaseReader &reader, JournalBearingCase &c) {
  auto &p = c.parameters;
  const auto &b = p.bore;
  p.ramp_angle = reader.number("drive.ramp_angle", 1.0);
  p.ramp_time = reader.positive("drive.ramp_time", 2.0);
  p.run_speed = reader.number("drive.run_speed", 0.0);
  p.inertia = reader.positive("drive.inertia");
  // Drive stiffness: the shaft's torsion between the drive and the bearing, k = G J / L with
  // G = E / (2 (1 + nu)) and J = pi d^4 / 32, unless drive.stiffness overrides it.
  c.shaft_diameter = reader.positive("shaft.diameter", 2.0 * b.shaft_radius);
  c.shaft_length = reader.positive("shaft.length", 0.2);
  const double shaft_modulus = reader.positive("shaft.youngs_modulus", b.youngs_modulus);
  const double shaft_poisson = reader.number("shaft.poisson_ratio", b.poisson_ratio);
  if (!(shaft_poisson > -1.0 && shaft_poisson < 0.5))
    reader.fail("shaft.poisson_ratio", "must be in (-1, 0.5), got " + CaseReader::format(shaft_poisson));
  c.shaft_stiffness =
      continuum::shaft_torsional_stiffness(c.shaft_diameter, c.shaft_length, shaft_modulus, shaft_poisson);
  c.bearing_material.youngs_modulus = b.youngs_modulus;
  c.bearing_material.poisson_ratio = b.poisson_ratio;
  c.shaft_material.youngs_modulus = shaft_modulus;
  c.shaft_material.poisson_ratio = shaft_poisson;
  c.stiffness_overridden = reader.has("drive.stiffness");
  p.coupling_stiffness = c.stiffness_overridden ? reader.positive("drive.stiffness") : c.shaft_stiffness;
  const double damping_ratio = reader.non_negative("drive.damping_ratio", 0.0);
  p.coupling_damping = 2.0 * damping_ratio * std::sqrt(p.coupling_stiffness * p.inertia);
}

// [wear]: Archard's law of the bore, or none besides the state law's; the wear step.
void read_bearing_wear(const CaseReader &reader, JournalBearingCase &c, bool state_law) {
  auto &p = c.parameters;
  if (state_law) {
    // One wear law: the state law's wear_rate wears the bore (doc/state_law_continuum.md).
    for (const char *key : {"wear.coefficient", "wear.hardness", "wear.form"})
      if (reader.has(key))
        reader.fail(key, "not used with friction.model = \"state_law\" (the law's wear_rate wears the bore)");
    p.wear_coefficient = 0.0;
    p.hardness = 1.0;  // unused
  } else {
    p.wear_coefficient = reader.non_negative("wear.coefficient", 0.0);
    p.hardness = reader.positive("wear.hardness");
    p.archard_form = reader.choice("wear.form", {"plain", "thesis"}, std::string("plain")) == "plain"
                         ? tribo::ArchardForm::plain
                         : tribo::ArchardForm::thesis;
  }
  // [0.01, 1): unstable above; below, the number of wear updates (each a contact solve) grows without bound, and
  // the state-law path has no update cap of its own
  c.run.wear_step_fraction = reader.number("wear.step_fraction", 0.5);
  if (!(c.run.wear_step_fraction >= 0.01 && c.run.wear_step_fraction < 1.0))
    reader.fail("wear.step_fraction", "must be in [0.01, 1) (the explicit wear step is unstable from 1 on), got " +
                                          CaseReader::format(c.run.wear_step_fraction));
  c.run.fixed_wear_step = reader.has("wear.fixed_step") ? reader.positive("wear.fixed_step") : 0.0;
}

void read_bearing_run(const CaseReader &reader, continuum::JournalBearingRun &run) {
  run.t_end = reader.positive("run.t_end");
  run.output_interval = reader.positive("run.output_interval", 1e-3);
  if (run.t_end / run.output_interval > 1e7) reader.fail("run.output_interval", "gives more than 1e7 samples");
  if (reader.has("run.frame_times")) {
    run.frame_times = reader.times_within("run.frame_times", run.t_end);
  } else {
    run.frame_times = {0.0, run.t_end};
  }
  continuum::CvodeIntegrator::Settings defaults;
  defaults.rtol = 1e-8;
  defaults.atol = 1e-10;
  defaults.max_steps = 100000;
  run.integrator = read_solver(reader, defaults);
}

void read_bearing_sweep(const CaseReader &reader, JournalBearingCase &c, bool state_law) {
  if (state_law) reader.fail("sweep.mu0", "not available with friction.model = \"state_law\" (mu_static is the law's)");
  if (c.friction_model == "law_file")
    reader.fail("sweep.mu0", "needs friction.model 'constant', 'static_kinetic' or 'feedback'");
  c.sweep_mu0 = reader.numbers_at_most("sweep.mu0", CaseReader::kMaxSweepValues);
  for (std::size_t i = 0; i < c.sweep_mu0.size(); ++i) {
    if (c.sweep_mu0[i] < 0.0)
      reader.fail("sweep.mu0", "element " + std::to_string(i) + ": must be >= 0, got " + CaseReader::format(c.sweep_mu0[i]));
    try {
      friction_with_mu0(c, c.sweep_mu0[i]);
    } catch (const std::invalid_argument &e) {
      reader.fail("sweep.mu0", "element " + std::to_string(i) + ": " + e.what());
    }
  }
}

}  // namespace

JournalBearingCase read_journal_bearing_case(const std::string &path, const std::optional<std::string> &law_path) {
  const CaseReader reader(path, parse_toml(path), kSchema);
  reader.reject_unknown_keys();

  JournalBearingCase c;
  c.path = path;
  c.title = reader.text("title", path);
  read_bearing(reader, path, c);
  read_drive(reader, c);
  const bool state_law = reader.has("friction.model") && reader.text("friction.model", "") == "state_law";
  read_bearing_wear(reader, c, state_law);

  c.friction_model =
      reader.choice("friction.model", {"constant", "static_kinetic", "law_file", "feedback", "state_law"});
  c.friction = read_friction(reader, law_path);
  check_law_materials(reader, *c.friction, law_path, "contact.bearing_material", c.bearing_material_name, "contact.shaft_material", c.shaft_material_name);
  // one shaft passes both halves: its film would be one state shared by them, which the halves' nodes do not hold
  read_film(reader, *c.friction,
            "a film on the shaft is not modelled in the journal bearing (the bore's film is: drop the counterface_* "
            "keys)");
  c.alpha = c.friction->speed_coefficient();
  if (c.friction_model == "static_kinetic") {
    const double mu_static = reader.number("friction.mu_static");
    c.kinetic_to_static = mu_static > 0.0 ? reader.number("friction.mu_kinetic") / mu_static : 1.0;
  }
  read_bearing_run(reader, c.run);
  if (reader.has("sweep.mu0")) read_bearing_sweep(reader, c, state_law);
  c.axial_points = static_cast<int>(reader.positive_integer("output.axial_points", 11));
  c.one_contact_comparison = reader.choice("output.one_contact_comparison", {"run", "skip"}, std::string("run")) == "run";
  if (c.axial_points < 2 || c.axial_points > 1000) reader.fail("output.axial_points", "must be in [2, 1000]");

  try {
    c.parameters.validate();
    c.run.validate();
  } catch (const std::invalid_argument &e) {
    reader.fail("bearing", e.what());  // every field is checked above; this is a safety net
  }
  return c;
}

}  // namespace runin::cli
