// LAMMPS side of the RunIn coefficient files (potentials/*.runin; the parser is tribo/material_file.h), shared
// by pair runin/asperity and fix runin/wall. SI units, '#' comments:
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]  [S_y[Pa]]   (S_y: elastic-plastic contact; else H / 2.8)
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
//   interface NAME_A NAME_B  STATE  m[-]   (optional; tau_s = m S_y / sqrt(3) or junction f = m)
#pragma once

#include "tribo/contact.h"
#include "tribo/contact_model.h"
#include "tribo/material_file.h"
#include "coefficient_grammar.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;

// One material pair as a contact sees it (parsed by runin::tribo::parse_material_file).
using RuninMaterialPair = runin::tribo::MaterialPairEntry;

// Reads the pair (material_a, material_b) on rank 0 and broadcasts it. Any problem (missing file,
// unknown material or pair, malformed line, impossible value) is one ERROR prefixed by 'style'.
RuninMaterialPair read_runin_material_pair(LAMMPS *lmp, const std::string &file, const std::string &material_a,
                                           const std::string &material_b, const std::string &style);

// The coefficient grammar's host adaptor (plugins/common/coefficient_grammar.h) for `style`: ERRORs and WARNINGs
// through LAMMPS's Error, numbers as utils::is_double reads them, coefficient files through read_runin_material_pair
// with `material_style` before its messages; `film`: the host keeps the per-summit film coverage.
runin_coeff::Host coefficient_host(LAMMPS *lmp, const std::string &style, const std::string &material_style, bool film);

}    // namespace LAMMPS_NS
