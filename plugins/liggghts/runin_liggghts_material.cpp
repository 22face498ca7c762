#include "runin_liggghts_material.h"

#include "runin_liggghts_errors.h"
#include "../lammps/runin_potential_path.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"

#include <fstream>

namespace tribo = runin::tribo;

runin_liggghts::MaterialPair runin_liggghts::read_material_pair(LAMMPS_NS::LAMMPS *lmp, const std::string &file,
                                                                const std::string &material_a,
                                                                const std::string &material_b,
                                                                const std::string &style)
{
  MaterialPair entry;
  std::string problem;
  if (lmp->comm->me == 0) {
    // the path as given, then $LAMMPS_POTENTIALS, as on the LAMMPS host
    const auto search = runin_lammps::find_potential_file(file);
    std::ifstream in;
    if (!search.found.empty()) in.open(search.found);
    if (!in.is_open()) {
      problem = search.message(file);
    } else {
      try {
        entry = tribo::parse_material_file(in, file).pair(material_a, material_b);
      } catch (const std::exception &e) {  // MaterialFileError, InvalidCoefficient: both name file and line
        problem = e.what();
      }
    }
  }
  int length = static_cast<int>(problem.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, lmp->world);
  problem.resize(length);
  if (length) MPI_Bcast(&problem[0], length, MPI_CHAR, 0, lmp->world);
  if (length) all(lmp, FLERR, style + ": " + problem);
  MPI_Bcast(&entry, sizeof(entry), MPI_BYTE, 0, lmp->world);
  return entry;
}

runin_coeff::Host runin_liggghts::coefficient_host(LAMMPS_NS::LAMMPS *lmp, const std::string &style,
                                                   const std::string &material_style, bool film)
{
  runin_coeff::Host host;
  host.style = style;
  host.film = film;
  host.fail = [lmp](const std::string &message) { all(lmp, FLERR, message); };
  host.warning = [lmp](const std::string &message) {
    if (lmp->comm->me == 0) lmp->error->warning(FLERR, message.c_str());
  };
  host.is_number = [](const char *text) { return is_double(text); };
  host.material = [lmp, material_style](const char *path, const char *a, const char *b) {
    return runin_coeff::parameters_of(read_material_pair(lmp, path, a, b, material_style));
  };
  return host;
}
