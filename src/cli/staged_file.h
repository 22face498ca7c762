// Atomic output.
//   StagedFile: one file, written to a temporary name in the destination's directory, then renamed.
//   StagedOutput: a run's whole output set (CSV, PNG, VTK series), written into a temporary sibling
//   of the output directory and moved in only by commit(), after everything succeeded. commit()
//   also removes the files an earlier run of the same subcommand left (its `owned` patterns), so
//   the directory never mixes runs. Without commit() the staging directory is removed and the
//   output directory keeps its previous complete contents (or does not exist).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <sys/types.h>

namespace runin::cli {

// The running child (a plot script) of this process, if any: SIGINT/SIGTERM stop its process group with SIGTERM and
// reap it before the staging directories are removed, so it cannot write into a removed directory. Register it
// with those signals blocked (between the start and the registration).
void register_child(pid_t process_group);
void unregister_child();

class StagedFile {
 public:
  explicit StagedFile(std::filesystem::path destination);
  ~StagedFile();  // removes the temporary file unless committed
  StagedFile(const StagedFile &) = delete;
  StagedFile &operator=(const StagedFile &) = delete;

  const std::filesystem::path &temp_path() const { return temp_; }
  const std::filesystem::path &destination() const { return destination_; }
  void write(const std::string &content);  // throws std::runtime_error
  void commit();                           // rename over the destination

 private:
  std::filesystem::path destination_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

class StagedOutput {
 public:
  // `owned`: glob patterns (fnmatch, relative to `directory`, e.g. "pin_face_*.vts") matching every
  // file this subcommand may write. Creates the staging directory (and the parent of `directory`).
  StagedOutput(std::filesystem::path directory, std::vector<std::string> owned);
  ~StagedOutput();  // removes the staging directory unless committed
  StagedOutput(const StagedOutput &) = delete;
  StagedOutput &operator=(const StagedOutput &) = delete;

  // Staged path of directory/name (subdirectories created); committed with the rest.
  std::filesystem::path file(const std::string &name) const;
  // Staged path of a helper file (e.g. a plot input) that is never committed.
  std::filesystem::path scratch(const std::string &name) const;
  void write(const std::string &name, const std::string &content) const;  // throws std::runtime_error
  std::filesystem::path destination(const std::string &name) const { return directory_ / name; }
  const std::filesystem::path &staging() const { return staging_; }
  // Final path of a path inside the staging directory (e.g. one returned by a VTK writer).
  std::filesystem::path destination_of(const std::filesystem::path &staged) const;

  // Moves every staged file into place (series indices such as .pvd last), then removes the
  // owned files of earlier runs that this run did not write. Returns the committed paths.
  std::vector<std::filesystem::path> commit();

 private:
  std::filesystem::path directory_, staging_;
  std::vector<std::string> owned_;
  bool committed_ = false;
  int signal_slot_ = -1;  // its entry in the SIGINT/SIGTERM cleanup list
};

}  // namespace runin::cli
