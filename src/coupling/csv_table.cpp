#include "coupling/csv_table.h"

#include <charconv>
#include <set>

namespace runin::coupling {
namespace {

std::string trim(const std::string &text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> split_fields(const std::string &line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::string unquote(const std::string &name) {
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"') return name.substr(1, name.size() - 2);
  return name;
}

std::string join(const std::vector<std::string> &names) {
  std::string out;
  for (const auto &n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

bool CsvTable::has_column(const std::string &name) const {
  for (const auto &n : names_)
    if (n == name) return true;
  return false;
}

std::vector<double> CsvTable::numbers(const std::string &name) const {
  std::size_t index = names_.size();
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) index = i;
  if (index == names_.size())
    throw InputFormatError(source_ + ": no column '" + name + "' (columns: " + join(names_) + ")");
  std::vector<double> out;
  out.reserve(cells_.size());
  for (std::size_t row = 0; row < cells_.size(); ++row) {
    const std::string &token = cells_[row][index];
    double value = 0.0;
    const char *begin = token.data();
    if (!token.empty() && token.front() == '+') ++begin;  // from_chars rejects a leading '+'
    const auto [end, ec] = std::from_chars(begin, token.data() + token.size(), value);
    if (token.empty() || ec != std::errc() || end != token.data() + token.size())
      throw InputFormatError(source_ + ":" + std::to_string(lines_[row]) + ": column '" + name + "': '" + token +
                             "' is not a number");
    out.push_back(value);
  }
  return out;
}

CsvTable parse_csv_table(std::istream &in, const std::string &source_name) {
  CsvTable table;
  table.source_ = source_name;
  const auto fail = [&](std::size_t line_no, const std::string &problem) {
    throw InputFormatError(source_name + ":" + std::to_string(line_no) + ": " + problem);
  };
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // UTF-8 byte order mark
    const std::string text = trim(line);
    if (text.empty() || text.front() == '#') continue;
    auto fields = split_fields(text);
    if (table.names_.empty()) {
      std::set<std::string> seen;
      for (auto &f : fields) {
        f = unquote(f);
        if (f.empty()) fail(line_no, "header: empty column name (expected names such as t,mu,R)");
        if (!seen.insert(f).second) fail(line_no, "header: column '" + f + "' appears twice");
      }
      table.names_ = std::move(fields);
      continue;
    }
    if (fields.size() != table.names_.size())
      fail(line_no, "expected " + std::to_string(table.names_.size()) + " comma-separated values (" +
                        join(table.names_) + "), got " + std::to_string(fields.size()));
    table.cells_.push_back(std::move(fields));
    table.lines_.push_back(line_no);
  }
  if (table.names_.empty()) throw InputFormatError(source_name + ": empty (expected a header line of column names)");
  if (table.cells_.empty()) throw InputFormatError(source_name + ": no data rows after the header");
  return table;
}

CsvTable read_csv_table(const std::string &path) {
  std::ifstream file = open_input(path, "CSV file");
  return parse_csv_table(file, path);
}

}  // namespace runin::coupling
