// Reading and validating a dry journal-bearing case file (TOML), thesis ch. 5.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "continuum/journal_bearing.h"

namespace runin::cli {

struct JournalBearingCase {
  std::string path;
  std::string title;
  continuum::JournalBearingParameters parameters;
  continuum::JournalBearingRun run;
  std::optional<continuum::SlidingFriction> friction;
  std::string friction_model;           // constant | static_kinetic | law_file | feedback
  double kinetic_to_static = 1.0;       // mu_kinetic / mu_static (static_kinetic), kept in the sweep
  double alpha = 0.0;
  std::vector<double> sweep_mu0;        // [sweep] mu0, empty if absent
  int axial_points = 11;                // VTK grid across the bearing length
  double shaft_diameter = 0.0, shaft_length = 0.0;  // m, [shaft] (defaults: 2 R and 0.2 m)
  double shaft_stiffness = 0.0;         // N m/rad, G J / L of the shaft
  bool stiffness_overridden = false;    // drive.stiffness given: it replaces G J / L
  bool one_contact_comparison = true;   // output.one_contact_comparison: re-run with one contact for the summary
  // Subsurface stress (doc/subsurface_stress.md): nu of each body from [bearing] / [shaft]; S_y (and H) from
  // contact.materials with contact.bearing_material / contact.shaft_material (names empty: S_y unknown).
  tribo::Material bearing_material, shaft_material;
  std::string bearing_material_name, shaft_material_name;
};

// `law_path` is the --law option; required exactly when friction.model = "law_file".
JournalBearingCase read_journal_bearing_case(const std::string &path, const std::optional<std::string> &law_path);

// The case's friction law with the static coefficient replaced by mu0 (friction_with_static_coefficient:
// constant: mu0; static_kinetic: mu_static = mu0, mu_kinetic = mu0 * kinetic_to_static; feedback:
// R0 with mu(R0) = mu0).
continuum::SlidingFriction friction_with_mu0(const JournalBearingCase &c, double mu0);

}  // namespace runin::cli
