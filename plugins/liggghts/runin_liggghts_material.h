// Reader of RunIn coefficient files (potentials/*.runin) for the LIGGGHTS host: the format of
// plugins/lammps/runin_material_file.h (LAMMPS's reader uses LAMMPS's tokenizer, which LIGGGHTS lacks):
//   material NAME  E[Pa]  nu[-]  rho[kg/m^3]  H[Pa]  [S_y[Pa]]
//   pair NAME_A NAME_B  e[-]  mu_s[-]  mu_k[-]  d_c[m]  k[-]
// Read on rank 0 and broadcast; any problem is one ERROR prefixed by `style`.
#pragma once

#include "tribo/contact.h"
#include "tribo/contact_model.h"

#include <string>

namespace LAMMPS_NS {
class LAMMPS;
}

namespace runin_liggghts {

struct MaterialPair {
  runin::tribo::Material a, b;
  double restitution = 1.0, mu_static = 0.0, mu_kinetic = 0.0, slip_weakening_distance = 0.0,
         wear_coefficient = 0.0;
};

MaterialPair read_material_pair(LAMMPS_NS::LAMMPS *lmp, const std::string &file, const std::string &material_a,
                                const std::string &material_b, const std::string &style);

inline runin::tribo::ContactParameters contact_parameters(const MaterialPair &entry)
{
  return runin::tribo::contact_parameters(entry.a, entry.b, entry.restitution, entry.mu_static, entry.mu_kinetic,
                                          entry.slip_weakening_distance, entry.wear_coefficient);
}

}    // namespace runin_liggghts
