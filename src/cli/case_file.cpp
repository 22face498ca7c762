#include "cli/case_file.h"

#include "tribo/contact_model.h"
#include "tribo/material_file.h"
#include "cli/case_reader.h"

#include <cmath>
#include <filesystem>
#include <tuple>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>


namespace runin::cli {

const std::set<std::string> &friction_keys() {
  static const std::set<std::string> keys = {"model", "mu0", "mu_static", "mu_kinetic", "alpha", "speed_term",
                                             "distance_scale", "branch", "kind", "C1", "C2", "K1", "K2",
                                             "A", "B", "R0", "basis", "law", "out_of_range"};
  return keys;
}

const std::set<std::string> &film_keys() {
  static const std::set<std::string> keys = {"coverage", "f_film", "interface", "removal_distance", "growth_rate",
                                             "counterface_coverage", "counterface_removal_distance",
                                             "counterface_growth_rate"};
  return keys;
}

namespace {

using continuum::SlidingFriction;

// Allowed keys per table; "" is the top level.
const Schema kSchema = {
    {"", {"title", "pin", "loading", "friction", "run", "solver", "contact", "wear", "output", "sweep", "film"}},
    {"film", film_keys()},
    {"contact", {"tip", "flat_radius", "tip_radius", "pin_youngs_modulus", "pin_poisson_ratio", "disk_youngs_modulus",
                 "disk_poisson_ratio", "rings", "grid_radius", "materials", "pin_material", "disk_material"}},
    {"wear", {"k", "hardness", "form", "step_safety", "max_steps", "disk_k", "disk_hardness"}},
    {"output", {"vtk_times"}},
    {"pin", {"mass", "track_radius", "normal_load"}},
    {"loading", {"drive", "ramp_time", "applied_torque", "target_speed", "target_time", "sliding_speed"}},
    {"friction", friction_keys()},
    {"run", {"t_end", "output_interval", "initial_speed", "wear_steps", "tolerance"}},
    {"solver", {"method", "rtol", "atol", "max_steps"}},
    {"sweep", {"mu0"}},
};

const Schema kFeedbackSchema = {
    {"", {"title", "model", "run", "solver", "sweep", "fit"}},
    {"model", {"kind", "C1", "C2", "K1", "K2", "A", "B"}},
    {"run", {"R0", "t_end", "output_interval"}},
    {"solver", {"method", "rtol", "atol", "max_steps"}},
    {"sweep", {"parameter", "values"}},
    // written by `runin fit-feedback` (cmd_fit_feedback.cpp): provenance and residuals of the fit
    {"fit", {"source", "source_sha256", "t_column", "mu_column", "r_column", "t_scale", "r_scale", "t0", "points",
             "dropped_repeated_t", "status", "method", "R_star", "A_K1", "B_K2", "R_star_squared_std_error",
             "R0_squared_std_error", "A_K1_std_error", "C1_std_error", "C2_std_error", "C2_clamped", "R_max_rel_error",
             "R_rms_rel_error", "mu_max_rel_error", "mu_rms_rel_error", "mu_of_R_max_rel_error",
             "mu_of_R_rms_rel_error", "max_rms_rel_error", "comparison"}},
};

// Keys each friction model reads besides "model", "alpha" and "speed_term".
const std::map<std::string, std::set<std::string>> kModelKeys = {
    {"constant", {"mu0"}},
    {"static_kinetic", {"mu_static", "mu_kinetic"}},
    {"law_file", {"distance_scale", "branch"}},
    {"feedback", {"kind", "C1", "C2", "K1", "K2", "A", "B", "R0", "basis"}},
    {"state_law", {"law", "out_of_range", "mu_static"}},
};


}  // namespace

namespace {

// mu0 + alpha V (strengthening, default) or mu0 - alpha V (weakening, thesis eq. 4.5 with -).
double read_speed_coefficient(const CaseReader &reader) {
  double alpha = reader.number("friction.alpha", 0.0);
  if (reader.has("friction.speed_term")) {
    const bool weakening = reader.choice("friction.speed_term", {"strengthening", "weakening"}) == "weakening";
    if (alpha < 0.0) reader.fail("friction.alpha", "must be >= 0 when friction.speed_term is given, got " +
                                                       CaseReader::format(alpha));
    if (weakening) alpha = -alpha;
  }
  return alpha;
}

// The homogenised path: per-node mu(p, h) and dh/ds from a runin-state-law file. Relative paths: to the case file's
// directory, else to the RunIn source tree.
SlidingFriction read_state_law_friction(const CaseReader &reader, const std::optional<std::string> &law_path,
                                        double alpha) {
  auto state = std::make_shared<continuum::StateLawFriction>();
  // --law FILE (relative to the working directory) overrides friction.law
  const std::string file = law_path ? *law_path : reader.text("friction.law", "");
  if (file.empty())
    reader.fail("friction.law", "missing (required): the state law file (runin homogenise), or --law FILE");
  if (law_path) {
    state->path = std::filesystem::path(file).lexically_normal().string();
    if (!std::filesystem::exists(state->path)) throw InputError("--law: no such file: " + state->path);
  } else {
    state->path = find_case_file(reader, "friction.law", file).string();
  }
  try {
    state->law = std::make_shared<const coupling::StateLaw>(coupling::StateLaw::read_file(state->path));
  } catch (const coupling::InputFormatError &e) {
    reader.fail("friction.law", e.what());
  }
  const std::string policy =
      reader.choice("friction.out_of_range", {"error", "clamp", "archard"}, std::string("error"));
  state->policy = policy == "clamp"     ? coupling::OutOfRange::Clamp
                  : policy == "archard" ? coupling::OutOfRange::Archard
                                        : coupling::OutOfRange::Error;
  if (reader.has("friction.mu_static")) state->mu_static = reader.non_negative("friction.mu_static");
  return SlidingFriction::state_law(std::move(state), alpha);
}

// The law's material file, for an interface state named by `key`: its metadata material.file, found as a case file
// is (beside the case, the working directory, the source tree).
double law_interface_factor(const CaseReader &reader, const coupling::StateLaw &law, const std::string &key,
                            const std::string &state_name) {
  const auto pair = law.materials();
  const auto &material = law.metadata().value("material", nlohmann::json::object());
  if (!pair || !material.contains("file") || !material["file"].is_string())
    reader.fail(key, "the state law names no material file (metadata material.file): give film.f_film instead");
  const auto path = find_case_file(reader, key, material["file"].get<std::string>());
  try {
    std::ifstream in(path);
    const auto file = tribo::parse_material_file(in, path.string());
    const double m = file.pair(pair->first, pair->second)
                         .interface_factor[static_cast<std::size_t>(tribo::find_interface_state(state_name))];
    if (std::isnan(m))
      reader.fail(key, path.string() + " has no 'interface " + pair->first + " " + pair->second + " " + state_name +
                           " m' line");
    return m;
  } catch (const InputError &) {
    throw;
  } catch (const std::exception &e) {  // an unknown state, a malformed file
    reader.fail(key, e.what());
  }
}

}  // namespace

void read_film(const CaseReader &reader, const continuum::SlidingFriction &friction,
               const std::string &counterface_refusal) {
  if (!reader.has("film")) return;
  auto *state = friction.state_law();
  if (!state) reader.fail("film", "a surface film needs friction.model = \"state_law\" (the law's contact fraction)");
  const auto &law = *state->law;
  const auto samples = law.metadata().value("samples", nlohmann::json::object());
  const auto contact = samples.value("contact", nlohmann::json::object());
  // the film scales a law that takes the interface state's m as its f (the registry's laws of that use)
  std::string junction_laws;
  bool junction_law = false;
  for (const tribo::SubModelInfo &info : tribo::registered_sub_models(tribo::SubModelKind::friction))
    if (info.interface_use == tribo::InterfaceUse::interface_coefficient) {
      junction_laws += (junction_laws.empty() ? "" : " or ") + std::string(info.name);
      junction_law = junction_law || contact.value("friction", std::string()) == info.name;
    }
  if (!junction_law)
    reader.fail("film", "the state law " + state->path + " was not built with " + junction_laws + " friction (samples."
                        "contact.friction): the film scales the law's junctions by Tabor's closed form");
  if (!contact.contains("f") || !contact["f"].is_number() || !contact.contains("alpha") ||
      !contact["alpha"].is_number() || !law.has(coupling::StateField::ContactFraction))
    reader.fail("film", "the state law " + state->path + " was built before surface films (no samples.contact.f, "
                        "alpha or contact_fraction field): rebuild it with runin homogenise");
  continuum::FilmSettings f;
  f.f_base = contact["f"].get<double>();
  f.alpha = contact["alpha"].get<double>();
  f.coverage = reader.number("film.coverage", 1.0);
  if (reader.has("film.f_film") == reader.has("film.interface"))
    reader.fail("film.f_film", "give exactly one of film.f_film (a number) and film.interface (a state of the law's "
                               "material file: clean, oxidised, boundary)");
  f.f_film = reader.has("film.f_film")
                 ? reader.number("film.f_film")
                 : law_interface_factor(reader, law, "film.interface", reader.text("film.interface", ""));
  // a state of m = 1 (clean) is named by its key, not as the f_film it becomes
  if (reader.has("film.interface") && !(f.f_film < 1.0))
    reader.fail("film.interface", "state '" + reader.text("film.interface", "") + "' has m = " +
                                      CaseReader::format(f.f_film) + " in the law's material file: at m >= 1 a junction "
                                      "grows without bound (seizure); give a state with m < 1");
  f.removal_distance = reader.number("film.removal_distance", 0.0);
  f.growth_rate = reader.number("film.growth_rate", 0.0);
  bool counterface = false;
  for (const char *key : {"film.counterface_coverage", "film.counterface_removal_distance", "film.counterface_growth_rate"})
    if (reader.has(key)) {
      if (!counterface_refusal.empty()) reader.fail(key, counterface_refusal);
      counterface = true;
    }
  if (counterface) {
    continuum::CounterfaceFilm c;
    c.coverage = reader.number("film.counterface_coverage", 1.0);
    c.removal_distance = reader.number("film.counterface_removal_distance", 0.0);
    c.growth_rate = reader.number("film.counterface_growth_rate", 0.0);
    f.counterface = c;
  }
  try {
    f.validate();
  } catch (const std::invalid_argument &e) {  // "film.key: problem"
    const std::string what = e.what();
    const auto colon = what.find(": ");
    reader.fail(what.substr(0, colon), what.substr(colon + 2));
  }
  state->film = f;
}

namespace {

SlidingFriction read_feedback_friction(const CaseReader &reader, double alpha) {
  const auto kind = reader.choice("friction.kind", {"lubricated", "dry"}, std::string("dry")) == "dry"
                        ? tribo::FeedbackKind::dry
                        : tribo::FeedbackKind::lubricated;
  tribo::FeedbackCoefficients k;
  k.C1 = reader.positive("friction.C1");
  k.C2 = reader.non_negative("friction.C2");
  k.K1 = reader.positive("friction.K1");
  k.K2 = reader.positive("friction.K2");
  k.A = reader.positive("friction.A");
  k.B = reader.positive("friction.B");
  const double r0 = reader.positive("friction.R0");
  const bool per_distance = reader.choice("friction.basis", {"distance", "time"}, std::string("distance")) == "distance";
  try {
    return SlidingFriction::feedback(tribo::FeedbackModel(k, kind), r0, per_distance, alpha);
  } catch (const tribo::InvalidCoefficient &e) {
    reader.fail("friction", e.what());
  }
}

SlidingFriction read_law_file_friction(const CaseReader &reader, const std::optional<std::string> &law_path,
                                       double alpha) {
  if (!law_path) reader.fail("friction.model", "is 'law_file' but no --law FILE was given");
  const double distance_scale = reader.positive("friction.distance_scale");
  const auto branch = reader.choice("friction.branch", {"fit", "table"}, std::string("fit")) == "fit"
                          ? coupling::FrictionLaw::Branch::Fit
                          : coupling::FrictionLaw::Branch::Table;
  coupling::FrictionLaw law = [&] {
    try {
      return coupling::read_law_file(*law_path);
    } catch (const coupling::InputFormatError &e) {
      throw InputError(e.what());
    }
  }();
  return SlidingFriction::from_law(law, branch, distance_scale, alpha);
}

}  // namespace

continuum::SlidingFriction read_friction(const CaseReader &reader, const std::optional<std::string> &law_path) {
  const std::string model =
      reader.choice("friction.model", {"constant", "static_kinetic", "law_file", "feedback", "state_law"});
  for (const auto &[other, keys] : kModelKeys)
    if (other != model)
      for (const auto &key : keys)
        if (reader.has("friction." + key) && !kModelKeys.at(model).count(key))
          reader.fail("friction." + key, "not used by model '" + model + "'");
  const double alpha = read_speed_coefficient(reader);
  if (law_path && model != "law_file" && model != "state_law")
    reader.fail("friction.model", "is '" + model + "' but --law was given");

  try {
    if (model == "constant") return SlidingFriction::constant(reader.non_negative("friction.mu0"), alpha);
    if (model == "static_kinetic") {
      const double mu_static = reader.non_negative("friction.mu_static");
      const double mu_kinetic = reader.non_negative("friction.mu_kinetic");
      if (mu_kinetic > mu_static) reader.fail("friction.mu_kinetic", "must not exceed friction.mu_static");
      return SlidingFriction::static_kinetic(mu_static, mu_kinetic, alpha);
    }
    if (model == "state_law") return read_state_law_friction(reader, law_path, alpha);
    if (model == "feedback") return read_feedback_friction(reader, alpha);
    return read_law_file_friction(reader, law_path, alpha);
  } catch (const std::invalid_argument &e) {
    reader.fail("friction", e.what());
  }
}

std::filesystem::path find_case_file(const CaseReader &reader, const std::string &key, const std::string &file) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path named(file);
  if (named.is_absolute()) {
    if (!fs::is_regular_file(named, error)) reader.fail(key, "no such file: " + file);
    return named.lexically_normal();
  }
  std::vector<fs::path> tried = {(fs::path(reader.path()).parent_path() / named).lexically_normal(),
                                 (fs::current_path(error) / named).lexically_normal()};
#ifdef RUNIN_SOURCE_DIR
  tried.push_back((fs::path(RUNIN_SOURCE_DIR) / named).lexically_normal());
#endif
  std::string list;
  for (std::size_t i = 0; i < tried.size(); ++i) {
    if (fs::is_regular_file(tried[i], error)) {
      if (i > 0)
        std::cout << "runin: note: " << reader.path() << ": key '" << key << "': '" << file
                  << "' is not beside the case file; read " << fs::absolute(tried[i]).lexically_normal().string()
                  << (i == 1 ? " (current directory)" : " (RunIn source tree)") << "\n";
      return tried[i];
    }
    list += (list.empty() ? "" : ", ") + tried[i].string();
  }
  reader.fail(key, "no such file '" + file + "' (tried " + list + ")");
}

