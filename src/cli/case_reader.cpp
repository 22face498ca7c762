#include "cli/case_reader.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include <nlohmann/json.hpp>

#include "coupling/ave_time_reader.h"  // InputFormatError
#include "coupling/json_input.h"

namespace runin::cli {

std::string type_name(const toml::node &node) {
  std::ostringstream out;
  out << node.type();
  return out.str();
}

namespace {

using json = nlohmann::json;
constexpr int kMaxCaseNesting = 32;

std::string one_line(std::string text) {
  for (char &c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::string key_path(const std::vector<std::string> &keys) {
  std::string path;
  for (const auto &k : keys) path += (path.empty() ? "" : ".") + k;
  return path;
}

// Where a converted value goes: a table under a key, or the end of an array. Two concrete types
// keep the recursion of convert() to two instantiations.
struct TableInsert {
  toml::table &table;
  const std::string &key;
  template <class Node>
  void operator()(Node &&node) const { table.insert_or_assign(key, std::forward<Node>(node)); }
};
struct ArrayInsert {
  toml::array &array;
  template <class Node>
  void operator()(Node &&node) const { array.push_back(std::forward<Node>(node)); }
};

template <class Emit>
void convert(const json &value, std::vector<std::string> &keys, const std::string &path, const Emit &emit);

toml::table convert_object(const json &value, std::vector<std::string> &keys, const std::string &path) {
  toml::table table;
  for (const auto &[key, child] : value.items()) {
    keys.push_back(key);
    convert(child, keys, path, TableInsert{table, key});
    keys.pop_back();
  }
  return table;
}

// JSON value -> TOML node handed to `emit`.
template <class Emit>
void convert(const json &value, std::vector<std::string> &keys, const std::string &path, const Emit &emit) {
  const auto fail = [&](const std::string &problem) {
    throw InputError(path + ": key '" + key_path(keys) + "': " + problem);
  };
  switch (value.type()) {
    case json::value_t::object: emit(convert_object(value, keys, path)); break;
    case json::value_t::array: {
      toml::array array;
      for (std::size_t i = 0; i < value.size(); ++i) {
        keys.push_back(std::to_string(i));
        convert(value[i], keys, path, ArrayInsert{array});
        keys.pop_back();
      }
      emit(std::move(array));
      break;
    }
    case json::value_t::string: emit(value.get<std::string>()); break;
    case json::value_t::boolean: emit(value.get<bool>()); break;
    case json::value_t::number_integer: emit(value.get<std::int64_t>()); break;
    case json::value_t::number_unsigned: {
      const auto u = value.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) fail("integer out of range");
      emit(static_cast<std::int64_t>(u));
      break;
    }
    case json::value_t::number_float: emit(value.get<double>()); break;
    case json::value_t::null: fail("null is not a value (leave the key out instead)"); break;
    default: fail("unsupported JSON value"); break;
  }
}

}  // namespace

toml::table parse_json_case(const std::string &text, const std::string &path) {
  json document;
  try {
    document = coupling::parse_json_input(text, path, kMaxCaseNesting);
  } catch (const coupling::InputFormatError &e) {
    throw InputError(e.what());
  }
  if (!document.is_object()) throw InputError(path + ":1:1: invalid JSON: the case must be an object { ... }");
  std::vector<std::string> where;
  return convert_object(document, where, path);
}

toml::table parse_toml(const std::string &path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError(path + ": is a directory, not a case file");
  if (!std::filesystem::exists(path, error))
    throw InputError(path + ": no such case file (a relative path is taken from the current directory, " +
                     std::filesystem::current_path(error).string() + ")");
  if (std::filesystem::path(path).extension() == ".json") {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open the case file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path + ": cannot read the case file");
    return parse_json_case(text, path);
  }
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error &e) {
    const std::string description = one_line(std::string(e.description()));
    const auto &where = e.source().begin;
    if (where.line == 0) throw InputError(path + ": " + description);  // e.g. file not readable
    throw InputError(path + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
                     ": invalid TOML: " + description);
  }
}

continuum::CvodeIntegrator::Settings read_solver(const CaseReader &reader, continuum::CvodeIntegrator::Settings s) {
  s.method = reader.choice("solver.method", {"bdf", "adams"}, std::string("bdf")) == "bdf"
                 ? continuum::CvodeIntegrator::Method::Bdf
                 : continuum::CvodeIntegrator::Method::Adams;
  s.rtol = reader.positive("solver.rtol", s.rtol);
  s.atol = reader.positive("solver.atol", s.atol);
  s.max_steps = reader.positive_integer("solver.max_steps", s.max_steps);
  return s;
}

}  // namespace runin::cli
