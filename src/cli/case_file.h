// Reading and validating a pin-on-disk case file (TOML).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "continuum/pin_on_disk.h"
#include "coupling/friction_law.h"

namespace runin::cli {

// Bad input: the CLI prints "runin: error: <what()>" and exits with code 2.
// Case-file messages read "<file>: key 'section.key': <problem>".
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct PinOnDiskCase {
  std::string path;
  std::string title;
  continuum::PinOnDiskParameters parameters;  // applied_torque resolved (eq. 4.11 if targeted)
  continuum::PinOnDiskRun run;
  std::optional<continuum::SlidingFriction> friction;
  std::string torque_origin;  // how applied_torque was obtained, for the summary
};

// `law_path` is the --law option; required exactly when friction.model = "law_file".
PinOnDiskCase read_pin_on_disk_case(const std::string &path, const std::optional<std::string> &law_path);

}  // namespace runin::cli