void check_law_materials(const CaseReader &reader, const continuum::SlidingFriction &friction,
                         const std::optional<std::string> &law_path, const std::string &key_a,
                         const std::string &name_a, const std::string &key_b, const std::string &name_b) {
  const auto *state = friction.state_law();
  if (!state || !state->law || name_a.empty() || name_b.empty()) return;
  const auto law = state->law->materials();
  if (!law) return;
  // the law's rough body is the one whose nodes carry h (name_a): the order matters for unlike bodies
  if (law->first == name_a && law->second == name_b) return;
  const bool swapped = law->first == name_b && law->second == name_a;
  const std::string problem = "the state law " + state->path + " is for " + law->first + " on " + law->second +
                              " (its material.rough, material.counterface), the case's bodies are " + name_a + " (" +
                              key_a + ") and " + name_b + " (" + key_b + ")" +
                              (swapped ? ", the other way round: the law's rough body must be the case's " + key_a
                                       : std::string()) +
                              ": use a law homogenised for these materials (runin homogenise)";
  if (law_path) throw InputError(reader.path() + ": --law: " + problem);
  reader.fail("friction.law", problem);
}

std::filesystem::path resolve_case_path(const std::string &case_path, const std::string &file) {
  std::filesystem::path resolved(file);
  if (resolved.is_relative()) {
    resolved = std::filesystem::path(case_path).parent_path() / file;
#ifdef RUNIN_SOURCE_DIR
    if (!std::filesystem::exists(resolved) && std::filesystem::exists(std::filesystem::path(RUNIN_SOURCE_DIR) / file))
      resolved = std::filesystem::path(RUNIN_SOURCE_DIR) / file;
#endif
  }
  return resolved.lexically_normal();
}

