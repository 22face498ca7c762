// `runin feedback CASE.toml --output-dir DIR [--no-plot]`: the thesis's ch. 3 roughness-feedback model R(t), mu(t)
// (continuum/feedback_system.h), with an optional one-parameter sweep; a case written by `runin fit-feedback` too.
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_feedback_command(CLI::App &app, PlotRunner plot);

}  // namespace runin::cli
