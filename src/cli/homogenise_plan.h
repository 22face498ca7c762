// `runin homogenise`: the case (which cell, which pressure grid, which seeds), the plan of samples it implies and
// the content-addressed cache of their outputs (doc/homogenise.md).
//
// A sample is one run of the cell deck at one (pressure, seed). Its cache key is the SHA-256 of a canonical JSON of
// everything that determines its output: the material file's content and the two names, the surface, p, v, seed,
// acceleration, depth, nslide, nout, the deck's content, the RunIn version and the physics identity of the LAMMPS
// executable that runs it (lmp_runin.physics: its physics sources, compiler and flags; a relink of the same sources
// keeps it), else that executable's SHA-256. The sample lives in <cache>/<key>/; it is complete when
// <cache>/<key>/out.dat exists (the deck renames its output to that name as its very last act).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tribo/contact_model.h"

namespace runin::cli {

struct HomogeniseCase {
  std::string path, title;
  std::string deck_file;  // resolved `deck` key (beside the case file first); empty: runin's default (--deck wins)
  // [material]
  std::string material_file;  // resolved
  std::string rough, counterface;
  // [surface]
  double R = 1.0e-4, sigma = 2.0e-7, spacing = 2.0e-5;
  long nside = 64;
  std::string heights_file;  // resolved summit list (LAMMPS atomfile "ID z"), empty: Gaussian heights of RMS sigma
  std::string heights_sha256;  // of the list's bytes as checked (part of every sample's key)
  bool caps = false;  // the deck's summits as caps (pair_style runin/asperity caps): the same spheres, a shorter list
  // [sliding]
  double speed = 0.1;
  bool vertical_drag = false;  // the counter-body keeps the loading's vertical drag while sliding (no bounce)
  // [grid]
  double pressure_min = 0.0, pressure_max = 0.0;
  std::vector<double> pressures;      // log-spaced, pressure_min .. pressure_max, with grid.extra_pressures, sorted
  std::vector<long> nside_at;         // summits per side at each pressure: surface.nside, or grid.extra_nside's
  std::vector<long> seeds;            // derived: seed_j = 4711 + 7919 j
  std::vector<double> acceleration;   // one per pressure (one number in the case: repeated)
  double depth = 0.0;                 // target mean worn depth of the rough body [m]
  long depth_points = 11;             // columns of the law's h grid, 0 .. depth
  double depth_first = 0.0;           // > 0: the grid is 0, then geometric from depth_first to depth
  long nslide = 100000, nout = 100;
  // [contact]
  // the cell's friction sub-model (the deck's `friction` variable; default: the registry's, its default for a cell)
  std::string friction = tribo::default_interface_friction_model();
  std::string interface;              // interface state of the material file (clean, oxidised, boundary); empty: none
  double interface_factor = 0.0;      // its friction factor m (junction: f = m); 0 without a state
  // [wear]
  double wear_k = 0.0;           // the cell's Archard k of both bodies (0: the material file's pair k)
  double wear_scale = 1.0;       // wear_k / the file's k: the deck's wear_scale besides any acceleration
  double jump_max_depth = 0.0;   // cycle jumping (fix runin/wear/jump): mean depth per jump, h + h_cf [m]; 0: off
  long jump_every = 1000;        // steps per phase of the jumps
  double jump_reference_pressure = 0.0;  // > 0: the tolerance at pressure p is jump_max_depth x p / this
  double jump_max_change = 0.0;  // > 0: largest change of one summit's height per jump [m], at every p (the state
                                 // tolerance of a deep law: doc/fix_runin_wear_jump.rst, "Choosing the jump")
  double jump_rate = 0.0;        // > 0: the jump's mean depth from Rq's measured relative change per cycle (needs
                                 // jump_max_change; jump_max_depth is the first jump's)
  // The jump tolerance of the sample at pressure p: the summits in contact move about D / (contact fraction) per
  // jump and that fraction goes with p, so D proportional to p keeps their change per jump the same at every p.
  double jump_depth_at(double pressure) const {
    return jump_reference_pressure > 0.0 ? jump_max_depth * pressure / jump_reference_pressure : jump_max_depth;
  }
  // [run]
  std::vector<std::string> launcher;  // run.launcher's words ({np} kept, a relative program resolved); empty: none
  // the contact table as the law's metadata and the samples' key record it (null at the defaults)
  nlohmann::json contact_json() const;
  // the registry's entry of `friction` (its capabilities)
  const tribo::SubModelInfo &friction_info() const;
  // the wear table as the law's metadata and the samples' key record it (null when the case has none)
  nlohmann::json wear_json() const;
};

// Reads and validates CASE (TOML, or JSON when it ends in .json); unknown keys, missing required keys and impossible
// values are InputError "<file>: key '<key>': <problem>" (exit 2).
// deck_given: --deck overrides the case's `deck`, which is then checked as text but not looked up.
HomogeniseCase read_homogenise_case(const std::string &path, bool deck_given = false);

// The j-th seed of every pressure (the same seeds at every pressure: common random numbers across the grid).
long derived_seed(long j);

// The value of `variable NAME <style> VALUE` in a deck's text (the first such line, comments stripped); empty if
// the deck has none. How a deck declares what it supports (height_source, accel_invariant).
std::string deck_variable(const std::string &deck_text, const std::string &name);

// The MPI launcher (--launcher, the case's run.launcher): its words, split at blanks without a shell, with the
// placeholder {np} where the number of ranks goes. Empty, a quote, backslash or '$', another placeholder or no {np}:
// InputError "<name>: <problem>".
std::vector<std::string> parse_launcher(const std::string &text, const std::string &name);
// The launcher's words with {np} replaced by `np`.
std::vector<std::string> expand_launcher(const std::vector<std::string> &words, int np);

std::string sha256_hex(const std::string &bytes);
std::string file_bytes(const std::filesystem::path &path);  // throws std::runtime_error naming the file

// What every sample shares besides its own (p, seed, acceleration).
struct CodeIdentity {
  std::string runin_version;  // PROJECT_VERSION
  std::string lmp_path, lmp_sha256;
  // the physics compiled into the LAMMPS executable: the first line of `<lmp>.physics` beside it (lmp_runin.physics,
  // written by the build from the SHA-256 of its physics sources, compiler and flags); empty when there is none,
  // and the samples are keyed on lmp_sha256 instead
  std::string physics_sha256;
};

// The physics identity recorded beside the LAMMPS executable `lmp` (`<lmp>.physics`): its first line, 64 hex digits;
// empty if the file does not exist. A file that exists but does not start with such a line is a runtime_error
// naming it.
std::string lmp_physics_identity(const std::filesystem::path &lmp);

struct Sample {
  std::size_t ip = 0, is = 0;  // pressure and seed indices
  double pressure = 0.0, acceleration = 1.0;
  long nside = 0;              // the cell's summits per side at this pressure
  long seed = 0;
  nlohmann::json inputs;  // canonical inputs (the key's preimage)
  std::string key;        // sha256 of inputs.dump()
  std::filesystem::path dir;
  std::filesystem::path output() const { return dir / "out.dat"; }
  std::filesystem::path log() const { return dir / "log.lammps"; }
  bool complete() const;
  std::string label() const;  // "p = 1e+06 Pa, seed 4711"
};

// One sample per (pressure, seed), pressure-major.
std::vector<Sample> plan_samples(const HomogeniseCase &c, const std::string &deck_text, const CodeIdentity &code,
                                 const std::filesystem::path &cache_dir);

}  // namespace runin::cli