std::optional<NamedMaterials> read_named_materials(const CaseReader &reader, const std::string &case_path,
                                                   const std::string &section, const std::string &key_a,
                                                   const std::string &key_b) {
  const std::string file_key = section + ".materials", a_key = section + "." + key_a, b_key = section + "." + key_b;
  if (!reader.has(file_key) && !reader.has(a_key) && !reader.has(b_key)) return std::nullopt;
  NamedMaterials m;
  const std::string file = reader.text(file_key, "");
  if (file.empty()) reader.fail(file_key, "needed with " + a_key + " / " + b_key);
  (void)case_path;
  m.path = find_case_file(reader, file_key, file).string();
  m.name_a = reader.text(a_key, "");
  m.name_b = reader.text(b_key, "");
  if (m.name_a.empty()) reader.fail(a_key, "needed with " + file_key);
  if (m.name_b.empty()) reader.fail(b_key, "needed with " + file_key);
  for (const auto &[key, name, out] : {std::make_tuple(a_key, m.name_a, &m.a), std::make_tuple(b_key, m.name_b, &m.b)}) {
    try {
      *out = read_runin_material(m.path, name);
    } catch (const std::invalid_argument &e) {
      reader.fail(key, e.what());
    }
  }
  return m;
}

tribo::Material read_runin_material(const std::string &path, const std::string &name) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("cannot open " + path);
  try {
    return tribo::parse_material_file(in, path).material(name);
  } catch (const std::exception &e) {  // MaterialFileError, InvalidCoefficient: both name the file
    throw std::invalid_argument(e.what());
  }
}

