#include "runin_liggghts_material.h"

#include "runin_liggghts_errors.h"

#include "comm.h"
#include "lammps.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace tribo = runin::tribo;

namespace {

std::string parse(FILE *fp, const std::string &file, const std::string &name_a, const std::string &name_b,
                  runin_liggghts::MaterialPair &out)
{
  std::map<std::string, tribo::Material> materials;
  std::optional<std::vector<double>> pair_values;
  char line[1024];
  int lineno = 0;
  try {
    while (fgets(line, sizeof(line), fp)) {
      lineno++;
      std::string text(line);
      text = text.substr(0, text.find('#'));
      std::istringstream stream(text);
      std::vector<std::string> words;
      for (std::string w; stream >> w;) words.push_back(w);
      if (words.empty()) continue;
      std::size_t next = 1;
      auto number = [&](const std::string &what) {
        if (next >= words.size()) throw std::runtime_error(what + ": missing");
        const std::string &w = words[next++];
        if (!runin_liggghts::is_double(w.c_str()))
          throw std::runtime_error(fmt::format("{}: expected a number, got '{}'", what, w));
        const double value = std::strtod(w.c_str(), nullptr);
        if (!std::isfinite(value)) throw std::runtime_error(fmt::format("{} must be a finite number, got {}", what, value));
        return value;
      };
      if (words[0] == "material") {
        if (words.size() != 6 && words.size() != 7) throw std::runtime_error("material needs NAME E nu rho H [S_y]");
        const std::string name = words[next++];
        tribo::Material m;
        m.youngs_modulus = number("material " + name + ": E");
        m.poisson_ratio = number("material " + name + ": nu");
        number("material " + name + ": rho");
        m.hardness = number("material " + name + ": H");
        if (words.size() == 7) {
          m.yield_strength = number("material " + name + ": S_y");
          if (!(m.yield_strength > 0.0))
            throw std::runtime_error(fmt::format("material {}: S_y must be > 0 and finite", name));
        }
        m.validate(fmt::format("{} line {}: material {}", file, lineno, name));
        materials[name] = m;
      } else if (words[0] == "pair") {
        if (words.size() != 8) throw std::runtime_error("pair needs A B e mu_s mu_k d_c k");
        const std::string a = words[1], b = words[2];
        next = 3;
        if ((a == name_a && b == name_b) || (a == name_b && b == name_a)) {
          std::vector<double> values;
          for (const char *what : {"e", "mu_s", "mu_k", "d_c", "k"})
            values.push_back(number(fmt::format("pair {} {}: {}", a, b, what)));
          pair_values = values;
        }
      } else {
        throw std::runtime_error(fmt::format("unknown entry '{}'", words[0]));
      }
    }
  } catch (const tribo::InvalidCoefficient &e) {
    return e.what();
  } catch (const std::exception &e) {
    return fmt::format("{} line {}: {}", file, lineno, e.what());
  }
  if (!materials.count(name_a)) return fmt::format("material '{}' not found in '{}'", name_a, file);
  if (!materials.count(name_b)) return fmt::format("material '{}' not found in '{}'", name_b, file);
  if (!pair_values) return fmt::format("no 'pair {} {}' entry in '{}'", name_a, name_b, file);
  const std::vector<double> &v = *pair_values;
  out.a = materials[name_a];
  out.b = materials[name_b];
  out.restitution = v[0];
  out.mu_static = v[1];
  out.mu_kinetic = v[2];
  out.slip_weakening_distance = v[3];
  out.wear_coefficient = v[4];
  return "";
}

}    // namespace

runin_liggghts::MaterialPair runin_liggghts::read_material_pair(LAMMPS_NS::LAMMPS *lmp, const std::string &file,
                                                                const std::string &material_a,
                                                                const std::string &material_b,
                                                                const std::string &style)
{
  MaterialPair entry;
  std::string problem;
  if (lmp->comm->me == 0) {
    FILE *fp = fopen(file.c_str(), "r");
    if (!fp) {
      problem = fmt::format("cannot open coefficient file '{}'", file);
    } else {
      problem = parse(fp, file, material_a, material_b, entry);
      fclose(fp);
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
