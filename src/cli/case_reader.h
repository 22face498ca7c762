// Typed, checked access to a TOML or JSON case file; every error names the file and the key.
#pragma once

#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "cli/case_file.h"  // InputError
#include "continuum/cvode_integrator.h"

namespace runin::cli {

// Allowed keys per table; "" is the top level.
using Schema = std::map<std::string, std::set<std::string>>;

std::string type_name(const toml::node &node);

// Parses a case file into a TOML table: `*.json` as JSON (objects become tables, so every case
// reader and its key errors work unchanged), anything else as TOML. A syntax error becomes
// InputError "<file>:<line>:<col>: invalid TOML: ..." (or "invalid JSON: ...").
toml::table parse_toml(const std::string &path);
// JSON text -> TOML table; `path` only names the file in errors. Throws InputError.
toml::table parse_json_case(const std::string &text, const std::string &path);

// Reads keys by dotted path ("pin.mass"); `fallback` makes a key optional.
class CaseReader {
 public:
  static constexpr std::size_t kMaxFrames = 200;
  static constexpr std::size_t kMaxSweepValues = 20;  // sweep.mu0: one full run each
  CaseReader(std::string path, toml::table root, const Schema &schema)
      : path_(std::move(path)), root_(std::move(root)), schema_(schema) {}

  [[noreturn]] void fail(const std::string &key, const std::string &problem) const {
    throw InputError(path_ + ": key '" + key + "': " + problem);
  }

  void reject_unknown_keys() const {
    for (const auto &[key, node] : root_) {
      const std::string name(key.str());
      if (!schema_.at("").count(name)) fail(name, "unknown key");
      if (name == "title" || !schema_.count(name)) continue;  // a top-level key, not a section
      const auto *table = node.as_table();
      if (!table) fail(name, "expected a table, got " + type_name(node));
      for (const auto &[sub, ignored] : *table) {
        (void)ignored;
        if (!schema_.at(name).count(std::string(sub.str()))) fail(name + "." + std::string(sub.str()), "unknown key");
      }
    }
  }

  const std::string &path() const { return path_; }
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
  bool flag(const std::string &key, bool fallback) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) return fallback;
    if (!node->is_boolean()) fail(key, "expected true or false, got " + type_name(*node));
    return *node->value<bool>();
  }
  // In (0, max]: a key whose huge values would overflow the run's arithmetic or its run time.
  double positive_at_most(const std::string &key, double max, std::optional<double> fallback = std::nullopt) const {
    const double value = positive(key, fallback);
    if (value > max) fail(key, "must be in (0, " + format(max) + "], got " + format(value));
    return value;
  }
  // numbers(key), at most `max_count` of them (each is a full run).
  std::vector<double> numbers_at_most(const std::string &key, std::size_t max_count) const {
    std::vector<double> values = numbers(key);
    if (values.size() > max_count)
      fail(key, std::to_string(values.size()) + " values: give 1 to " + std::to_string(max_count));
    return values;
  }
  // Positive and at most `max` (an int by default: callers store counts in int, which must not wrap).
  long positive_integer(const std::string &key, long fallback, long max = std::numeric_limits<int>::max()) const {
    const toml::node *node = root_.at_path(key).node();
    if (!node) return fallback;
    if (!node->is_integer()) fail(key, "expected an integer, got " + type_name(*node));
    const long value = static_cast<long>(*node->value<int64_t>());
    if (value <= 0) fail(key, "must be positive, got " + std::to_string(value));
    if (value > max) fail(key, "must be at most " + std::to_string(max) + ", got " + std::to_string(value));
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
  // Output times (VTK frames): numbers(key), each in [0, t_end], at most `max_frames` of them (every frame is a
  // full field file: the cap bounds the run's output size and time).
  std::vector<double> times_within(const std::string &key, double t_end, std::size_t max_frames = kMaxFrames) const {
    const std::vector<double> times = numbers(key);
    if (times.size() > max_frames)
      fail(key, std::to_string(times.size()) + " frames: at most " + std::to_string(max_frames) + " allowed");
    for (std::size_t i = 0; i < times.size(); ++i)
      if (times[i] < 0.0 || times[i] > t_end)
        fail(key, "element " + std::to_string(i) + ": must be in [0, run.t_end], got " + format(times[i]));
    return times;
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

// [solver] method = "bdf"|"adams", rtol, atol, max_steps; absent keys keep `defaults`.
continuum::CvodeIntegrator::Settings read_solver(const CaseReader &reader, continuum::CvodeIntegrator::Settings defaults);

}  // namespace runin::cli
