#include "cli/case_file.h"

#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <toml++/toml.h>

namespace runin::cli {
namespace {

using continuum::SlidingFriction;

// Allowed keys per table; "" is the top level.
using Schema = std::map<std::string, std::set<std::string>>;
const Schema kSchema = {
    {"", {"title", "pin", "loading", "friction", "run", "solver"}},
    {"pin", {"mass", "track_radius", "normal_load"}},
    {"loading", {"ramp_time", "applied_torque", "target_speed", "target_time"}},
    {"friction", {"model", "mu0", "mu_static", "mu_kinetic", "alpha", "distance_scale", "branch"}},
    {"run", {"t_end", "output_interval", "initial_speed"}},
    {"solver", {"method", "rtol", "atol", "max_steps"}},
};

const Schema kFeedbackSchema = {
    {"", {"title", "model", "run", "solver", "sweep"}},
    {"model", {"kind", "C1", "C2", "K1", "K2", "A", "B"}},
    {"run", {"R0", "t_end", "output_interval"}},
    {"solver", {"method", "rtol", "atol", "max_steps"}},
    {"sweep", {"parameter", "values"}},
};

// Keys each friction model reads besides "model" and "alpha".
const std::map<std::string, std::set<std::string>> kModelKeys = {
    {"constant", {"mu0"}},
    {"static_kinetic", {"mu_static", "mu_kinetic"}},
    {"law_file", {"distance_scale", "branch"}},
};

std::string type_name(const toml::node &node) {
  std::ostringstream out;
  out << node.type();
  return out.str();
}

// Typed, checked access to the parsed document; every error names file and key.
class CaseReader {
 public:
  CaseReader(std::string path, toml::table root, const Schema &schema = kSchema)
      : path_(std::move(path)), root_(std::move(root)), schema_(schema) {}

  [[noreturn]] void fail(const std::string &key, const std::string &problem) const {
    throw InputError(path_ + ": key '" + key + "': " + problem);
  }

  void reject_unknown_keys() const {
    for (const auto &[key, node] : root_) {
      const std::string name(key.str());
      if (!schema_.at("").count(name)) fail(name, "unknown key");
      if (name == "title") continue;
      const auto *table = node.as_table();
      if (!table) fail(name, "expected a table, got " + type_name(node));
      for (const auto &[sub, ignored] : *table) {
        (void)ignored;
        if (!schema_.at(name).count(std::string(sub.str()))) fail(name + "." + std::string(sub.str()), "unknown key");
      }
    }
  }

  bool has(const std::string &key) const { return static_cast<bool>(root_.at_path(key)); }

  double number(const std::string &key, std::optional<double> fallback = std::nullopt) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing (required)");
    }
    if (!node->is_number()) fail(key, "expected a number, got " + type_name(*node));
    const double value = *node->value<double>();
    if (!std::isfinite(value)) fail(key, "must be finite");
    return value;
  }
  double positive(const std::string &key, std::optional<double> fallback = std::nullopt) const {
    const double value = number(key, fallback);
    if (!(value > 0.0)) fail(key, "must be positive, got " + format(value));
    return value;
  }
  double non_negative(const std::string &key, std::optional<double> fallback = std::nullopt) const {
    const double value = number(key, fallback);
    if (value < 0.0) fail(key, "must be >= 0, got " + format(value));
    return value;
  }
  long positive_integer(const std::string &key, long fallback) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) return fallback;
    if (!node->is_integer()) fail(key, "expected an integer, got " + type_name(*node));
    const long value = static_cast<long>(*node->value<int64_t>());
    if (value <= 0) fail(key, "must be positive, got " + std::to_string(value));
    return value;
  }
  std::string choice(const std::string &key, const std::set<std::string> &options,
                     std::optional<std::string> fallback = std::nullopt) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) {
      if (fallback) return *fallback;
      fail(key, "missing (required)");
    }
    if (!node->is_string()) fail(key, "expected a string, got " + type_name(*node));
    const std::string value = *node->value<std::string>();
    if (!options.count(value)) {
      std::string list;
      for (const auto &o : options) list += (list.empty() ? "" : ", ") + o;
      fail(key, "'" + value + "' is not one of " + list);
    }
    return value;
  }
  // Non-empty array of numbers.
  std::vector<double> numbers(const std::string &key) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) fail(key, "missing (required)");
    const auto *array = node->as_array();
    if (!array) fail(key, "expected an array of numbers, got " + type_name(*node));
    if (array->empty()) fail(key, "must not be empty");
    std::vector<double> values;
    for (const auto &element : *array) {
      if (!element.is_number())
        fail(key, "element " + std::to_string(values.size()) + ": expected a number, got " + type_name(element));
      values.push_back(*element.value<double>());
      if (!std::isfinite(values.back())) fail(key, "element " + std::to_string(values.size() - 1) + ": must be finite");
    }
    return values;
  }
  std::string text(const std::string &key, const std::string &fallback) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) return fallback;
    if (!node->is_string()) fail(key, "expected a string, got " + type_name(*node));
    return *node->value<std::string>();
  }

  static std::string format(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
  }

 private:
  std::string path_;
  toml::table root_;
  const Schema &schema_;
};

