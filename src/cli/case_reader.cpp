#include "cli/case_reader.h"

namespace runin::cli {

std::string type_name(const toml::node &node) {
  std::ostringstream out;
  out << node.type();
  return out.str();
}

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
