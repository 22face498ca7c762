#include "cli/python_plot.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>

#include "cli/staged_file.h"  // register_child

extern char **environ;

namespace runin::cli {

void run_python_plot(const std::string &script_name, const std::vector<std::string> &script_args) {
  const char *python_env = std::getenv("RUNIN_PYTHON");
  const std::string python = python_env && *python_env ? python_env : RUNIN_DEFAULT_PYTHON;
  const std::string script = std::string(RUNIN_SOURCE_DIR) + "/tools/" + script_name;
  std::vector<std::string> args = {python, script};
  args.insert(args.end(), script_args.begin(), script_args.end());
  std::vector<char *> argv;
  for (auto &a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // Its own process group, registered with SIGINT/SIGTERM held back: a signal to runin stops the script (and
  // whatever it started) before the staging directory it writes into is removed.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, held, previous;
  sigemptyset(&none);
  sigemptyset(&held);
  sigaddset(&held, SIGINT);
  sigaddset(&held, SIGTERM);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  pthread_sigmask(SIG_BLOCK, &held, &previous);
  pid_t pid = 0;
  const int started = posix_spawnp(&pid, python.c_str(), nullptr, &attr, argv.data(), environ);
  if (started == 0) register_child(pid);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  posix_spawnattr_destroy(&attr);
  if (started != 0) throw std::runtime_error("cannot start " + python + " for the plot (set RUNIN_PYTHON or use --no-plot)");
  int status = 0;
  pid_t waited = 0;
  while ((waited = waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
  }
  unregister_child();
  if (waited < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("plotting failed: " + python + " " + script + " (use --no-plot to skip)");
}

}  // namespace runin::cli
