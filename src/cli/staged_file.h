// Atomic output: write to a temporary file in the destination's directory, then rename.
#pragma once

#include <filesystem>
#include <string>

namespace runin::cli {

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

}  // namespace runin::cli
