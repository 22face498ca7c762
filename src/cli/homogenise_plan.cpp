#include "cli/homogenise_plan.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/core.h>
#include <openssl/evp.h>

#include "cli/case_file.h"
#include "cli/case_reader.h"
#include "tribo/friction_strength.h"
#include "tribo/material_file.h"

namespace runin::cli {

namespace fs = std::filesystem;

namespace {

const Schema &schema() {
  static const Schema s = {
      {"", {"title", "deck", "material", "surface", "sliding", "grid", "contact", "wear", "run"}},
      {"material", {"file", "rough", "counterface"}},
      {"surface", {"R", "sigma", "spacing", "nside", "heights", "caps"}},
      {"sliding", {"speed", "vertical_drag"}},
      {"contact", {"friction", "interface"}},
      {"wear", {"k", "jump_max_depth", "jump_every", "jump_reference_pressure", "jump_max_change", "jump_rate"}},
      {"run", {"launcher"}},
      {"grid",
       {"pressure_min", "pressure_max", "pressures", "extra_pressures", "extra_nside", "seeds", "acceleration", "depth",
        "depth_points",
        "depth_first", "nslide", "nout"}},
  };
  return s;
}

std::string required_text(const CaseReader &reader, const std::string &key) {
  if (!reader.has(key)) reader.fail(key, "missing (required)");
  const std::string value = reader.text(key, "");
  if (value.empty()) reader.fail(key, "must not be empty");
  if (value.find_first_of(" \t\n\"'") != std::string::npos)
    reader.fail(key, "must not contain blanks or quotes (it is passed to LAMMPS as one word)");
  return value;
}

// A summit list (LAMMPS atomfile: '#' comments, a count line, then "ID z" lines): exactly nside^2 summits with IDs
// 1..nside^2 once each and finite heights [m]. Sets the case's absolute path and the SHA-256 of the bytes checked.
// Defects are reader.fail on surface.heights.
void check_summit_list(const CaseReader &reader, const fs::path &file, HomogeniseCase &c) {
  std::error_code error;
  if (!fs::is_regular_file(file, error)) reader.fail("surface.heights", "no such file: " + file.string());
  const std::string resolved = fs::absolute(file).lexically_normal().string();
  if (resolved.find_first_of(" \t\n\"'") != std::string::npos)
    reader.fail("surface.heights", "the resolved path must not contain blanks or quotes: " + resolved);
  const std::string bytes = file_bytes(resolved);
  std::istringstream in(bytes);
  const long nside = c.nside;
  const long n = nside * nside;
  std::vector<char> seen(static_cast<std::size_t>(n) + 1, 0);
  long count = -1, rows = 0;
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    auto where = [&] { return resolved + ":" + std::to_string(number) + ": "; };
    if (count < 0) {
      if (!(fields >> count) || count != n)
        reader.fail("surface.heights", where() + "the count line must give surface.nside^2 = " + std::to_string(n) +
                                           " summits, got '" + line + "'");
      continue;
    }
    long id = 0;
    double z = 0.0;
    if (!(fields >> id >> z) || !std::isfinite(z) || id < 1 || id > n || seen[static_cast<std::size_t>(id)])
      reader.fail("surface.heights", where() + "expected 'ID z' with a new ID in 1.." + std::to_string(n) +
                                         " and a finite height, got '" + line + "'");
    seen[static_cast<std::size_t>(id)] = 1;
    ++rows;
  }
  if (rows != n)
    reader.fail("surface.heights", resolved + ": " + std::to_string(rows) + " summits, surface.nside^2 = " +
                                       std::to_string(n) + " expected");
  c.heights_file = resolved;
  c.heights_sha256 = sha256_hex(bytes);
}

}  // namespace

long derived_seed(long j) { return 4711 + 7919 * j; }

