// `runin piston-ring CASE.toml --output-dir DIR [--law FILE] [--no-plot]` (thesis ch. 6).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace runin::cli {

struct PistonRingCommand {
  CLI::App *app = nullptr;
  std::function<int()> run;  // call when app->parsed(); throws InputError on bad input
};

// plot(script in tools/, arguments) runs a plotting script and throws on failure.
using PistonRingPlotter = std::function<void(const std::string &, const std::vector<std::string> &)>;

PistonRingCommand add_piston_ring_command(CLI::App &app, PistonRingPlotter plot);

}  // namespace runin::cli
