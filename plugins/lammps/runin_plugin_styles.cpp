// runin_styles.so: the RunIn styles behind a C entry point, opened by the loader runinplugin.so (runinplugin.cpp)
// once it has checked that the host LAMMPS is the release of these headers. Built against one release's headers,
// this library needs that release's C++ symbols; loading it into another would fail in dlopen, or worse, run.
#include "runin_styles.h"

#include "lammpsplugin.h"
#include "version.h"

// The header release this library was built for (yyyymmdd), for the loader's second check.
extern "C" int runin_styles_lammps_version()
{
  return RUNIN_PLUGIN_HEADER_VERSION;
}

// As lammpsplugin_init: registers every RunIn style with `regfunc`, under the loader's `handle`.
extern "C" void runin_styles_register(void *lmp, void *handle, void *regfunc)
{
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
