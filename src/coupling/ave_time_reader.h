// Reader for LAMMPS `fix ave/time ... mode scalar` output files.
#pragma once

#include <fstream>
#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace runin::coupling {

// Bad micro-scale output or law file. The message is one line and starts with
// "<file>:<line>: " (or "<file>: " when no line applies).
class InputFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An input file opened for reading; a directory or an unreadable path is an InputFormatError naming it
// (a directory "opens" as a stream that fails on the first read, with a library message).
std::ifstream open_input(const std::string &path, const std::string &what);

// The numeric table of one ave/time file; columns are named by the header line
// ("TimeStep", "v_slide", "c_fric[3]", ...).
class AveTimeTable {
 public:
  AveTimeTable(std::string source, std::vector<std::string> names,
               std::vector<std::vector<double>> columns);

  const std::string &source() const { return source_; }
  const std::vector<std::string> &column_names() const { return names_; }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_.front().size(); }
  // Throws InputFormatError listing the available names if `name` is absent.
  const std::vector<double> &column(const std::string &name) const;
  bool has_column(const std::string &name) const;

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
};

AveTimeTable read_ave_time(const std::string &path);
// `source_name` is used in error messages only.
AveTimeTable parse_ave_time(std::istream &in, const std::string &source_name);

}  // namespace runin::coupling
