// One run's key numbers, as every machine-element command writes them (<element>_summary.csv, one row)
// and as `runin sweep` reads them back.
#pragma once

#include <string>

#include <fmt/core.h>

namespace runin::cli {

struct RunSummary {
  double peak_friction_force = 0.0, peak_time = 0.0;
  double breakaway_time = -1.0;  // < 0: never broke away within the run
  double steady_time = -1.0;     // < 0: not steady within the run
  double steady_mu = 0.0, wear_volume = 0.0;
};

inline constexpr const char *kRunSummaryHeader =
    "peak_friction_force_N,peak_time_s,breakaway_time_s,steady_time_s,steady_mu,wear_volume_m3";

// A time that was not reached is an empty cell, not a number a reader could take for a time.
inline std::string time_cell(double t) { return t < 0.0 ? std::string() : fmt::format("{:.12g}", t); }

inline std::string run_summary_row(const RunSummary &s) {
  return fmt::format("{:.12g},{:.12g},{},{},{:.12g},{:.12g}", s.peak_friction_force, s.peak_time,
                     time_cell(s.breakaway_time), time_cell(s.steady_time), s.steady_mu, s.wear_volume);
}

}  // namespace runin::cli
