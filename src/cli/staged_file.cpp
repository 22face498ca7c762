#include "cli/staged_file.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fnmatch.h>
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

// Collection files name the frames; move them after the frames so that they never point at nothing.
bool is_index(const fs::path &p) { return p.extension() == ".pvd"; }

}  // namespace

StagedOutput::StagedOutput(fs::path directory, std::vector<std::string> owned)
    : directory_(normalised(std::move(directory))), owned_(std::move(owned)) {
  static std::atomic<int> counter{0};
  // A sibling of the output directory: same file system, so every commit step is a rename.
  create(directory_.parent_path());
  staging_ = directory_.parent_path() / ("." + directory_.filename().string() + ".staging-" +
                                         std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::error_code error;
  fs::remove_all(staging_, error);
  create(staging_ / kScratch);
}

StagedOutput::~StagedOutput() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

fs::path StagedOutput::file(const std::string &name) const {
  const fs::path p = staging_ / name;
  create(p.parent_path());
  return p;
}

fs::path StagedOutput::scratch(const std::string &name) const { return staging_ / kScratch / name; }

void StagedOutput::write(const std::string &name, const std::string &content) const {
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