namespace {

// [loading]: the speed drive, or the torque drive with its torque given or from eq. 4.11; returns whether the torque
// was targeted (target_speed + target_time).
bool read_loading(const CaseReader &reader, PinOnDiskCase &c) {
  auto &p = c.parameters;
  const bool speed_drive = reader.choice("loading.drive", {"torque", "speed"}, std::string("torque")) == "speed";
  const bool explicit_torque = reader.has("loading.applied_torque");
  const bool targeted = reader.has("loading.target_speed") || reader.has("loading.target_time");
  if (speed_drive) {
    for (const char *key : {"loading.applied_torque", "loading.target_speed", "loading.target_time"})
      if (reader.has(key)) reader.fail(key, "not used by loading.drive = \"speed\" (give loading.sliding_speed)");
    p.drive = continuum::PinDrive::Speed;
    p.sliding_speed = reader.positive("loading.sliding_speed");
    c.torque_origin = "speed drive: V ramps to " + CaseReader::format(p.sliding_speed) + " m/s, T_app = T_f + J dw/dt";
  } else if (reader.has("loading.sliding_speed")) {
    reader.fail("loading.sliding_speed", "needs loading.drive = \"speed\"");
  }
  if (!speed_drive && explicit_torque && targeted)
    reader.fail("loading.applied_torque", "give either applied_torque or target_speed + target_time, not both");
  if (speed_drive) return targeted;  // the drive sets V(t); its torque is an output
  if (explicit_torque) {
    p.applied_torque = reader.positive("loading.applied_torque");
    c.torque_origin = "from the case file";
    return targeted;
  }
  if (!targeted) reader.fail("loading.applied_torque", "missing (or give target_speed + target_time)");
  const double v1 = reader.positive("loading.target_speed");
  const double t1 = reader.positive("loading.target_time");
  if (c.friction->speed_coefficient() < 0.0)
    reader.fail("loading.target_speed",
                "eq. 4.11 with velocity weakening puts T_app at the static limit to within exp(-|alpha| W t1 / m); "
                "give loading.applied_torque instead");
  // Eq. 4.11 from rest with mu0 = the static coefficient (the thesis's mu0).
  p.applied_torque = continuum::thesis_torque_for_speed(p, c.friction->static_coefficient(),
                                                        c.friction->speed_coefficient(), 0.0, v1, t1);
  if (!(p.applied_torque > 0.0)) reader.fail("loading.target_speed", "eq. 4.11 gives a non-positive torque");
  c.torque_origin = "eq. 4.11: V = " + CaseReader::format(v1) + " m/s at t = " + CaseReader::format(t1) +
                    " s from rest under constant torque";
  return targeted;
}

void read_pin_run(const CaseReader &reader, continuum::PinOnDiskRun &run) {
  run.t_end = reader.positive("run.t_end");
  run.output_interval = reader.positive("run.output_interval", 1e-3);
  if (run.t_end / run.output_interval > 1e7) reader.fail("run.output_interval", "gives more than 1e7 samples");
  run.initial_speed = reader.number("run.initial_speed", 0.0);
  continuum::CvodeIntegrator::Settings defaults;
  defaults.rtol = 1e-8;
  defaults.atol = 1e-10;
  defaults.max_steps = 100000;
  run.integrator = read_solver(reader, defaults);
}

// Yield strengths (and E, nu unless given in [contact]) from a RunIn coefficient file, for the subsurface stress
// verdict (doc/subsurface_stress.md).
void read_contact_materials(const CaseReader &reader, PinContactCase &k) {
  const std::string file = reader.text("contact.materials", "");
  if (file.empty()) reader.fail("contact.materials", "needed with contact.pin_material / disk_material");
  k.materials_path = find_case_file(reader, "contact.materials", file).string();
  k.pin_name = reader.text("contact.pin_material", "");
  k.disk_name = reader.text("contact.disk_material", "");
  if (k.pin_name.empty() || k.disk_name.empty())
    reader.fail("contact.materials", "needs both contact.pin_material and contact.disk_material");
  try {
    const tribo::Material pin = read_runin_material(k.materials_path, k.pin_name);
    const tribo::Material disk = read_runin_material(k.materials_path, k.disk_name);
    if (!reader.has("contact.pin_youngs_modulus")) k.pin.youngs_modulus = pin.youngs_modulus;
    if (!reader.has("contact.pin_poisson_ratio")) k.pin.poisson_ratio = pin.poisson_ratio;
    if (!reader.has("contact.disk_youngs_modulus")) k.disk.youngs_modulus = disk.youngs_modulus;
    if (!reader.has("contact.disk_poisson_ratio")) k.disk.poisson_ratio = disk.poisson_ratio;
    k.pin.yield_strength = pin.yield_strength;
    k.disk.yield_strength = disk.yield_strength;
    k.pin.hardness = pin.hardness;
    k.disk.hardness = disk.hardness;
  } catch (const std::invalid_argument &e) {
    reader.fail("contact.materials", e.what());
  }
}

// [contact] without [wear]: the tip (sphere or flat end), the materials, the rings.
PinContactCase read_pin_contact(const CaseReader &reader, bool state_law) {
  PinContactCase k;
  k.flat = reader.choice("contact.tip", {"sphere", "flat"}, std::string("sphere")) == "flat";
  if (k.flat) {
    if (!state_law) reader.fail("contact.tip", "'flat' needs friction.model = \"state_law\"");
    if (reader.has("contact.tip_radius")) reader.fail("contact.tip_radius", "not used by contact.tip = \"flat\"");
    k.flat_radius = reader.positive("contact.flat_radius");
    k.tip_radius = k.flat_radius;  // only names a size below
  } else {
    if (reader.has("contact.flat_radius")) reader.fail("contact.flat_radius", "needs contact.tip = \"flat\"");
    k.tip_radius = reader.positive("contact.tip_radius");
  }
  // Thesis ch. 4: Cu pin E = 110 GPa, nu = 0.37; Al disk E = 69 GPa, nu = 0.33.
  k.pin.youngs_modulus = reader.positive("contact.pin_youngs_modulus", 110e9);
  k.pin.poisson_ratio = reader.non_negative("contact.pin_poisson_ratio", 0.37);
  k.disk.youngs_modulus = reader.positive("contact.disk_youngs_modulus", 69e9);
  k.disk.poisson_ratio = reader.non_negative("contact.disk_poisson_ratio", 0.33);
  if (reader.has("contact.materials") || reader.has("contact.pin_material") || reader.has("contact.disk_material"))
    read_contact_materials(reader, k);
  for (const char *key : {"contact.pin_poisson_ratio", "contact.disk_poisson_ratio"})
    if (reader.number(key, 0.0) >= 0.5) reader.fail(key, "must be < 0.5");
  const long rings = reader.positive_integer("contact.rings", 256);
  if (rings < 8 || rings > 4096) reader.fail("contact.rings", "must be in [8, 4096], got " + std::to_string(rings));
  k.rings = static_cast<int>(rings);
  if (reader.has("contact.grid_radius")) k.grid_radius = reader.positive("contact.grid_radius");
  return k;
}

// The disk's own Archard wear of its track (opt-in: without wear.disk_k the disk is not worn). H_d defaults to the
// disk material's hardness in contact.materials.
void read_disk_wear(const CaseReader &reader, PinContactCase &k, tribo::ArchardForm form) {
  if (reader.has("wear.disk_hardness") && !reader.has("wear.disk_k"))
    reader.fail("wear.disk_hardness", "needs wear.disk_k (the disk's wear coefficient)");
  if (!reader.has("wear.disk_k")) return;
  const double disk_k = reader.non_negative("wear.disk_k");
  double disk_hardness = 0.0;
  if (reader.has("wear.disk_hardness")) {
    disk_hardness = reader.positive("wear.disk_hardness");
    k.disk_hardness_origin = "wear.disk_hardness";
  } else if (k.disk.hardness > 0.0) {
    disk_hardness = k.disk.hardness;
    k.disk_hardness_origin = k.disk_name + " in " + k.materials_path;
  } else {
    reader.fail("wear.disk_hardness", "missing (or name the disk's material with contact.materials and "
                                      "contact.disk_material)");
  }
  k.disk_wear.emplace(disk_k, disk_hardness, form);
}

// [wear]: the state law's own (its wear_rate wears the pin, its counterface_wear_rate the disk), or Archard's.
void read_pin_wear(const CaseReader &reader, PinContactCase &k, bool state_law) {
  if (state_law) {
    for (const char *key : {"wear.k", "wear.hardness", "wear.form", "wear.disk_k", "wear.disk_hardness"})
      if (reader.has(key))
        reader.fail(key, "not used with friction.model = \"state_law\" (the law's wear_rate wears the pin, its "
                         "counterface_wear_rate the disk)");
  } else {
    const double coefficient = reader.non_negative("wear.k");
    const double hardness = reader.positive("wear.hardness");
    const auto form = reader.choice("wear.form", {"plain", "thesis"}, std::string("plain")) == "thesis"
                          ? tribo::ArchardForm::thesis
                          : tribo::ArchardForm::plain;
    k.wear.emplace(coefficient, hardness, form);
    read_disk_wear(reader, k, form);
  }
  k.step_safety = reader.positive("wear.step_safety", 0.5);
  if (k.step_safety > 1.0) reader.fail("wear.step_safety", "must be <= 1 (fraction of the stability bound)");
  k.max_wear_steps = reader.positive_integer("wear.max_steps", 1000000);
}

// run.wear_steps: "fixed" (a slow step per output interval) or "adaptive" (doc/state_law_continuum.md).
void read_wear_steps(const CaseReader &reader, PinOnDiskCase &c, bool state_law) {
  const bool adaptive = reader.choice("run.wear_steps", {"fixed", "adaptive"}, std::string("fixed")) == "adaptive";
  if (!adaptive) {
    if (reader.has("run.tolerance")) reader.fail("run.tolerance", "needs run.wear_steps = \"adaptive\"");
    return;
  }
  if (!state_law) reader.fail("run.wear_steps", "\"adaptive\" needs friction.model = \"state_law\"");
  if (c.parameters.drive != continuum::PinDrive::Speed && !(c.friction->speed_coefficient() > 0.0))
    reader.fail("run.wear_steps", "\"adaptive\" under the torque drive needs friction.alpha > 0 (steady sliding at "
                                  "V_ss = (T / r - mu W) / (alpha W)); without it use \"fixed\" or the speed drive");
  c.wear_steps.adaptive = true;
  c.wear_steps.tolerance = reader.positive_at_most("run.tolerance", 0.1, 1e-3);
}

void read_pin_sweep(const CaseReader &reader, PinOnDiskCase &c, bool state_law) {
  if (state_law) reader.fail("sweep.mu0", "not available with friction.model = \"state_law\" (mu_static is the law's)");
  if (c.friction_model == "law_file")
    reader.fail("sweep.mu0", "needs friction.model 'constant', 'static_kinetic' or 'feedback'");
  c.sweep_mu0 = reader.numbers_at_most("sweep.mu0", CaseReader::kMaxSweepValues);
  const bool speed_drive = c.parameters.drive == continuum::PinDrive::Speed;
  for (std::size_t i = 0; i < c.sweep_mu0.size(); ++i) {
    if (c.sweep_mu0[i] < 0.0) reader.fail("sweep.mu0", "element " + std::to_string(i) + ": must be >= 0");
    try {
      friction_with_static_coefficient(*c.friction, c.friction_model, c.sweep_mu0[i]);
    } catch (const std::invalid_argument &e) {
      reader.fail("sweep.mu0", "element " + std::to_string(i) + ": " + e.what());
    }
    if (!speed_drive && !(with_mu0(c, c.sweep_mu0[i]).parameters.applied_torque > 0.0))
      reader.fail("sweep.mu0", "element " + std::to_string(i) + ": eq. 4.11 gives a non-positive torque");
  }
}

}  // namespace

