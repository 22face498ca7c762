// lmp_runin: Debian's LAMMPS library with the RunIn styles registered before input is read.
// Usage is that of lmp: mpirun -np 2 lmp_runin -in in.deck
#include "runin_styles.h"

#include "error.h"
#include "exceptions.h"
#include "input.h"
#include "lammps.h"
#include "plugin.h"

#include <dlfcn.h>
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
// LAMMPS's plugin command, except that 'plugin load FILE' of a file that cannot be loaded is an ERROR:
// LAMMPS only logs "Open of file ... failed" and goes on, and the deck then stops later at the first style
// the plugin should have brought, far from the cause.
class CheckedPlugin : public Plugin {
 public:
  using Plugin::Plugin;
  void command(int narg, char **arg) override
  {
    if (narg >= 2 && strcmp(arg[0], "load") == 0) {
      void *handle = dlopen(arg[1], RTLD_NOW | RTLD_GLOBAL);
      if (!handle) error->all(FLERR, std::string("plugin load: cannot load '") + arg[1] + "': " + dlerror());
      dlclose(handle);
    }
    Plugin::command(narg, arg);
  }
};

Command *plugin_command(LAMMPS *lmp)
{
  return new CheckedPlugin(lmp);
}
}    // namespace

// 'clear' destroys the style maps and builds them anew, then calls post_create(), as the constructor does.
// lmp_runin defines post_create(): the library's own, then the RunIn styles again, so decks that 'clear'
// (parameter loops, restart round trips) keep them. The library calls post_create() through its PLT, so this
// definition takes precedence; a library bound otherwise simply keeps calling its own (the styles then
// stay registered from main() only, until a 'clear').
void LAMMPS_NS::LAMMPS::post_create()
{
  using PostCreate = void (*)(LAMMPS *);
  static const auto library = reinterpret_cast<PostCreate>(dlsym(RTLD_NEXT, "_ZN9LAMMPS_NS6LAMMPS11post_createEv"));
  if (library) library(this);
  if (force && modify) runin_lammps::register_styles(this);
}

namespace {
void run(int argc, char **argv, bool help);
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);

  // LAMMPS answers -h inside its constructor, before our styles exist: answer it here instead.
  bool help = false;
  std::vector<char *> args;
  for (int i = 0; i < argc; i++) {
    if (i > 0 && (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "-help") == 0))
      help = true;
    else
      args.push_back(argv[i]);
  }
  if (help) {
    static char log_flag[] = "-log", none[] = "none";
    args.push_back(log_flag);
    args.push_back(none);
  }
  args.push_back(nullptr);

  // As LAMMPS's own main: a library built with exceptions (every release since 2023) throws on ERROR after
  // printing it; without a catch the process would end in std::terminate (SIGABRT).
  try {
    run(static_cast<int>(args.size()) - 1, args.data(), help);
  } catch (const LAMMPSAbortException &) {    // error->one: the other ranks do not know
    MPI_Abort(MPI_COMM_WORLD, 1);
  } catch (const LAMMPSException &) {         // error->all: every rank is here, the message is printed
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Finalize();
    return 1;
  } catch (const std::exception &e) {
    fprintf(stderr, "ERROR: lmp_runin: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return 0;
}

namespace {
void run(int argc, char **argv, bool help)
{
  auto *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  runin_lammps::register_styles(lmp);
  (*lmp->input->command_map)["plugin"] = &plugin_command;

  if (help) {
    int me = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &me);
    if (me == 0) {
      printf("\nlmp_runin: LAMMPS with the RunIn styles. Usage as lmp, e.g. mpirun -np 2 lmp_runin -in in.deck\n"
             "RunIn styles:\n");
      for (const auto &style : runin_lammps::styles())
        printf("  %-8s %-20s %s\n", style.kind, style.name, style.info);
      printf("\nAll styles of this executable:\n");
    }
    lmp->input->one("info styles");
  } else {
    lmp->input->file();
  }
  delete lmp;
}
}    // namespace
