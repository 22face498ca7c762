// What the machine-element subcommands share with main: their registration and the plot runner.
#pragma once

#include <filesystem>
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

// For --output-dir: non-empty, and not an existing file (a directory, or a path still to be created).
inline const CLI::Validator &output_directory() {
  static const CLI::Validator check(
      [](std::string &value) {
        if (value.empty()) return std::string("must not be empty");
        std::error_code error;
        if (std::filesystem::exists(value, error) && !std::filesystem::is_directory(value, error))
          return "'" + value + "' is an existing file, not a directory (name a directory, or a path to create)";
        return std::string();
      },
      "DIR");
  return check;
}

struct Subcommand {
  CLI::App *app = nullptr;
  std::function<int()> run;  // call when app->parsed(); throws InputError on bad input
};

}  // namespace runin::cli
