#include <algorithm>
#include "coupling/ave_time_reader.h"

#include <filesystem>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace runin::coupling {
namespace {

std::vector<std::string> split_whitespace(const std::string &text) {
  std::istringstream stream(text);
  std::vector<std::string> tokens;
  for (std::string token; stream >> token;) tokens.push_back(token);
  return tokens;
}

std::string join(const std::vector<std::string> &words) {
  std::string out;
  for (const auto &w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

}  // namespace

AveTimeTable::AveTimeTable(std::string source, std::vector<std::string> names,
                           std::vector<std::vector<double>> columns)
    : source_(std::move(source)), names_(std::move(names)), columns_(std::move(columns)) {}

bool AveTimeTable::has_column(const std::string &name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

const std::vector<double> &AveTimeTable::column(const std::string &name) const {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return columns_[i];
  throw InputFormatError(source_ + ": no column '" + name + "' (columns: " + join(names_) + ")");
}

AveTimeTable parse_ave_time(std::istream &in, const std::string &source_name) {
  auto fail = [&](std::size_t line_no, const std::string &problem) {
    throw InputFormatError(source_name + ":" + std::to_string(line_no) + ": " + problem);
  };

  // LAMMPS writes comment lines first; the last one before the data names the columns.
  std::vector<std::string> last_comment;
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      if (!names.empty()) fail(line_no, "comment line after the data started (concatenated runs?)");
      last_comment = split_whitespace(line.substr(first + 1));
      continue;
    }
    if (names.empty()) {
      if (last_comment.empty() || last_comment.front() != "TimeStep")
        fail(line_no, "data before a '# TimeStep ...' header line");
      if (last_comment.size() > 1 && last_comment[1] == "Number-of-rows")
        fail(line_no, "fix ave/time mode vector output is not supported; use mode scalar");
      if (last_comment.size() < 2) fail(line_no, "header names no column besides TimeStep");
      names = last_comment;
      columns.resize(names.size());
    }
    const auto tokens = split_whitespace(line);
    if (tokens.size() != names.size())
      fail(line_no, "expected " + std::to_string(names.size()) + " values (" + join(names) +
                        "), got " + std::to_string(tokens.size()));
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const std::string &token = tokens[i];
      double value = 0.0;
      const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
      if (ec != std::errc() || end != token.data() + token.size())
        fail(line_no, "column '" + names[i] + "': '" + token + "' is not a number");
      if (!std::isfinite(value)) fail(line_no, "column '" + names[i] + "': non-finite value '" + token + "'");
      columns[i].push_back(value);
    }
  }
  if (names.empty()) fail(line_no, "no data rows (expected '# TimeStep ...' header and rows)");
  return AveTimeTable(source_name, std::move(names), std::move(columns));
}

std::ifstream open_input(const std::string &path, const std::string &what) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputFormatError(path + ": is a directory, not a " + what);
  std::ifstream file(path);
  if (!file) throw InputFormatError(path + ": cannot open the " + what);
  return file;
}

AveTimeTable read_ave_time(const std::string &path) {
  std::ifstream file = open_input(path, "fix ave/time file");
  return parse_ave_time(file, path);
}

}  // namespace runin::coupling
