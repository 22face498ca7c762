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
  auto interface = interfaces.find({a, b});
  if (interface == interfaces.end()) interface = interfaces.find({b, a});
  if (interface != interfaces.end()) entry.interface_factor = interface->second;
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
    } else if (words[0] == "interface") {
      if (words.size() != 5) throw MaterialFileError(where + "interface needs A B STATE m (STATE: " + interface_state_list() + ")");
      const std::string prefix = "interface " + words[1] + " " + words[2] + " " + words[3] + ": ";
      int state = 0;
      try {
        state = find_interface_state(words[3]);
      } catch (const InvalidCoefficient &e) {
        throw MaterialFileError(where + e.what());
      }
      next = 4;
      const double m = number(prefix + "m");
      if (!(m >= 0.0 && m <= 1.0))
        throw MaterialFileError(where + prefix + "m must be in [0, 1] (tau_s / (S_y / sqrt(3)) of the softer body), got '" +
                                words[4] + "'");
      auto found = result.interfaces.find({words[1], words[2]});
      if (found == result.interfaces.end()) found = result.interfaces.find({words[2], words[1]});
      if (found == result.interfaces.end())
        found = result.interfaces.emplace(std::make_pair(words[1], words[2]), no_interface_factors()).first;
      if (!std::isnan(found->second[state])) throw MaterialFileError(where + prefix + "given twice");
      found->second[state] = m;
    } else {
      throw MaterialFileError(where + "unknown entry '" + words[0] + "'");
    }
  }
  return result;
}

}  // namespace runin::tribo
