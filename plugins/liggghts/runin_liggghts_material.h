// RunIn coefficient files (potentials/*.runin) for the LIGGGHTS host, parsed by tribo/material_file.h as in
// the LAMMPS styles:
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]  [S_y[Pa]]
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
// Read on rank 0 and broadcast; any problem is one ERROR prefixed by `style`.
#pragma once

#include "tribo/contact.h"
#include "tribo/contact_model.h"
#include "tribo/material_file.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace runin_liggghts {

using MaterialPair = runin::tribo::MaterialPairEntry;

MaterialPair read_material_pair(LAMMPS_NS::LAMMPS *lmp, const std::string &file, const std::string &material_a,
                                const std::string &material_b, const std::string &style);

inline runin::tribo::ContactParameters contact_parameters(const MaterialPair &entry)
{
  auto p = runin::tribo::contact_parameters(entry.a, entry.b, entry.restitution, entry.mu_static, entry.mu_kinetic,
                                            entry.slip_weakening_distance, entry.wear_coefficient);
  p.interface_factors = entry.interface_factor;    // the file's 'interface' lines (keyword interface STATE)
  return p;
}

}    // namespace runin_liggghts
