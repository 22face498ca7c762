// `runin fit-feedback --input DATA.csv --t-column NAME --mu-column NAME --r-column NAME --output CASE.toml
//  [--kind lubricated|dry] [--t-scale X] [--r-scale X] [--max-rms-error E] [--title T] [--no-plot]`:
// fits the ch. 3 feedback model (coupling/feedback_fit.h) to a run-in series and writes a case file that
// `runin feedback` reads, with a [fit] provenance table, plus CASE_comparison.csv and CASE_comparison.png.
#pragma once

#include "cli/subcommand.h"

namespace runin::cli {

Subcommand add_fit_feedback_command(CLI::App &app, PlotRunner plot);

}  // namespace runin::cli
