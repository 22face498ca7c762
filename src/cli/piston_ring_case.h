// Reading and validating a piston-ring case file (TOML), thesis ch. 6.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "continuum/piston_ring.h"
#include "continuum/ring_liner_wear.h"
#include "tribo/wear.h"

namespace runin::cli {

class CaseReader;

// One ring of the pack: its own tension, land, face profile and wear (ring face + its share of
// the one liner). Its centre rides at piston position + `position` + land deflection.
struct PistonRingOfPack {
  std::string name;                                  // "A", "B", ... (groove order of ring_pack arrays)
  continuum::PistonRingParameters parameters;        // kinematics as the case; own W, m, k, c
  continuum::RingLinerWearSettings wear_settings;    // own crown; liner grid of the whole pack
  double position = 0.0;                             // m, groove centre along the piston, + towards the crown
  double groove_diameter = 0.0, land_width = 0.0;    // m (0 if the stiffness was given)
  std::optional<continuum::LandStiffness> land;      // from geometry; empty: land_stiffness given by hand
};

struct PistonRingCase {
  std::string path;
  std::string title;
  continuum::PistonRingParameters parameters;        // = rings[0].parameters
  std::string ring_model = "single";                 // single ([ring] only, or ring_pack.model) | pack
  std::vector<PistonRingOfPack> rings;               // 1 (single) or the pack, in ring_pack order
  continuum::PistonRingRun run;
  std::optional<continuum::SlidingFriction> friction;
  std::string friction_model;  // constant | static_kinetic | law_file | feedback
  continuum::RingLinerWearSettings wear_settings;  // = rings[0].wear_settings; liner grid set from the stroke
  std::optional<tribo::ArchardWear> archard;
  double land_damping_ratio = 0.0;
  std::vector<double> vtk_times;  // s
  int circumferential_points = 48;
  std::vector<double> sweep_mu0;  // [sweep] mu0, empty if absent
  // Subsurface stress (doc/subsurface_stress.md): nu from [material]; S_y (and H) from material.materials with
  // material.ring_material / material.liner_material (names empty: S_y unknown).
  tribo::Material ring_material, liner_material;
  std::string ring_material_name, liner_material_name;
};

// `law_path` is the --law option; required exactly when friction.model = "law_file".
PistonRingCase read_piston_ring_case(const std::string &path, const std::optional<std::string> &law_path);
// The case's [gas] table (crank_angle_deg, pressure, cycle_deg, factor), shared by the dry and lubricated rings.
continuum::GasPressureTable read_gas_pressure_table(const CaseReader &reader);

// The case's friction with the static coefficient replaced by mu0 (friction_with_static_coefficient).
// Throws std::invalid_argument for law_file or a mu0 not above the feedback law's steady value.
continuum::SlidingFriction piston_ring_friction_with_mu0(const PistonRingCase &c, double mu0);

}  // namespace runin::cli
