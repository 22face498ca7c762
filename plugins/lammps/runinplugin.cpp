// runinplugin.so: the RunIn styles for a LAMMPS built with PKG_PLUGIN (plugin load runinplugin.so).
#include "runin_styles.h"

#include "library.h"
#include "lammpsplugin.h"
#include "version.h"

#include <dlfcn.h>

#include <cstdio>
#include <string>

namespace {
// The styles are compiled against one release's headers (RUNIN_PLUGIN_HEADER_VERSION, yyyymmdd from CMake);
// LAMMPS's classes change layout between releases, so a plugin loaded into another release would run on
// wrong offsets. LAMMPS itself only notes the difference; here it is an ERROR and nothing is registered.
bool host_matches_headers(void *lmp)
{
  const int host = lammps_version(lmp);
  if (host == RUNIN_PLUGIN_HEADER_VERSION) return true;
  const std::string message = "runinplugin.so was built for LAMMPS " + std::to_string(RUNIN_PLUGIN_HEADER_VERSION) +
      " headers but is loaded into LAMMPS " + std::to_string(host) +
      "; rebuild RunIn with -DRUNIN_LAMMPS_SOURCE_DIR=<this LAMMPS's src> -DRUNIN_LAMMPS_LIBRARY=<its liblammps>";
  // lammps_error (LAMMPS 2023+) raises a proper ERROR; it is looked up at run time so that an older host
  // still loads this file and gets the message
  using ErrorFunction = void (*)(void *, int, const char *);
  if (auto error = reinterpret_cast<ErrorFunction>(dlsym(RTLD_DEFAULT, "lammps_error"))) error(lmp, 2, message.c_str());
  fprintf(stderr, "ERROR: %s\n", message.c_str());
  return false;
}
}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  if (!host_matches_headers(lmp)) return;
  auto register_plugin = reinterpret_cast<lammpsplugin_regfunc>(regfunc);
  for (const auto &style : runin_lammps::styles()) {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = style.kind;
    plugin.name = style.name;
    plugin.info = style.info;
    plugin.author = "RunIn developers";
    if (style.create_pair)
      plugin.creator.v1 = reinterpret_cast<lammpsplugin_factory1 *>(style.create_pair);
    else
      plugin.creator.v2 = reinterpret_cast<lammpsplugin_factory2 *>(style.create_fix_or_compute);
    plugin.handle = handle;
    (*register_plugin)(&plugin, lmp);
  }
}
