#include "runin_material_file.h"
#include "runin_potential_path.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cstdio>
#include <sstream>

using namespace LAMMPS_NS;
namespace tribo = runin::tribo;

RuninMaterialPair LAMMPS_NS::read_runin_material_pair(LAMMPS *lmp, const std::string &file,
                                                      const std::string &material_a, const std::string &material_b,
                                                      const std::string &style)
{
  RuninMaterialPair entry;
  std::string problem;
  if (lmp->comm->me == 0) {
    // the path as given, then $LAMMPS_POTENTIALS (runin_potential_path.h); the ERROR lists every place tried
    const auto search = runin_lammps::find_potential_file(file);
    FILE *fp = search.found.empty() ? nullptr : fopen(search.found.c_str(), "r");
    if (!fp) {
      problem = search.message(file);
    } else {
      std::string text;
      char buffer[4096];
      for (std::size_t n; (n = fread(buffer, 1, sizeof(buffer), fp)) > 0;) text.append(buffer, n);
      fclose(fp);
      try {
        std::istringstream stream(text);
        entry = tribo::parse_material_file(stream, file).pair(material_a, material_b);
      } catch (const std::exception &e) {  // MaterialFileError, InvalidCoefficient: both name file and line
        problem = e.what();
      }
    }
  }
  int length = problem.size();
  MPI_Bcast(&length, 1, MPI_INT, 0, lmp->world);
  problem.resize(length);
  MPI_Bcast(&problem[0], length, MPI_CHAR, 0, lmp->world);
  if (length) lmp->error->all(FLERR, "{}: {}", style, problem);
  MPI_Bcast(&entry, sizeof(entry), MPI_BYTE, 0, lmp->world);    // trivially copyable doubles
  return entry;
}

runin_coeff::Host LAMMPS_NS::coefficient_host(LAMMPS *lmp, const std::string &style, const std::string &material_style,
                                              bool film)
{
  runin_coeff::Host host;
  host.style = style;
  host.film = film;
  host.fail = [lmp](const std::string &message) { lmp->error->all(FLERR, message); };
  host.warning = [lmp](const std::string &message) {
    if (lmp->comm->me == 0) lmp->error->warning(FLERR, message);
  };
  host.is_number = [](const char *text) { return text && utils::is_double(text); };
  host.material = [lmp, material_style](const char *path, const char *a, const char *b) {
    return runin_coeff::parameters_of(read_runin_material_pair(lmp, path, a, b, material_style));
  };
  return host;
}