PinOnDiskCase read_pin_on_disk_case(const std::string &path, const std::optional<std::string> &law_path) {
  const CaseReader reader(path, parse_toml(path), kSchema);
  reader.reject_unknown_keys();

  PinOnDiskCase c;
  c.path = path;
  c.title = reader.text("title", path);
  auto &p = c.parameters;
  p.mass = reader.positive_at_most("pin.mass", 1e3);  // kg; above it eq. 4.11's torque overflows long before
  p.track_radius = reader.positive("pin.track_radius");
  p.normal_load = reader.positive("pin.normal_load");
  p.ramp_time = reader.non_negative("loading.ramp_time", 2.0);
  c.friction = read_friction(reader, law_path);
  const bool targeted = read_loading(reader, c);
  read_pin_run(reader, c.run);

  c.friction_model = reader.text("friction.model", "");
  if (targeted) c.torque_target = std::make_pair(reader.number("loading.target_speed"), reader.number("loading.target_time"));
  if (reader.has("wear") && !reader.has("contact")) reader.fail("wear", "needs a [contact] table (tip geometry)");
  const bool state_law = c.friction->state_law() != nullptr;
  if (state_law && !reader.has("contact"))
    reader.fail("friction.model", "'state_law' needs a [contact] table (the per-node pressures)");
  if (reader.has("contact")) {
    PinContactCase k = read_pin_contact(reader, state_law);
    if (reader.has("wear")) read_pin_wear(reader, k, state_law);
    c.contact = k;
    // the state law reads the flat end's nominal pressure: finite, or the key that overflows it
    const double area = M_PI * k.flat_radius * k.flat_radius;
    if (k.flat && !(area > 0.0))
      reader.fail("contact.flat_radius", "the flat end's area pi a^2 underflows to 0 m^2 at a = " +
                                             CaseReader::format(k.flat_radius) + " m");
    if (k.flat && !std::isfinite(p.normal_load / area))
      reader.fail("pin.normal_load", "the nominal pressure W / (pi contact.flat_radius^2) overflows at W = " +
                                         CaseReader::format(p.normal_load) + " N, a = " +
                                         CaseReader::format(k.flat_radius) + " m");
    check_law_materials(reader, *c.friction, law_path, "contact.pin_material", k.pin_name, "contact.disk_material",
                        k.disk_name);
  }
  if (reader.has("output.vtk_times")) {
    if (!c.contact) reader.fail("output.vtk_times", "needs a [contact] table");
    c.vtk_times = reader.times_within("output.vtk_times", c.run.t_end);
    if (c.vtk_times.size() > 100) reader.fail("output.vtk_times", "more than 100 frames");
  }
  if (reader.has("sweep")) read_pin_sweep(reader, c, state_law);
  read_wear_steps(reader, c, state_law);
  c.wear_steps.stop_times = c.vtk_times;
  read_film(reader, *c.friction);
  return c;
}

