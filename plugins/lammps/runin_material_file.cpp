#include "runin_material_file.h"

#include "runin_errors.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "tokenizer.h"
#include "utils.h"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

using namespace LAMMPS_NS;
namespace tribo = runin::tribo;

namespace {

constexpr std::array<const char *, 5> kPairValues{"e", "mu_s", "mu_k", "d_c", "k"};

// Parses the whole file; returns an empty string or the problem, naming file and line.
std::string parse(FILE *fp, const std::string &file, const std::string &name_a, const std::string &name_b,
                  RuninMaterialPair &out)
{
  std::map<std::string, tribo::Material> materials;
  std::optional<std::vector<double>> pair_values;
  char line[1024];
  int lineno = 0;
  try {
    while (fgets(line, sizeof(line), fp)) {
      lineno++;
      ValueTokenizer words(utils::trim_comment(line));
      if (!words.has_next()) continue;
      // 1e999 (inf) is refused here, by name and line, before it surfaces renamed as E* or mu
      auto number = [&words](const std::string &what) {
        const std::string text = words.next_string();
        if (const auto value = runin_lammps::parse_finite(text.c_str())) return *value;
        throw TokenizerException(fmt::format("{} must be a finite number, got '{}'", what, text), "");
      };
      const std::string kind = words.next_string();
      if (kind == "material") {
        if (words.count() != 6 && words.count() != 7)
          throw TokenizerException("material needs NAME E nu rho H [S_y]", "");
        const std::string name = words.next_string();
        tribo::Material m;
        m.youngs_modulus = number("material " + name + ": E");
        m.poisson_ratio = number("material " + name + ": nu");
        number("material " + name + ": rho");    // density: the timestep guard takes it from the atoms' rmass
        m.hardness = number("material " + name + ": H");
        if (words.has_next()) {
          m.yield_strength = number("material " + name + ": S_y");
          if (!(m.yield_strength > 0.0))
            throw TokenizerException(fmt::format("material {}: S_y must be > 0 and finite", name), "");
        }
        m.validate(fmt::format("{} line {}: material {}", file, lineno, name));
        materials[name] = m;
      } else if (kind == "pair") {
        if (words.count() != 3 + kPairValues.size()) throw TokenizerException("pair needs A B e mu_s mu_k d_c k", "");
        const std::string a = words.next_string(), b = words.next_string();
        if ((a == name_a && b == name_b) || (a == name_b && b == name_a)) {
          std::vector<double> values;
          for (const char *what : kPairValues)
            values.push_back(number(fmt::format("pair {} {}: {}", a, b, what)));
          pair_values = values;
        }
      } else {
        throw TokenizerException(fmt::format("unknown entry '{}'", kind), "");
      }
    }
  } catch (const TokenizerException &e) {
    return fmt::format("{} line {}: {}", file, lineno, e.what());
  } catch (const tribo::InvalidCoefficient &e) {
    return e.what();
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

RuninMaterialPair LAMMPS_NS::read_runin_material_pair(LAMMPS *lmp, const std::string &file,
                                                      const std::string &material_a, const std::string &material_b,
                                                      const std::string &style)
{
  RuninMaterialPair entry;
  std::string problem;
  if (lmp->comm->me == 0) {
    FILE *fp = utils::open_potential(file, lmp, nullptr);
    if (!fp) {
      problem = fmt::format("cannot open coefficient file '{}'", file);
    } else {
      problem = parse(fp, file, material_a, material_b, entry);
      fclose(fp);
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
