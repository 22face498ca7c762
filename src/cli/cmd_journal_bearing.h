// `runin journal-bearing CASE.toml --output-dir DIR [--law FILE] [--no-plot]` (thesis ch. 5).
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace runin::cli {

struct Subcommand {
  CLI::App *app = nullptr;
  std::function<int()> run;  // call when app->parsed(); throws InputError on bad input
};

Subcommand add_journal_bearing_command(CLI::App &app);

}  // namespace runin::cli
