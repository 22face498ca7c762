// RunIn coefficient files (potentials/*.runin) for the LIGGGHTS host, parsed by tribo/material_file.h as in
// the LAMMPS styles:
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]  [S_y[Pa]]
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
// Read on rank 0 and broadcast; any problem is one ERROR prefixed by `style`.
#pragma once

#include "tribo/contact.h"
#include "tribo/contact_model.h"
#include "tribo/material_file.h"
#include "coefficient_grammar.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace runin_liggghts {

using MaterialPair = runin::tribo::MaterialPairEntry;

MaterialPair read_material_pair(LAMMPS_NS::LAMMPS *lmp, const std::string &file, const std::string &material_a,
                                const std::string &material_b, const std::string &style);

// The coefficient grammar's host adaptor (plugins/common/coefficient_grammar.h) for `style`: ERRORs and WARNINGs
// through LIGGGHTS's Error, numbers as runin_liggghts::is_double reads them, coefficient files through
// read_material_pair with `material_style` before its messages; `film`: the host keeps a per-summit film coverage.
runin_coeff::Host coefficient_host(LAMMPS_NS::LAMMPS *lmp, const std::string &style, const std::string &material_style,
                                   bool film);

}    // namespace runin_liggghts
