#include "tribo/material_file.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace runin::tribo {
namespace {

// strtod on the whole word, decimal notation only, finite: "1e999" (inf), "nan", "0x10" or a word are refused.
bool finite_number(const std::string &word, double &value) {
  if (word.empty() || word.find_first_not_of("0123456789+-.eE") != std::string::npos) return false;
  char *end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end == word.c_str() + word.size() && std::isfinite(value);
}

}  // namespace

const Material &MaterialFile::material(const std::string &name) const {
  const auto found = materials.find(name);
  if (found == materials.end()) throw MaterialFileError(file + ": no material '" + name + "'");
  return found->second;
}

MaterialPairEntry MaterialFile::pair(const std::string &a, const std::string &b) const {
  auto found = pairs.find({a, b});
  if (found == pairs.end()) found = pairs.find({b, a});
  if (found == pairs.end()) {
    material(a), material(b);  // a missing material is the more useful message
    throw MaterialFileError(file + ": no 'pair " + a + " " + b + "' entry");
  }
  MaterialPairEntry entry = found->second;
  entry.a = material(a);
  entry.b = material(b);
  return entry;
}

MaterialFile parse_material_file(std::istream &in, const std::string &file) {
  MaterialFile result;
  result.file = file;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    const std::string where = file + " line " + std::to_string(lineno) + ": ";
    std::istringstream stream(line.substr(0, line.find('#')));
    std::vector<std::string> words;
    for (std::string w; stream >> w;) words.push_back(w);
    if (words.empty()) continue;
    std::size_t next = 0;
    auto number = [&](const std::string &what) {
      double value = 0.0;
      const std::string &word = words[next++];
      if (!finite_number(word, value))
        throw MaterialFileError(where + what + " must be a finite number, got '" + word + "'");
      return value;
    };
    if (words[0] == "material") {
      if (words.size() != 6 && words.size() != 7) throw MaterialFileError(where + "material needs NAME E nu rho H [S_y]");
      const std::string &name = words[1];
      next = 2;
      Material m;
      m.youngs_modulus = number("material " + name + ": E");
      m.poisson_ratio = number("material " + name + ": nu");
      number("material " + name + ": rho");  // density: the hosts take it from the atoms' mass
      m.hardness = number("material " + name + ": H");
      if (words.size() == 7) {
        m.yield_strength = number("material " + name + ": S_y");
        if (!(m.yield_strength > 0.0)) throw MaterialFileError(where + "material " + name + ": S_y must be > 0");
      }
      m.validate(where + "material " + name);
      result.materials[name] = m;
    } else if (words[0] == "pair") {
      if (words.size() != 8) throw MaterialFileError(where + "pair needs A B e mu_s mu_k d_c k");
      const std::string prefix = "pair " + words[1] + " " + words[2] + ": ";
      next = 3;
      MaterialPairEntry entry;
      entry.restitution = number(prefix + "e");
      entry.mu_static = number(prefix + "mu_s");
      entry.mu_kinetic = number(prefix + "mu_k");
      entry.slip_weakening_distance = number(prefix + "d_c");
      entry.wear_coefficient = number(prefix + "k");
      result.pairs[{words[1], words[2]}] = entry;
    } else {
      throw MaterialFileError(where + "unknown entry '" + words[0] + "'");
    }
  }
  return result;
}

}  // namespace runin::tribo