namespace {

// [material]: a RunIn coefficient file (relative: beside the case file, else the current directory, else the RunIn
// source tree, the last two with a note; find_case_file) and the two bodies' materials in it. Returns the file, parsed
// once, for the tables that read its pair ([contact], [wear]); a defect of the file is named at material.rough.
tribo::MaterialFile read_cell_materials(const CaseReader &reader, HomogeniseCase &c) {
  const std::string file = required_text(reader, "material.file");
  const fs::path resolved = find_case_file(reader, "material.file", file);
  c.material_file = fs::absolute(resolved).lexically_normal().string();
  if (c.material_file.find_first_of(" \t\n\"'") != std::string::npos)
    reader.fail("material.file", "the resolved path must not contain blanks or quotes: " + c.material_file);
  c.rough = required_text(reader, "material.rough");
  c.counterface = required_text(reader, "material.counterface");
  tribo::MaterialFile materials;
  try {
    std::ifstream in(c.material_file);
    if (!in) throw std::invalid_argument("cannot open " + c.material_file);
    materials = tribo::parse_material_file(in, c.material_file);
  } catch (const std::exception &e) {    // MaterialFileError, InvalidCoefficient: both name the file
    reader.fail("material.rough", e.what());
  }
  for (const auto &[key, name] : {std::make_pair("material.rough", c.rough), std::make_pair("material.counterface",
                                                                                            c.counterface)}) {
    try {
      materials.material(name);
    } catch (const std::exception &e) {
      reader.fail(key, e.what());
    }
  }
  return materials;
}

// grid.acceleration: one number, or one per pressure; 1 (none) when absent.
void read_acceleration(const CaseReader &reader, const toml::table &root, HomogeniseCase &c) {
  const bool is_array = root.at_path("grid.acceleration").is_array();
  if (!reader.has("grid.acceleration")) {
    c.acceleration.assign(c.pressures.size(), 1.0);
  } else {
    // one number, or one per pressure
    if (is_array)
      c.acceleration = reader.numbers("grid.acceleration");
    else
      c.acceleration.assign(c.pressures.size(), reader.number("grid.acceleration"));
    if (is_array && c.acceleration.size() != c.pressures.size())
      reader.fail("grid.acceleration", fmt::format("has {} values; give one number or one per pressure ({})",
                                                   c.acceleration.size(), c.pressures.size()));
    for (std::size_t i = 0; i < c.acceleration.size(); ++i)
      if (!(c.acceleration[i] >= 1.0))
        reader.fail("grid.acceleration", fmt::format("{}must be >= 1 (a factor on the Archard k), got {:g}",
                                                     is_array ? fmt::format("element {}: ", i) : std::string(),
                                                     c.acceleration[i]));
  }
}

// [contact]: the cell's friction sub-model and the interface state whose friction factor m the material file gives
// (tau_s = m S_y / sqrt(3) for strength and brizmer, f = m for junction; doc/interface_strength.md). The state is
// checked here against the file's pair (a missing line names the key); the deck's pair_coeff checks the rest.
void read_contact(const CaseReader &reader, const tribo::MaterialFile &materials, HomogeniseCase &c) {
  // the registry's laws that an interface state sets; one that takes it as its f has no other source of f here
  const std::vector<std::string> laws = tribo::interface_friction_models();
  c.friction = reader.choice("contact.friction", {laws.begin(), laws.end()}, c.friction);
  c.interface = reader.text("contact.interface", "");
  if (c.friction_info().interface_use == tribo::InterfaceUse::interface_coefficient && c.interface.empty())
    reader.fail("contact.friction",
                c.friction + " needs contact.interface (its f is the state's friction factor m)");
  if (c.interface.empty()) return;
  try {
    const int state = tribo::find_interface_state(c.interface);
    const auto pair = materials.pair(c.rough, c.counterface);
    c.interface_factor = pair.interface_factor[static_cast<std::size_t>(state)];
    if (std::isnan(c.interface_factor))
      reader.fail("contact.interface", fmt::format("the file {} has no 'interface {} {} {} m' line", c.material_file,
                                                   c.rough, c.counterface, c.interface));
  } catch (const std::exception &e) {    // an unknown state (InvalidCoefficient) or no pair (MaterialFileError)
    reader.fail("contact.interface", e.what());
  }
}

// [wear]: the cell's Archard k (both bodies; the material file's pair k when absent) and cycle jumping for mild k
// (fix runin/wear/jump, doc/rve_cell.md "Mild wear"). A k of its own is the physical k of the cell, not an
// acceleration: the deck runs it as wear_scale = k / k_file, and grid.acceleration cannot be given with it.
void read_wear(const CaseReader &reader, const tribo::MaterialFile &materials, HomogeniseCase &c) {
  if (reader.has("wear.k")) {
    if (reader.has("grid.acceleration"))
      reader.fail("wear.k", "give the cell's physical k or grid.acceleration, not both");
    c.wear_k = reader.positive("wear.k");
    if (!(c.wear_k <= 1.0)) reader.fail("wear.k", fmt::format("must be at most 1 (a dimensionless Archard k), got {:g}",
                                                              c.wear_k));
    double file_k = 0.0;
    try {
      file_k = materials.pair(c.rough, c.counterface).wear_coefficient;
    } catch (const std::exception &e) {
      reader.fail("wear.k", e.what());
    }
    if (!(file_k > 0.0))
      reader.fail("wear.k", fmt::format("the pair {} / {} of {} has k = 0: the cell cannot scale it", c.rough,
                                        c.counterface, c.material_file));
    c.wear_scale = c.wear_k / file_k;    // physical: the law's rates and distances are not rescaled by it
  }
  if (reader.has("wear.jump_max_depth")) c.jump_max_depth = reader.positive("wear.jump_max_depth");
  c.jump_every = reader.positive_integer("wear.jump_every", c.jump_every, 1000000000L);
  if (reader.has("wear.jump_every") && !(c.jump_max_depth > 0.0))
    reader.fail("wear.jump_every", "needs wear.jump_max_depth (cycle jumping is off without it)");
  if (reader.has("wear.jump_reference_pressure")) {
    if (!(c.jump_max_depth > 0.0))
      reader.fail("wear.jump_reference_pressure", "needs wear.jump_max_depth (cycle jumping is off without it)");
    c.jump_reference_pressure = reader.positive("wear.jump_reference_pressure");
  }
  if (reader.has("wear.jump_max_change")) {
    if (!(c.jump_max_depth > 0.0))
      reader.fail("wear.jump_max_change", "needs wear.jump_max_depth (cycle jumping is off without it)");
    c.jump_max_change = reader.positive("wear.jump_max_change");
    if (!(c.jump_max_change < c.sigma))
      reader.fail("wear.jump_max_change",
                  fmt::format("must be below surface.sigma ({:g} m), got {:g}: one jump would move a summit by more "
                              "than the height spread of the surface", c.sigma, c.jump_max_change));
  }
  if (reader.has("wear.jump_rate")) {
    if (!(c.jump_max_change > 0.0))
      reader.fail("wear.jump_rate", "needs wear.jump_max_change (the rate-controlled jumps grow up to it)");
    c.jump_rate = reader.positive("wear.jump_rate");
    if (!(c.jump_rate < 1.0))
      reader.fail("wear.jump_rate", fmt::format("must be below 1 (a relative change of Rq per cycle), got {:g}",
                                                c.jump_rate));
  }
}

// What is wrong with a launcher text (empty: nothing); its words into `words`.
std::string launcher_problem(const std::string &text, std::vector<std::string> &words) {
  std::istringstream in(text);
  for (std::string word; in >> word;) words.push_back(word);
  if (words.empty())
    return "empty; give the MPI launcher's command with {np} for the number of ranks, e.g. \"srun -n {np}\"";
  bool has_np = false;
  for (const auto &word : words) {
    if (word.find_first_of("'\"\\$`") != std::string::npos)
      return "the word " + word + " holds a quote, backslash, backtick or $: the launcher is split at blanks " +
             "without a shell (no quoting, no $variables); write the values out, or name a wrapper script";
    for (std::size_t i = 0; i < word.size(); ++i) {
      if (word[i] == '}')
        return "unmatched '}' in '" + word + "'; the only placeholder is {np}, the number of MPI ranks";
      if (word[i] != '{') continue;
      const auto close = word.find('}', i);
      if (close == std::string::npos)
        return "unmatched '{' in '" + word + "'; the only placeholder is {np}, the number of MPI ranks";
      const std::string placeholder = word.substr(i, close - i + 1);
      if (placeholder != "{np}")
        return "unknown placeholder '" + placeholder + "' in '" + word +
               "'; the only one is {np}, the number of MPI ranks";
      has_np = true;
      i = close;
    }
  }
  if (words.front().find('{') != std::string::npos)
    return "the first word names the launcher program, not '" + words.front() + "'";
  if (!has_np)  // LAMMPS needs as many ranks as partitions: the launcher must take runin's count
    return "no {np} in \"" + text + "\": say where the number of ranks goes, e.g. \"srun -n {np}\" or " +
           "\"mpirun --hostfile hosts -np {np}\"";
  return {};
}

// [run]: the MPI launcher of the samples (--launcher overrides it); a program path relative as material.file.
void read_run(const CaseReader &reader, HomogeniseCase &c) {
  if (!reader.has("run.launcher")) return;
  std::vector<std::string> words;
  if (const std::string problem = launcher_problem(reader.text("run.launcher", ""), words); !problem.empty())
    reader.fail("run.launcher", problem);
  if (words.front().find('/') != std::string::npos && fs::path(words.front()).is_relative())
    words.front() = fs::absolute(find_case_file(reader, "run.launcher", words.front())).lexically_normal().string();
  c.launcher = words;
}

}  // namespace