continuum::SlidingFriction friction_with_static_coefficient(const continuum::SlidingFriction &friction,
                                                            const std::string &model, double mu0) {
  const double alpha = friction.speed_coefficient();
  if (model == "constant") return SlidingFriction::constant(mu0, alpha);
  if (model == "static_kinetic") {
    const double mu_s = friction.static_coefficient();
    const double ratio = mu_s > 0.0 ? friction.kinetic(0.0, 0.0) / mu_s : 1.0;
    return SlidingFriction::static_kinetic(mu0, ratio * mu0, alpha);
  }
  if (model == "feedback" && friction.feedback_model()) {
    const auto &law = *friction.feedback_model();
    return SlidingFriction::feedback(law, SlidingFriction::feedback_roughness_for(law, mu0),
                                     friction.state_per_distance(), alpha);
  }
  throw std::invalid_argument("a mu0 sweep needs friction model constant, static_kinetic or feedback");
}

PinOnDiskCase with_mu0(const PinOnDiskCase &c, double mu0) {
  PinOnDiskCase out = c;
  const double alpha = c.friction->speed_coefficient();
  out.friction = friction_with_static_coefficient(*c.friction, c.friction_model, mu0);
  if (c.torque_target)
    out.parameters.applied_torque = continuum::thesis_torque_for_speed(
        out.parameters, mu0, alpha, 0.0, c.torque_target->first, c.torque_target->second);
  return out;
}

