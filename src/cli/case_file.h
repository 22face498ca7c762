// Reading and validating a pin-on-disk case file (TOML).
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <set>
#include <string>
#include <vector>

#include "continuum/axisymmetric_contact.h"
#include "continuum/feedback_system.h"
#include "continuum/pin_on_disk.h"
#include "continuum/pin_state_law.h"
#include "tribo/contact.h"
#include "tribo/wear.h"
#include "coupling/friction_law.h"

namespace runin::cli {

// Bad input: the CLI prints "runin: error: <what()>" and exits with code 2.
// Case-file messages read "<file>: key 'section.key': <problem>".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// [contact] (Hertz tip on the flat disk, discretised face) and optional [wear] (Archard on the pin).
struct PinContactCase {
  // contact.tip: "sphere" (Hertz tip, elastic pressure solve on the rings) or "flat" (friction.model =
  // "state_law" only: a flat-ended pin of radius contact.flat_radius at the uniform nominal pressure
  // W / (pi a^2), which its uniform wear keeps uniform; the elastic edge concentration is not modelled).
  bool flat = false;
  double flat_radius = 0.0;                // m, contact.tip = "flat"
  double tip_radius = 0.0;                 // m
  tribo::Material pin, disk;               // E, nu (hardness of the pin from [wear]); S_y from `materials`
  std::string materials_path;              // contact.materials (.runin file), resolved; empty: none
  std::string pin_name, disk_name;         // contact.pin_material / disk_material in that file
  int rings = 256;
  std::optional<double> grid_radius;       // m; absent: sized from Hertz and the Archard volume
  std::optional<tribo::ArchardWear> wear;  // absent: contact only, no wear
  // wear.disk_k / disk_hardness: the disk's own Archard wear of its track (same wear.form); absent: not worn.
  std::optional<tribo::ArchardWear> disk_wear;
  std::string disk_hardness_origin;        // "wear.disk_hardness" or "<material> in <file>"
  double step_safety = 0.5;
  long max_wear_steps = 1000000;
  double effective_modulus() const { return tribo::effective_modulus(pin, disk); }
};

struct PinOnDiskCase {
  std::string path;
  std::string title;
  continuum::PinOnDiskParameters parameters;  // applied_torque resolved (eq. 4.11 if targeted)
  continuum::PinOnDiskRun run;
  std::optional<continuum::SlidingFriction> friction;
  std::string torque_origin;  // how applied_torque was obtained, for the summary
  std::optional<PinContactCase> contact;
  std::vector<double> vtk_times;    // [output] vtk_times, s (needs [contact])
  std::vector<double> sweep_mu0;    // [sweep] mu0: overlay runs with everything else fixed
  // eq. 4.11 target (V1, t1) when the torque was targeted; the sweep recomputes T per mu0.
  std::optional<std::pair<double, double>> torque_target;
  std::string friction_model;       // [friction] model
  // run.wear_steps = "adaptive" (state law, speed drive) with run.tolerance; default: one per output interval
  continuum::WearSteps wear_steps;
};

// The case with its static coefficient replaced by `mu0` (see friction_with_static_coefficient), and
// the torque re-derived from eq. 4.11 if it was targeted.
PinOnDiskCase with_mu0(const PinOnDiskCase &c, double mu0);

// One `material NAME E nu rho H [S_y]` line of a RunIn coefficient file (potentials/*.runin). Throws
// std::invalid_argument naming the file and line (or the missing material).
tribo::Material read_runin_material(const std::string &path, const std::string &name);

class CaseReader;
// [film] of an element on a state law (doc/surface_films.md, "In an element"): coverage, f_film or interface (a state
// of the law's material file), removal_distance, growth_rate, counterface_*; f_base and alpha from the law
// (samples.contact, a junction law); the law must have its contact_fraction field. Sets the state law's film; nothing
// without [film]. Bad input fails naming the key; so does a counterface_* key when `counterface_refusal` (the
// element's reason) is not empty.
void read_film(const CaseReader &reader, const continuum::SlidingFriction &friction,
               const std::string &counterface_refusal = {});
const std::set<std::string> &film_keys();

// A file named in a case file: an absolute path as given; a relative one against the case file's directory, else
// (when that does not exist and the source tree has it) against the RunIn source tree, the shipped potentials/
// and inputs/. Lexically normal; whether it exists is the caller's check.
std::filesystem::path resolve_case_path(const std::string &case_path, const std::string &file);

// A file a case names under `key`: an absolute path as given; a relative one beside the case file, else in the
// current directory, else in the RunIn source tree (its potentials/ and inputs/), the last two with a note on
// stdout naming the file read. None exists: fails naming the key and every path tried (exit 2).
std::filesystem::path find_case_file(const CaseReader &reader, const std::string &key, const std::string &file);

// friction.model = "state_law" with both bodies' materials named: the law's materials (StateLaw::materials)
// must be the same pair in the same order, its rough body the case's name_a (the body whose nodes carry h);
// otherwise fails naming both (exit 2). `law_path` is the --law option.
void check_law_materials(const CaseReader &reader, const continuum::SlidingFriction &friction,
                         const std::optional<std::string> &law_path, const std::string &key_a,
                         const std::string &name_a, const std::string &key_b, const std::string &name_b);

// Two materials named in a RunIn coefficient file, for the subsurface-stress yield verdict of the line contacts
// (journal bearing, piston ring): `<section>.materials` (the .runin file; relative: to the case file's
// directory, else to the RunIn source tree) with `<section>.<key_a>` and `<section>.<key_b>`. None of the three
// keys: nullopt (S_y unknown). A missing partner key or an unknown material fails naming its key (exit 2).
struct NamedMaterials {
  std::string path;                  // resolved
  std::string name_a, name_b;
  tribo::Material a, b;              // E, nu, H, S_y (0 if the file gives none) from the file