std::vector<std::string> parse_launcher(const std::string &text, const std::string &name) {
  std::vector<std::string> words;
  if (const std::string problem = launcher_problem(text, words); !problem.empty())
    throw InputError(name + ": " + problem);
  return words;
}

std::vector<std::string> expand_launcher(const std::vector<std::string> &words, int np) {
  std::vector<std::string> out;
  for (std::string word : words) {
    for (std::size_t at; (at = word.find("{np}")) != std::string::npos;) word.replace(at, 4, std::to_string(np));
    out.push_back(word);
  }
  return out;
}

const tribo::SubModelInfo &HomogeniseCase::friction_info() const {
  return tribo::registered_sub_models(
      tribo::SubModelKind::friction)[tribo::find_sub_model(tribo::SubModelKind::friction, friction)];
}

nlohmann::json HomogeniseCase::contact_json() const {
  if (friction == tribo::default_interface_friction_model() && interface.empty()) return nullptr;
  nlohmann::json out = {{"friction", friction}};
  if (!interface.empty()) out["interface"] = interface;
  return out;
}

nlohmann::json HomogeniseCase::wear_json() const {
  if (!(wear_k > 0.0) && !(jump_max_depth > 0.0)) return nullptr;
  nlohmann::json out = nlohmann::json::object();
  if (wear_k > 0.0) out["k"] = wear_k;
  if (jump_max_depth > 0.0) {
    out["jump_max_depth"] = jump_max_depth;
    out["jump_every"] = jump_every;
    if (jump_reference_pressure > 0.0) out["jump_reference_pressure"] = jump_reference_pressure;
    if (jump_max_change > 0.0) out["jump_max_change"] = jump_max_change;
    if (jump_rate > 0.0) out["jump_rate"] = jump_rate;
  }
  return out;
}

