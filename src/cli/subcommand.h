// What the machine-element subcommands share with main: their registration and the plot runner.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace runin::cli {

// Runs tools/<script> with the configured python and the arguments; throws on failure.
using PlotRunner = std::function<void(const std::string &script, const std::vector<std::string> &args)>;

struct Subcommand {
  CLI::App *app = nullptr;
  std::function<int()> run;  // call when app->parsed(); throws InputError on bad input
};

}  // namespace runin::cli
