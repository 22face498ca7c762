#include "cli/staged_file.h"

#include <fstream>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace runin::cli {

StagedFile::StagedFile(std::filesystem::path destination) : destination_(std::move(destination)) {
  // Same directory as the destination so that rename() is atomic.
  temp_ = destination_.parent_path() /
          ("." + destination_.filename().string() + ".tmp-" + std::to_string(::getpid()));
}

StagedFile::~StagedFile() {
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
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
  std::filesystem::rename(temp_, destination_, error);
  if (error) throw std::runtime_error("cannot rename " + temp_.string() + " to " + destination_.string() + ": " +
                                      error.message());
  committed_ = true;
}

}  // namespace runin::cli