namespace {
// [grid] pressures: the log grid from pressure_min to pressure_max, plus grid.extra_pressures.
void read_grid_pressures(const CaseReader &reader, HomogeniseCase &c) {
  c.pressure_min = reader.positive("grid.pressure_min");
  c.pressure_max = reader.positive("grid.pressure_max");
  if (!(c.pressure_max > c.pressure_min))
    reader.fail("grid.pressure_max", fmt::format("must be above grid.pressure_min = {:g}, got {:g}", c.pressure_min,
                                                 c.pressure_max));
  const long pressures = reader.positive_integer("grid.pressures", 8, 100);
  if (pressures < 2) reader.fail("grid.pressures", "a law needs at least 2 pressures, got " + std::to_string(pressures));
  for (long i = 0; i < pressures; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(pressures - 1);
    c.pressures.push_back(i == pressures - 1 ? c.pressure_max
                                             : c.pressure_min * std::pow(c.pressure_max / c.pressure_min, t));
  }
  c.nside_at.assign(c.pressures.size(), c.nside);
  // Pressures added to the log grid (an element's low-pressure edges): a new pressure_min or count would move
  // every grid pressure, and so miss every cached sample.
  if (reader.has("grid.extra_pressures")) {
    const std::vector<double> extra = reader.numbers("grid.extra_pressures");
    for (std::size_t i = 0; i < extra.size(); ++i) {
      if (!(extra[i] > 0.0))
        reader.fail("grid.extra_pressures", fmt::format("element {}: must be a positive pressure [Pa], got {:g}", i,
                                                        extra[i]));
      for (double p : c.pressures)
        if (std::abs(extra[i] / p - 1.0) < 1e-6)
          reader.fail("grid.extra_pressures",
                      fmt::format("element {}: {:.17g} Pa is already on the grid ({:.17g} Pa); remove it", i,
                                  extra[i], p));
      c.pressures.push_back(extra[i]);
    }
    // a larger cell below the grid keeps enough summits in contact where the pressure is low
    std::vector<long> extra_nside(extra.size(), c.nside);
    if (reader.has("grid.extra_nside")) {
      if (!c.heights_file.empty())
        reader.fail("grid.extra_nside", "not with surface.heights (the summit list has surface.nside^2 summits)");
      const std::vector<double> given = reader.numbers("grid.extra_nside");
      if (given.size() != extra.size())
        reader.fail("grid.extra_nside", fmt::format("{} values for {} grid.extra_pressures: give one per pressure",
                                                    given.size(), extra.size()));
      for (std::size_t i = 0; i < given.size(); ++i) {
        if (!(given[i] >= 1.0 && given[i] <= 1000.0 && given[i] == std::floor(given[i])))
          reader.fail("grid.extra_nside",
                      fmt::format("element {}: summits per side must be a whole number in 1..1000, got {:g}", i,
                                  given[i]));
        extra_nside[i] = static_cast<long>(given[i]);
      }
    }
    c.nside_at.insert(c.nside_at.end(), extra_nside.begin(), extra_nside.end());
    std::vector<std::size_t> order(c.pressures.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.pressures[a] < c.pressures[b]; });
    std::vector<double> pressures_sorted;
    std::vector<long> nside_sorted;
    for (std::size_t i : order) {
      pressures_sorted.push_back(c.pressures[i]);
      nside_sorted.push_back(c.nside_at[i]);
    }
    c.pressures = pressures_sorted;
    c.nside_at = nside_sorted;
  } else if (reader.has("grid.extra_nside")) {
    reader.fail("grid.extra_nside", "needs grid.extra_pressures (one summit count per extra pressure)");
  }
}
}  // namespace

