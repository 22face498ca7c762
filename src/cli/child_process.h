// Child processes of the CLI (runin sweep runs this runin per case, runin homogenise runs mpirun): start with
// redirected standard streams, poll or wait for the exit status, read a log's last line.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace runin::cli {

struct ChildStreams {
  std::filesystem::path stdout_file = "/dev/null";  // truncated
  std::optional<std::filesystem::path> stderr_file;  // truncated; none: stderr goes where stdout goes
  std::optional<std::filesystem::path> working_directory;
};

// Starts `args` (args[0] searched on PATH) with stdin from /dev/null and `environment` ("NAME=value"; empty: this
// process's environment). Throws std::runtime_error naming args[0] if it cannot start.
pid_t start_child(const std::vector<std::string> &args, const ChildStreams &streams,
                  const std::vector<std::string> &environment = {});

// Exit status (128 + signal for a signal) once the child has ended, nullopt while it runs.
std::optional<int> poll_child(pid_t pid);
int wait_child(pid_t pid);

// The last line of `file` with other than blanks, or "".
std::string last_line(const std::filesystem::path &file);

}  // namespace runin::cli
