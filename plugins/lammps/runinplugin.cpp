// runinplugin.so: the file a LAMMPS built with PKG_PLUGIN loads ('plugin load runinplugin.so', or
// LAMMPS_PLUGIN_PATH). It is a loader that uses no LAMMPS C++ symbol, so it opens in any LAMMPS release; it checks
// that the host is the release of the headers the styles were built for, and only then opens the styles
// (runin_styles.so, next to it) and registers them. A styles library built for another release would not even
// open there (its C++ symbols differ: "undefined symbol: _ZN9LAMMPS_NS5Error..."), and LAMMPS would only log that.
#include <dlfcn.h>

#include <cstdio>
#include <string>

namespace {
const char *const kStylesLibrary = "runin_styles.so";

// LAMMPS's C library API, looked up at run time: lammps_version in every release, lammps_error since 2023.
int host_version(void *lmp)
{
  using VersionFunction = int (*)(void *);
  auto version = reinterpret_cast<VersionFunction>(dlsym(RTLD_DEFAULT, "lammps_version"));
  return version ? version(lmp) : -1;
}

// One ERROR line, and the deck stops: through lammps_error where the host has it (2023+); before, printed by the
// host's 'print' (screen and log file) and ended by its 'quit 1' (every rank runs this, as 'quit' needs).
void refuse(void *lmp, const std::string &message)
{
  using ErrorFunction = void (*)(void *, int, const char *);
  using CommandFunction = char *(*)(void *, const char *);
  if (auto error = reinterpret_cast<ErrorFunction>(dlsym(RTLD_DEFAULT, "lammps_error"))) error(lmp, 2, message.c_str());
  if (auto command = reinterpret_cast<CommandFunction>(dlsym(RTLD_DEFAULT, "lammps_command"))) {
    command(lmp, ("print \"ERROR: " + message + "\"").c_str());
    command(lmp, "quit 1");
  }
  fprintf(stderr, "ERROR: %s\n", message.c_str());
}

std::string version_mismatch(int built_for, int host)
{
  return "runinplugin.so was built for LAMMPS " + std::to_string(built_for) + " headers but is loaded into LAMMPS " +
         std::to_string(host) +
         "; rebuild RunIn with -DRUNIN_LAMMPS_SOURCE_DIR=<this LAMMPS's src> -DRUNIN_LAMMPS_LIBRARY=<its liblammps> "
         "(doc/lammps_versions.md)";
}

// The directory of this loader (dladdr of one of its functions), with a trailing '/', or "" if unknown.
std::string own_directory()
{
  Dl_info info;
  if (!dladdr(reinterpret_cast<void *>(&host_version), &info) || !info.dli_fname) return "";
  const std::string path = info.dli_fname;
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}
}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  // The styles are compiled against one release's headers (RUNIN_PLUGIN_HEADER_VERSION, yyyymmdd from CMake);
  // LAMMPS's classes change layout between releases, so they must not run in another.
  const int host = host_version(lmp);
  if (host != RUNIN_PLUGIN_HEADER_VERSION) return refuse(lmp, version_mismatch(RUNIN_PLUGIN_HEADER_VERSION, host));

  const std::string path = own_directory() + kStylesLibrary;
  void *styles = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!styles) {
    const char *why = dlerror();
    return refuse(lmp, "runinplugin.so: cannot load its styles library " + path + ": " + (why ? why : "?") +
                           "; build the target runinplugin (it builds both files) and keep them in one directory");
  }
  using VersionFunction = int (*)();
  using RegisterFunction = void (*)(void *, void *, void *);
  auto styles_version = reinterpret_cast<VersionFunction>(dlsym(styles, "runin_styles_lammps_version"));
  auto register_styles = reinterpret_cast<RegisterFunction>(dlsym(styles, "runin_styles_register"));
  if (!styles_version || !register_styles)
    return refuse(lmp, "runinplugin.so: " + path + " is not a RunIn styles library; rebuild the target runinplugin");
  // a styles library from another build next to this loader
  if (styles_version() != host) return refuse(lmp, "runinplugin.so: " + path + ": " +
                                                       version_mismatch(styles_version(), host));
  register_styles(lmp, handle, regfunc);
}