HomogeniseCase read_homogenise_case(const std::string &path, bool deck_given) {
  const toml::table root = parse_toml(path);
  CaseReader reader(path, root, schema());
  reader.reject_unknown_keys();
  HomogeniseCase c;
  c.path = path;
  c.title = reader.text("title", "");

  const tribo::MaterialFile materials = read_cell_materials(reader, c);

  // [surface]
  c.R = reader.positive("surface.R", c.R);
  c.sigma = reader.positive("surface.sigma", c.sigma);
  c.spacing = reader.positive("surface.spacing", c.spacing);
  if (c.sigma >= c.R) reader.fail("surface.sigma", "must be below surface.R (summit heights are a small fraction of R)");
  c.nside = reader.positive_integer("surface.nside", c.nside, 1000);
  const std::string heights = reader.text("surface.heights", "");
  if (!heights.empty()) check_summit_list(reader, find_case_file(reader, "surface.heights", heights), c);
  c.caps = reader.flag("surface.caps", false);

  // [sliding]
  c.speed = reader.positive("sliding.speed", c.speed);
  c.vertical_drag = reader.flag("sliding.vertical_drag", false);

  read_grid_pressures(reader, c);
  const long seeds = reader.positive_integer("grid.seeds", 3, 100);
  for (long j = 0; j < seeds; ++j) c.seeds.push_back(derived_seed(j));

  read_acceleration(reader, root, c);
  read_contact(reader, materials, c);
  read_wear(reader, materials, c);
  c.depth = reader.positive("grid.depth");
  if (c.depth >= c.R) reader.fail("grid.depth", "must be below surface.R");
  c.depth_points = reader.positive_integer("grid.depth_points", c.depth_points, 10000);
  if (c.depth_points < 2) reader.fail("grid.depth_points", "must be at least 2 (0 and depth)");
  if (reader.has("grid.depth_first")) {
    c.depth_first = reader.positive("grid.depth_first");
    if (!(c.depth_first < c.depth))
      reader.fail("grid.depth_first", fmt::format("must be below grid.depth = {:g}", c.depth));
    if (c.depth_points < 3)
      reader.fail("grid.depth_first", "needs grid.depth_points >= 3 (0, depth_first and depth)");
  }
  c.nslide = reader.positive_integer("grid.nslide", c.nslide, 1000000000L);
  c.nout = reader.positive_integer("grid.nout", c.nout, 1000000000L);
  if (c.nout > c.nslide) reader.fail("grid.nout", fmt::format("must be at most grid.nslide = {}", c.nslide));

  // the cell deck the case was written for (relative: beside the case file, as material.file); not looked up
  // when --deck overrides it
  const std::string deck = reader.text("deck", "");
  if (reader.has("deck") && deck.empty()) reader.fail("deck", "must not be empty");
  if (!deck.empty() && !deck_given)
    c.deck_file = fs::absolute(find_case_file(reader, "deck", deck)).lexically_normal().string();
  read_run(reader, c);
  return c;
}

