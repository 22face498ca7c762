// Strict JSON for input files (case files, law files).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace runin::coupling {

// Parses `text` (named `path` in errors). Beyond nlohmann's own checks: a key defined twice, nesting deeper
// than `max_depth` levels (a hostile file could otherwise exhaust the stack of any recursive reader) and a
// number beyond a double are errors naming the key path ("run.R0"); a syntax error names line and column.
// Throws InputFormatError (coupling/ave_time_reader.h) with one line "<path>[:line:col]: ...".
nlohmann::json parse_json_input(const std::string &text, const std::string &path, int max_depth = 32);

}  // namespace runin::coupling
