#include "coupling/json_input.h"

#include <algorithm>
#include <set>
#include <vector>

#include "coupling/ave_time_reader.h"  // InputFormatError

namespace runin::coupling {

namespace {
using json = nlohmann::json;

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}
}  // namespace

json parse_json_input(const std::string &text, const std::string &path, int max_depth) {
  std::vector<std::set<std::string>> seen;  // keys of each open object
  std::vector<std::string> keys;            // per open container: its current key ("" in arrays)
  const auto key_path = [&] {
    std::string dotted;
    for (const auto &k : keys)
      if (!k.empty()) dotted += (dotted.empty() ? "" : ".") + k;
    return "key '" + dotted + "'";
  };
  const json::parser_callback_t strict = [&](int depth, json::parse_event_t event, json &parsed) {
    if (depth > max_depth)
      throw InputFormatError(path + ": " + key_path() + ": nested deeper than " + std::to_string(max_depth) +
                             " levels");
    switch (event) {
      case json::parse_event_t::object_start: seen.emplace_back(); keys.emplace_back(); break;
      case json::parse_event_t::array_start: seen.emplace_back(); keys.emplace_back(); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end: seen.pop_back(); keys.pop_back(); break;
      case json::parse_event_t::key: {
        keys.back() = parsed.get<std::string>();
        if (!seen.back().insert(keys.back()).second) throw InputFormatError(path + ": " + key_path() + ": defined twice");
        break;
      }
      case json::parse_event_t::value: break;
    }
    return true;
  };
  try {
    return json::parse(text, strict);
  } catch (const json::out_of_range &) {  // a number beyond a double (e.g. 1e400)
    throw InputFormatError(path + ": " + key_path() + ": number out of range (overflows a double)");
  } catch (const json::parse_error &e) {
    // e.byte counts the characters read up to and including the offending one
    const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
    const std::size_t line = 1 + std::count(text.begin(), text.begin() + end, '\n');
    const std::size_t line_start = text.rfind('\n', end > 0 ? end - 1 : 0);
    const std::size_t column = line == 1 ? end + 1 : end - line_start;
    std::string what = e.what();
    const auto colon = what.find(": ", what.find("parse error"));
    if (colon != std::string::npos) what = what.substr(colon + 2);
    throw InputFormatError(path + ":" + std::to_string(line) + ":" + std::to_string(column) + ": invalid JSON: " +
                           one_line(what));
  }
}

}  // namespace runin::coupling
