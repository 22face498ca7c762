// Where a coefficient file named in a deck is looked for (host-neutral: the LAMMPS and LIGGGHTS hosts share it).
// LAMMPS's convention (utils::open_potential): the path as given, then each directory of $LAMMPS_POTENTIALS
// (':'-separated). LAMMPS joins only the file's base name to the directory; here the relative path as given is
// tried first, so 'file potentials/CuAl.runin' also works with LAMMPS_POTENTIALS set to the directory above.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace runin_lammps {

struct PotentialSearch {
  std::string found;                // the readable path, or empty
  std::vector<std::string> tried;   // every place looked, in order
  bool environment_set = false;     // whether $LAMMPS_POTENTIALS was set (and not empty)

  // "cannot open coefficient file 'X' (looked in: a, b, c)" with a hint when $LAMMPS_POTENTIALS is not set
  std::string message(const std::string &name) const
  {
    std::string places;
    for (const auto &place : tried) places += (places.empty() ? "" : ", ") + place;
    std::string text = "cannot open coefficient file '" + name + "' (looked in: " + places + ")";
    if (!environment_set && (name.empty() || name[0] != '/'))
      text += "; $LAMMPS_POTENTIALS is not set (a ':'-separated list of directories to search)";
    return text;
  }
};

inline bool readable_file(const std::string &path)
{
  FILE *fp = std::fopen(path.c_str(), "r");
  if (!fp) return false;
  std::fclose(fp);
  return true;
}

// `environment`: the value of $LAMMPS_POTENTIALS (nullptr: not set).
inline PotentialSearch find_potential_file(const std::string &name, const char *environment)
{
  PotentialSearch search;
  auto try_path = [&](const std::string &path) {
    for (const auto &seen : search.tried)
      if (seen == path) return false;
    search.tried.push_back(path);
    if (!readable_file(path)) return false;
    search.found = path;
    return true;
  };
  search.environment_set = environment && *environment;
  if (try_path(name) || name.empty() || name[0] == '/' || !search.environment_set) return search;
  const std::string dirs = environment;
  const std::string base = name.substr(name.find_last_of('/') == std::string::npos ? 0 : name.find_last_of('/') + 1);
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    std::string dir = dirs.substr(start, end - start);
    start = end + 1;
    if (dir.empty()) continue;
    if (dir.back() != '/') dir += '/';
    if (try_path(dir + name) || try_path(dir + base)) return search;
  }
  return search;
}

inline PotentialSearch find_potential_file(const std::string &name)
{
  return find_potential_file(name, std::getenv("LAMMPS_POTENTIALS"));
}

}    // namespace runin_lammps
