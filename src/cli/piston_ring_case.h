// Reading and validating a piston-ring case file (TOML), thesis ch. 6.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#include "tribo/wear.h"

namespace runin::cli {

struct PistonRingCase {
  std::string path;
  std::string title;
  continuum::PistonRingParameters parameters;
  continuum::PistonRingRun run;
  std::optional<continuum::SlidingFriction> friction;
  std::string friction_model;  // constant | static_kinetic | law_file | feedback
  continuum::RingLinerWearSettings wear_settings;  // liner grid set from the stroke
  std::optional<tribo::ArchardWear> archard;
  double land_damping_ratio = 0.0;
  std::vector<double> vtk_times;  // s
  int circumferential_points = 48;
  std::vector<double> sweep_mu0;  // [sweep] mu0, empty if absent
};

// `law_path` is the --law option; required exactly when friction.model = "law_file".
PistonRingCase read_piston_ring_case(const std::string &path, const std::optional<std::string> &law_path);

// The case's friction with the static coefficient replaced by mu0 (friction_with_static_coefficient).
// Throws std::invalid_argument for law_file or a mu0 not above the feedback law's steady value.
continuum::SlidingFriction piston_ring_friction_with_mu0(const PistonRingCase &c, double mu0);

}  // namespace runin::cli