toml::table parse_toml(const std::string &path) {
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error &e) {
    std::string description(e.description());
    for (char &c : description)
      if (c == '\n') c = ' ';
    const auto &where = e.source().begin;
    if (where.line == 0) throw InputError(path + ": " + description);  // e.g. file not readable
    throw InputError(path + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                     ": invalid TOML: " + description);
  }
}

SlidingFriction read_friction(const CaseReader &reader, const std::optional<std::string> &law_path) {
  const std::string model = reader.choice("friction.model", {"constant", "static_kinetic", "law_file"});
  for (const auto &[other, keys] : kModelKeys)
    if (other != model)
      for (const auto &key : keys)
        if (reader.has("friction." + key)) reader.fail("friction." + key, "not used by model '" + model + "'");
  const double alpha = reader.number("friction.alpha", 0.0);
  if (law_path && model != "law_file") reader.fail("friction.model", "is '" + model + "' but --law was given");

  try {
    if (model == "constant") return SlidingFriction::constant(reader.non_negative("friction.mu0"), alpha);
    if (model == "static_kinetic") {
      const double mu_static = reader.non_negative("friction.mu_static");
      const double mu_kinetic = reader.non_negative("friction.mu_kinetic");
      if (mu_kinetic > mu_static) reader.fail("friction.mu_kinetic", "must not exceed friction.mu_static");
      return SlidingFriction::static_kinetic(mu_static, mu_kinetic, alpha);
    }
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
  } catch (const std::invalid_argument &e) {
    reader.fail("friction", e.what());
  }
}

}  // namespace

PinOnDiskCase read_pin_on_disk_case(const std::string &path, const std::optional<std::string> &law_path) {
  const CaseReader reader(path, parse_toml(path));
  reader.reject_unknown_keys();

  PinOnDiskCase c;
  c.path = path;
  c.title = reader.text("title", path);
  auto &p = c.parameters;
  p.mass = reader.positive("pin.mass");
  p.track_radius = reader.positive("pin.track_radius");
  p.normal_load = reader.positive("pin.normal_load");
  p.ramp_time = reader.non_negative("loading.ramp_time", 2.0);
  c.friction = read_friction(reader, law_path);

  const bool explicit_torque = reader.has("loading.applied_torque");
  const bool targeted = reader.has("loading.target_speed") || reader.has("loading.target_time");
  if (explicit_torque && targeted)
    reader.fail("loading.applied_torque", "give either applied_torque or target_speed + target_time, not both");
  if (explicit_torque) {
    p.applied_torque = reader.positive("loading.applied_torque");
    c.torque_origin = "from the case file";
  } else {
    if (!targeted) reader.fail("loading.applied_torque", "missing (or give target_speed + target_time)");
    const double v1 = reader.positive("loading.target_speed");
    const double t1 = reader.positive("loading.target_time");
    // Eq. 4.11 from rest with mu0 = the static coefficient (the thesis's mu0).
    p.applied_torque = continuum::thesis_torque_for_speed(p, c.friction->static_coefficient(),
                                                          c.friction->speed_coefficient(), 0.0, v1, t1);
    if (!(p.applied_torque > 0.0)) reader.fail("loading.target_speed", "eq. 4.11 gives a non-positive torque");
    c.torque_origin = "eq. 4.11: V = " + CaseReader::format(v1) + " m/s at t = " + CaseReader::format(t1) +
                      " s from rest under constant torque";
  }

  auto &run = c.run;
  run.t_end = reader.positive("run.t_end");
  run.output_interval = reader.positive("run.output_interval", 1e-3);
  if (run.t_end / run.output_interval > 1e7) reader.fail("run.output_interval", "gives more than 1e7 samples");
  run.initial_speed = reader.number("run.initial_speed", 0.0);
  run.integrator.method = reader.choice("solver.method", {"bdf", "adams"}, std::string("bdf")) == "bdf"
                              ? continuum::CvodeIntegrator::Method::Bdf
                              : continuum::CvodeIntegrator::Method::Adams;
  run.integrator.rtol = reader.positive("solver.rtol", 1e-8);
  run.integrator.atol = reader.positive("solver.atol", 1e-10);
  run.integrator.max_steps = reader.positive_integer("solver.max_steps", 100000);
  return c;
}

namespace {
continuum::CvodeIntegrator::Settings read_solver(const CaseReader &reader, continuum::CvodeIntegrator::Settings s) {
  s.method = reader.choice("solver.method", {"bdf", "adams"}, std::string("bdf")) == "bdf"
                 ? continuum::CvodeIntegrator::Method::Bdf
                 : continuum::CvodeIntegrator::Method::Adams;
  s.rtol = reader.positive("solver.rtol", s.rtol);
  s.atol = reader.positive("solver.atol", s.atol);
  s.max_steps = reader.positive_integer("solver.max_steps", s.max_steps);
  return s;
}

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
  return c;
}

}  // namespace runin::cli
