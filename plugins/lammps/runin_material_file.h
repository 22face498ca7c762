// LAMMPS side of the RunIn coefficient files (potentials/*.runin; the parser is tribo/material_file.h), shared
// by pair runin/asperity and fix runin/wall. SI units, '#' comments:
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]  [S_y[Pa]]   (S_y: elastic-plastic contact; else H / 2.8)
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
//   interface NAME_A NAME_B  STATE  m[-]   (optional; tau_s = m S_y / sqrt(3) or junction f = m)
#pragma once

#include "tribo/contact.h"
#include "tribo/contact_model.h"
#include "tribo/material_file.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;

// One material pair as a contact sees it (parsed by runin::tribo::parse_material_file).
using RuninMaterialPair = runin::tribo::MaterialPairEntry;

// Reads the pair (material_a, material_b) on rank 0 and broadcasts it. Any problem (missing file,
// unknown material or pair, malformed line, impossible value) is one ERROR prefixed by 'style'.
RuninMaterialPair read_runin_material_pair(LAMMPS *lmp, const std::string &file, const std::string &material_a,
                                           const std::string &material_b, const std::string &style);

// The contact parameters of that pair (E*, G* from the two materials, their hardnesses, the pair entry and its
// interface lines).
inline runin::tribo::ContactParameters contact_parameters(const RuninMaterialPair &entry)
{
  auto p = runin::tribo::contact_parameters(entry.a, entry.b, entry.restitution, entry.mu_static, entry.mu_kinetic,
                                            entry.slip_weakening_distance, entry.wear_coefficient);
  p.interface_factors = entry.interface_factor;
  return p;
}

}    // namespace LAMMPS_NS