std::string deck_variable(const std::string &deck_text, const std::string &name) {
  std::istringstream in(deck_text);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string command, variable, style, value;
    if (words >> command >> variable >> style >> value && command == "variable" && variable == name) return value;
  }
  return {};
}

std::string sha256_hex(const std::string &bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 failed (libcrypto)");
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

std::string file_bytes(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  std::error_code error;
  if (!in || fs::is_directory(path, error)) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw std::runtime_error("cannot read " + path.string());
  return text.str();
}

std::string lmp_physics_identity(const fs::path &lmp) {
  // beside the path given, else beside the executable a symlink names
  fs::path file = lmp.string() + ".physics";
  std::error_code error;
  if (!fs::exists(file, error)) {
    const fs::path target = fs::canonical(lmp, error);
    if (error) return {};
    file = target.string() + ".physics";
    if (!fs::exists(file, error)) return {};
  }
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const bool hex = line.size() == 64 && line.find_first_not_of("0123456789abcdef") == std::string::npos;
  if (!hex)
    throw std::runtime_error(file.string() + ": the first line is not a SHA-256 (64 hex digits); rebuild lmp_runin "
                             "(the build writes this file) or delete it to key the samples on the executable");
  return line;
}

bool Sample::complete() const {
  std::error_code error;
  return fs::is_regular_file(output(), error);
}

std::string Sample::label() const { return fmt::format("p = {:.4g} Pa, seed {}", pressure, seed); }

std::vector<Sample> plan_samples(const HomogeniseCase &c, const std::string &deck_text, const CodeIdentity &code,
                                 const fs::path &cache_dir) {
  const std::string material_sha = sha256_hex(file_bytes(c.material_file));
  const std::string deck_sha = sha256_hex(deck_text);
  nlohmann::json surface = {{"R", c.R}, {"sigma", c.sigma}, {"spacing", c.spacing}, {"nside", c.nside}};
  if (!c.heights_file.empty()) surface["heights_sha256"] = c.heights_sha256;
  // caps change the arithmetic (the centres are computed), so the last bits of a sample; absent: whole spheres
  if (c.caps) surface["caps"] = true;
  // the physics the executable was built from, not its bytes: a relink of the same sources hits the cache
  const nlohmann::json code_key =
      code.physics_sha256.empty()
          ? nlohmann::json{{"runin_version", code.runin_version}, {"lmp_sha256", code.lmp_sha256}}
          : nlohmann::json{{"runin_version", code.runin_version}, {"physics_sha256", code.physics_sha256}};
  std::vector<Sample> samples;
  for (std::size_t ip = 0; ip < c.pressures.size(); ++ip)
    for (std::size_t is = 0; is < c.seeds.size(); ++is) {
      Sample s;
      s.ip = ip;
      s.is = is;
      s.pressure = c.pressures[ip];
      s.acceleration = c.acceleration[ip];
      s.seed = c.seeds[is];
      s.nside = c.nside_at[ip];
      nlohmann::json cell = surface;
      cell["nside"] = s.nside;
      // nlohmann::json objects keep their keys sorted and dump doubles to round trip: a canonical text.
      s.inputs = {
          {"material", {{"sha256", material_sha}, {"rough", c.rough}, {"counterface", c.counterface}}},
          {"surface", cell},
          {"pressure", s.pressure},
          {"speed", c.speed},
          {"seed", s.seed},
          {"acceleration", s.acceleration},
          {"depth", c.depth},
          {"nslide", c.nslide},
          {"nout", c.nout},
          {"deck_sha256", deck_sha},
          {"code", code_key},
          {"cache_format", 2},
      };
      if (c.vertical_drag) s.inputs["vertical_drag"] = true;    // absent: the cells of laws built before it
      if (const nlohmann::json wear = c.wear_json(); !wear.is_null()) s.inputs["wear"] = wear;
      if (const nlohmann::json contact = c.contact_json(); !contact.is_null()) s.inputs["contact"] = contact;
      s.key = sha256_hex(s.inputs.dump());
      s.dir = cache_dir / s.key;
      samples.push_back(std::move(s));
    }
  return samples;
}

}  // namespace runin::cli
