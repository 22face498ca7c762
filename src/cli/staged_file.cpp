#include "cli/staged_file.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <fnmatch.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace runin::cli {

namespace fs = std::filesystem;

StagedFile::StagedFile(fs::path destination) : destination_(std::move(destination)) {
  // Same directory as the destination so that rename() is atomic.
  temp_ = destination_.parent_path() /
          ("." + destination_.filename().string() + ".tmp-" + std::to_string(::getpid()));
}

StagedFile::~StagedFile() {
  if (!committed_) {
    std::error_code ignored;
    fs::remove(temp_, ignored);
  }
}

void StagedFile::write(const std::string &content) {
  std::ofstream out(temp_, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + temp_.string());
}

void StagedFile::commit() {
  std::error_code error;
  fs::rename(temp_, destination_, error);
  if (error) throw std::runtime_error("cannot rename " + temp_.string() + " to " + destination_.string() + ": " +
                                      error.message());
  committed_ = true;
}

namespace {

constexpr const char *kScratch = ".scratch";

fs::path normalised(fs::path directory) {
  directory = fs::absolute(directory).lexically_normal();
  if (directory.filename().empty()) directory = directory.parent_path();  // "out/x/" -> "out/x"
  return directory;
}

void create(const fs::path &directory) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error) throw std::runtime_error("cannot create " + directory.string() + ": " + error.message());
}

// Staging directories of this process, removed by SIGINT/SIGTERM. The handler only uses async-signal-safe
// calls (fork, execv, waitpid, raise): a child runs rm -rf on each registered path, then the signal is
// re-raised with its default action so the exit status still says how the process ended.
constexpr int kMaxActive = 8;
constexpr std::size_t kPathBytes = 4096;
char active_paths[kMaxActive][kPathBytes];
volatile std::sig_atomic_t active_used[kMaxActive];

volatile std::sig_atomic_t active_child = 0;  // pid = process group of the running plot script, 0: none

extern "C" void remove_staging_and_reraise(int signal_number) {
  if (const pid_t child = static_cast<pid_t>(active_child); child > 0) {
    ::kill(-child, SIGTERM);
    ::waitpid(child, nullptr, 0);
  }
  for (int k = 0; k < kMaxActive; ++k) {
    if (!active_used[k]) continue;
    const pid_t child = ::fork();
    if (child == 0) {
      char rm[] = "rm", flags[] = "-rf", dashes[] = "--";
      char *argv[] = {rm, flags, dashes, active_paths[k], nullptr};
      ::execv("/bin/rm", argv);
      ::_exit(127);
    }
    if (child > 0) ::waitpid(child, nullptr, 0);
  }
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

int register_active(const fs::path &staging) {
  static const bool installed = [] {
    for (int signal_number : {SIGINT, SIGTERM}) ::signal(signal_number, remove_staging_and_reraise);
    return true;
  }();
  (void)installed;
  const std::string text = staging.string();
  for (int k = 0; k < kMaxActive; ++k) {
    if (active_used[k] || text.size() >= kPathBytes) continue;
    std::copy(text.begin(), text.end(), active_paths[k]);
    active_paths[k][text.size()] = '\0';
    active_used[k] = 1;
    return k;
  }
  return -1;  // more than kMaxActive at once: that one is left to the next run's stale sweep
}

void unregister_active(int slot) {
  if (slot >= 0) active_used[slot] = 0;
}

}  // namespace

void register_child(pid_t process_group) { active_child = static_cast<std::sig_atomic_t>(process_group); }
void unregister_child() { active_child = 0; }

