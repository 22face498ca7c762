#include "cli/child_process.h"

#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace runin::cli {

pid_t start_child(const std::vector<std::string> &args, const ChildStreams &streams,
                  const std::vector<std::string> &environment) {
  std::vector<std::string> arg_text = args, env_text = environment;
  std::vector<char *> argv, envp;
  for (auto &a : arg_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (auto &e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, streams.stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  if (streams.stderr_file)
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, streams.stderr_file->c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
  else
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  // POSIX has no chdir action before POSIX.1-2024; glibc has had the _np one since 2.29
  if (streams.working_directory) posix_spawn_file_actions_addchdir_np(&actions, streams.working_directory->c_str());
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args.front().c_str(), &actions, nullptr, argv.data(),
                              environment.empty() ? environ : envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + args.front());
  return pid;
}

namespace {
int exit_status(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }
}  // namespace

std::optional<int> poll_child(pid_t pid) {
  int status = 0;
  const pid_t done = waitpid(pid, &status, WNOHANG);
  if (done == 0) return std::nullopt;
  if (done < 0) return 255;
  return exit_status(status);
}

int wait_child(pid_t pid) {
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return 255;
  return exit_status(status);
}

std::string last_line(const std::filesystem::path &file) {
  std::ifstream in(file);
  std::string last;
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last;
}

}  // namespace runin::cli
