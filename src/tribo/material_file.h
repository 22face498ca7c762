// RunIn coefficient files (potentials/*.runin): the one parser that the LAMMPS styles, the LIGGGHTS host and the
// CLI share. SI units, '#' comments:
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]  [S_y[Pa]]   (S_y: elastic-plastic contact; else H / 2.8)
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
//   interface NAME_A NAME_B  STATE  m[-]   (optional; STATE clean, oxidised or boundary; tau_s = m S_y / sqrt(3))
#pragma once

#include <istream>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "tribo/contact.h"
#include "tribo/friction_strength.h"

namespace runin::tribo {

// A malformed file: "<file> line <n>: <problem>", or "<file>: no material 'X'" / "<file>: no 'pair A B' entry".
class MaterialFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One material pair as a contact sees it: body a's and body b's materials and the pair entry.
struct MaterialPairEntry {
  Material a, b;
  double restitution = 1.0, mu_static = 0.0, mu_kinetic = 0.0, slip_weakening_distance = 0.0,
         wear_coefficient = 0.0;
  InterfaceFactors interface_factor = no_interface_factors();    // m per interface state; NaN: no line
};

struct MaterialFile {
  std::string file;
  std::map<std::string, Material> materials;
  std::map<std::pair<std::string, std::string>, MaterialPairEntry> pairs;  // as written (a, b); materials unset
  std::map<std::pair<std::string, std::string>, InterfaceFactors> interfaces;  // as written (a, b)

  const Material &material(const std::string &name) const;  // throws MaterialFileError
  // The pair in either order, with a's and b's materials filled in; throws MaterialFileError.
  MaterialPairEntry pair(const std::string &a, const std::string &b) const;
};

// An 'interface' line needs m in [0, 1] and a known state (MaterialFileError naming the file, line, entry and, for
// a state, the known ones); the same pair and state twice is refused. Every line is checked: a number that is not finite ("1e999", "nan") or not a number is a MaterialFileError naming
// the file, line and entry; an impossible value (E <= 0, nu out of range, ...) throws InvalidCoefficient from
// Material::validate, whose message names the file, line and material.
MaterialFile parse_material_file(std::istream &in, const std::string &file);

}  // namespace runin::tribo