namespace {

// ".NAME.staging-PID-N" siblings of `directory` whose process no longer exists (killed by SIGKILL, power
// loss): the next run in that directory removes them.
void remove_stale_staging(const fs::path &directory) {
  const std::string prefix = "." + directory.filename().string() + ".staging-";
  std::error_code error;
  for (const auto &entry : fs::directory_iterator(directory.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const long pid = std::strtol(rest.c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to judge
    std::error_code ignored;
    fs::remove_all(entry.path(), ignored);
  }
}

// Holds SIGINT and SIGTERM back for its lifetime: a signal during commit() would leave the output
// directory with part of the new set; held, it arrives once the set is complete.
class InterruptsHeld {
 public:
  InterruptsHeld() {
    sigset_t held;
    sigemptyset(&held);
    sigaddset(&held, SIGINT);
    sigaddset(&held, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &held, &previous_);
  }
  ~InterruptsHeld() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  InterruptsHeld(const InterruptsHeld &) = delete;
  InterruptsHeld &operator=(const InterruptsHeld &) = delete;

 private:
  sigset_t previous_;
};

// Collection files name the frames; move them after the frames so that they never point at nothing.
bool is_index(const fs::path &p) { return p.extension() == ".pvd"; }

}  // namespace

StagedOutput::StagedOutput(fs::path directory, std::vector<std::string> owned)
    : directory_(normalised(std::move(directory))), owned_(std::move(owned)) {
  static std::atomic<int> counter{0};
  // A sibling of the output directory: same file system, so every commit step is a rename.
  create(directory_.parent_path());
  remove_stale_staging(directory_);
  staging_ = directory_.parent_path() / ("." + directory_.filename().string() + ".staging-" +
                                         std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::error_code error;
  fs::remove_all(staging_, error);
  signal_slot_ = register_active(staging_);
  create(staging_ / kScratch);
}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  unregister_active(signal_slot_);
}

fs::path StagedOutput::file(const std::string &name) const {
  const fs::path p = staging_ / name;
  create(p.parent_path());
  return p;
}

fs::path StagedOutput::scratch(const std::string &name) const { return staging_ / kScratch / name; }

namespace {
bool non_finite_token(std::string token) {
  for (char &c : token) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!token.empty() && (token[0] == '-' || token[0] == '+')) token.erase(0, 1);
  return token == "nan" || token == "inf" || token == "infinity";
}

// A solver that produced NaN or inf must not leave a plausible-looking file behind: the run stops here
// (the staging directory is removed, nothing is committed), naming the file, row and column.
void check_finite_csv(const std::string &name, const std::string &content) {
  std::istringstream lines(content);
  std::string line, header;
  for (std::size_t row = 0; std::getline(lines, line); ++row) {
    if (row == 0) header = line;
    std::istringstream cells(line);
    std::string cell;
    for (std::size_t column = 0; std::getline(cells, cell, ','); ++column) {
      const auto first = cell.find_first_not_of(" \t\r"), last = cell.find_last_not_of(" \t\r");
      if (first == std::string::npos || !non_finite_token(cell.substr(first, last - first + 1))) continue;
      std::istringstream names(header);
      std::string column_name = "column " + std::to_string(column + 1);
      for (std::size_t k = 0; std::getline(names, cell, ',') && k <= column; ++k)
        if (k == column) column_name = "'" + cell + "'";
      throw std::runtime_error(name + ": non-finite value in row " + std::to_string(row) + ", " + column_name +
                               ": the solution diverged; no output was written (check the case's parameters)");
    }
  }
}

}  // namespace

void StagedOutput::write(const std::string &name, const std::string &content) const {
  if (fs::path(name).extension() == ".csv") check_finite_csv(name, content);
  const fs::path p = file(name);
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();
  if (!out) throw std::runtime_error("cannot write " + destination(name).string());
}

fs::path StagedOutput::destination_of(const fs::path &staged) const {
  return directory_ / fs::path(staged).lexically_relative(staging_);
}

std::vector<fs::path> StagedOutput::commit() {
  if (committed_) throw std::logic_error("StagedOutput::commit called twice");
  std::vector<fs::path> staged;  // relative to staging_
  for (auto it = fs::recursive_directory_iterator(staging_); it != fs::recursive_directory_iterator(); ++it) {
    if (it->is_directory() && it->path().filename() == kScratch) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file()) staged.push_back(it->path().lexically_relative(staging_));
  }
  std::stable_partition(staged.begin(), staged.end(), [](const fs::path &p) { return !is_index(p); });

  const InterruptsHeld held;
  std::vector<fs::path> committed;
  for (const auto &relative : staged) {
    const fs::path to = directory_ / relative;
    create(to.parent_path());
    std::error_code error;
    fs::rename(staging_ / relative, to, error);
    if (error) throw std::runtime_error("cannot move " + (staging_ / relative).string() + " to " + to.string() + ": " +
                                        error.message());
    committed.push_back(to);
  }
  // Owned files of an earlier run that this run did not write (e.g. its extra VTK frames).
  std::vector<fs::path> stale;
  for (auto it = fs::recursive_directory_iterator(directory_); it != fs::recursive_directory_iterator(); ++it) {
    if (!it->is_regular_file() && !it->is_symlink()) continue;
    const std::string relative = it->path().lexically_relative(directory_).generic_string();
    const bool owned = std::any_of(owned_.begin(), owned_.end(), [&](const std::string &pattern) {
      return ::fnmatch(pattern.c_str(), relative.c_str(), FNM_PATHNAME) == 0;
    });
    if (owned && std::find(staged.begin(), staged.end(), fs::path(relative)) == staged.end())
      stale.push_back(it->path());
  }
  for (const auto &p : stale) {
    std::error_code error;
    fs::remove(p, error);
    if (error) throw std::runtime_error("cannot remove the earlier run's " + p.string() + ": " + error.message());
  }
  committed_ = true;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  return committed;
}

}  // namespace runin::cli