namespace {
tribo::FeedbackModel build_model(const CaseReader &reader, const tribo::FeedbackCoefficients &c, tribo::FeedbackKind kind,
                                 const std::string &key) {
  try {
    return tribo::FeedbackModel(c, kind);
  } catch (const tribo::InvalidCoefficient &e) {
    reader.fail(key, e.what());
  }
}
}  // namespace

const std::set<std::string> &feedback_sweep_parameters() {
  static const std::set<std::string> names = {"A", "B", "C1", "C2", "K1", "K2", "R0"};
  return names;
}

void set_feedback_parameter(tribo::FeedbackCoefficients &c, double &r0, const std::string &name, double value) {
  if (name == "C1") c.C1 = value;
  else if (name == "C2") c.C2 = value;
  else if (name == "K1") c.K1 = value;
  else if (name == "K2") c.K2 = value;
  else if (name == "A") c.A = value;
  else if (name == "B") c.B = value;
  else if (name == "R0") r0 = value;
  else throw std::invalid_argument("unknown feedback parameter " + name);
}

FeedbackCase read_feedback_case(const std::string &path) {
  const CaseReader reader(path, parse_toml(path), kFeedbackSchema);
  reader.reject_unknown_keys();

  FeedbackCase c;
  c.path = path;
  c.title = reader.text("title", path);
  const auto kind = reader.choice("model.kind", {"lubricated", "dry"}) == "dry" ? tribo::FeedbackKind::dry
                                                                               : tribo::FeedbackKind::lubricated;
  auto &k = c.coefficients;
  k.C1 = reader.positive("model.C1");
  k.C2 = reader.non_negative("model.C2");
  k.K1 = reader.positive("model.K1");
  k.K2 = reader.positive("model.K2");
  k.A = reader.positive("model.A");
  k.B = reader.positive("model.B");
  c.model.emplace(build_model(reader, k, kind, "model"));

  auto &run = c.run;
  run.initial_roughness = reader.positive("run.R0");
  run.t_end = reader.positive("run.t_end");
  if (run.t_end < kFeedbackMinTimeSpan)   // CVODE stopped with "tstop is behind current t" at 1e-197 s
    reader.fail("run.t_end", "must be at least " + CaseReader::format(kFeedbackMinTimeSpan) +
                                 " s (below, the integrator's step control underflows: take t in larger units), got " +
                                 CaseReader::format(run.t_end));
  run.output_interval = reader.positive("run.output_interval", run.t_end / 1000.0);
  if (run.t_end / run.output_interval > 1e7) reader.fail("run.output_interval", "gives more than 1e7 samples");
  run.integrator = read_solver(reader, continuum::FeedbackRun::default_settings());

  if (reader.has("sweep")) {
    FeedbackSweep sweep;
    sweep.parameter = reader.choice("sweep.parameter", feedback_sweep_parameters());
    sweep.values = reader.numbers("sweep.values");
    if (sweep.values.size() > 50) reader.fail("sweep.values", "more than 50 values");
    for (std::size_t i = 0; i < sweep.values.size(); ++i) {
      auto coefficients = k;
      double r0 = run.initial_roughness;
      set_feedback_parameter(coefficients, r0, sweep.parameter, sweep.values[i]);
      const std::string where = "element " + std::to_string(i) + " (" + sweep.parameter + " = " +
                                CaseReader::format(sweep.values[i]) + "): ";
      if (!(r0 > 0.0)) reader.fail("sweep.values", where + "R0 must be positive");
      try {
        tribo::FeedbackModel(coefficients, kind);
      } catch (const tribo::InvalidCoefficient &e) {
        reader.fail("sweep.values", where + e.what());
      }
    }
    c.sweep = sweep;
  }
  if (reader.has("fit"))
    c.fitted_from = reader.text("fit.source", "?") + " (sha256 " + reader.text("fit.source_sha256", "?") +
                    ", fit " + reader.text("fit.status", "?") + ")";
  return c;
}

}  // namespace runin::cli