  // The yield verdict's strengths into the case's materials; their E and nu stay the case's (the contact model's).
  void copy_strengths(tribo::Material &to_a, tribo::Material &to_b) const {
    to_a.yield_strength = a.yield_strength, to_a.hardness = a.hardness;
    to_b.yield_strength = b.yield_strength, to_b.hardness = b.hardness;
  }
};
std::optional<NamedMaterials> read_named_materials(const CaseReader &reader, const std::string &case_path,
                                                   const std::string &section, const std::string &key_a,
                                                   const std::string &key_b);

// `friction` (of [friction] model `model`) with the static coefficient replaced by mu0, the thesis's
// one varied parameter: constant: mu0 (+ alpha V); static_kinetic: mu_static = mu0, mu_kinetic in the
// case's ratio; feedback: the same law started at the roughness R0 with mu(R0) = mu0
// (SlidingFriction::feedback_roughness_for). Throws std::invalid_argument otherwise (law_file) or if mu0
// is not above the feedback law's steady value.
continuum::SlidingFriction friction_with_static_coefficient(const continuum::SlidingFriction &friction,
                                                            const std::string &model, double mu0);

class CaseReader;
// The [friction] table shared by every machine-element case: model = "constant" | "static_kinetic" |
// "law_file" | "feedback" (+ alpha, speed_term = "strengthening" | "weakening" for mu0 +/- alpha V).
// `law_path` is the --law option.
continuum::SlidingFriction read_friction(const CaseReader &reader, const std::optional<std::string> &law_path);
// Every key read_friction may read, for a case's Schema entry "friction".
const std::set<std::string> &friction_keys();

// `law_path` is the --law option; required exactly when friction.model = "law_file".
PinOnDiskCase read_pin_on_disk_case(const std::string &path, const std::optional<std::string> &law_path);

// Feedback-model case (thesis ch. 3): [model] kind, C1, C2, K1, K2, A, B; [run] R0, t_end,
// output_interval; optional [solver]; optional [sweep] parameter + values; optional [fit], the provenance
// `runin fit-feedback` writes (not used by the run; its source and status are echoed).
struct FeedbackSweep {
  std::string parameter;  // one of feedback_sweep_parameters()
  std::vector<double> values;
};

struct FeedbackCase {
  std::string path;
  std::string title;
  tribo::FeedbackCoefficients coefficients;
  std::optional<tribo::FeedbackModel> model;  // always set after reading
  continuum::FeedbackRun run;
  std::optional<FeedbackSweep> sweep;  // every value already checked to give a valid model
  std::optional<std::string> fitted_from;  // [fit]: "source (sha256 ..., fit status)", when the case was fitted
};

FeedbackCase read_feedback_case(const std::string &path);
// Shortest run.t_end `runin feedback` integrates (and data span `runin fit-feedback` fits), s.
inline constexpr double kFeedbackMinTimeSpan = 1e-100;
const std::set<std::string> &feedback_sweep_parameters();  // A, B, C1, C2, K1, K2, R0
// Sets coefficient `name` in `c`, or `r0` for "R0".
void set_feedback_parameter(tribo::FeedbackCoefficients &c, double &r0, const std::string &name, double value);

}  // namespace runin::cli
