// What the machine-element subcommands share with main: their registration and the plot runner.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace runin::cli {

// Runs tools/<script> with the configured python and the arguments; throws on failure.
using PlotRunner = std::function<void(const std::string &script, const std::vector<std::string> &args)>;

// For --output-dir and other path options: an empty path names no directory.
inline const CLI::Validator &non_empty_path() {
  static const CLI::Validator check(
      [](std::string &value) { return value.empty() ? std::string("must not be empty") : std::string(); },
      "PATH");
  return check;
}

struct Subcommand {
  CLI::App *app = nullptr;
  std::function<int()> run;  // call when app->parsed(); throws InputError on bad input
};

}  // namespace runin::cli
