// runinplugin.so: the RunIn styles for a LAMMPS built with PKG_PLUGIN (plugin load runinplugin.so).
#include "runin_styles.h"

#include "lammpsplugin.h"
#include "version.h"

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
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
