// Reader for plain CSV tables with a header line of column names (any producer: a runin element's CSV,
// a spreadsheet export, a post-processed LAMMPS log). Lines starting with '#' and blank lines are skipped;
// fields are comma-separated and trimmed; a header name may be double-quoted. Only the columns asked for
// must be numeric, so text columns elsewhere in the file are fine.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "coupling/ave_time_reader.h"  // InputFormatError, open_input

namespace runin::coupling {

class CsvTable {
 public:
  const std::string &source() const { return source_; }
  const std::vector<std::string> &column_names() const { return names_; }
  std::size_t rows() const { return cells_.size(); }
  bool has_column(const std::string &name) const;
  // The column as numbers. Throws InputFormatError "<source>: no column 'X' (columns: a, b)" or
  // "<source>:<line>: column 'X': 'abc' is not a number". Non-finite values ("nan", "inf") are returned
  // as such: the caller decides (and names the row).
  std::vector<double> numbers(const std::string &name) const;
  // File line number of data row i (for messages).
  std::size_t line_of(std::size_t row) const { return lines_.at(row); }

  friend CsvTable parse_csv_table(std::istream &in, const std::string &source_name);

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::vector<std::vector<std::string>> cells_;
  std::vector<std::size_t> lines_;
};

// Throws InputFormatError naming the file and line: no header, a row with a different field count,
// duplicate or empty column names, no data rows.
CsvTable parse_csv_table(std::istream &in, const std::string &source_name);
CsvTable read_csv_table(const std::string &path);

}  // namespace runin::coupling
