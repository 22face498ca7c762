// tools/<script> run with the configured python for a subcommand's plots (the PlotRunner of subcommand.h).
#pragma once

#include <string>
#include <vector>

namespace runin::cli {

// /usr/bin/python3 (or $RUNIN_PYTHON) tools/<script_name> script_args...; in its own process group, stopped with
// runin on SIGINT/SIGTERM. Throws std::runtime_error (exit 1) if it cannot start or fails.
void run_python_plot(const std::string &script_name, const std::vector<std::string> &script_args);

}  // namespace runin::cli
