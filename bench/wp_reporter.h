// Shared by the bench/wp_*.cpp work-precision programs: Google Benchmark times each (method, setting)
// configuration; this reporter prints the usual console table and keeps, per benchmark name, the
// median wall time and the user counters (rel_error, steps, ...) so each program can write its CSV.
#pragma once

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <unistd.h>
#include <vector>

namespace runin::bench {

struct Median {
  double seconds = 0.0;  // median over the repetitions of the wall time per iteration
  long repetitions = 1;  // how many repetitions the median is taken over
  std::map<std::string, double> counters;
  double counter(const std::string &name) const {
    const auto it = counters.find(name);
    return it == counters.end() ? 0.0 : it->second;
  }
};

class MedianReporter : public benchmark::ConsoleReporter {
 public:
  // Colour only on a terminal, so that redirected logs stay plain text.
  MedianReporter() : ConsoleReporter(isatty(fileno(stdout)) ? OO_ColorTabular : OO_Tabular) {}
  void ReportRuns(const std::vector<Run> &runs) override {
    for (const Run &run : runs) {
      if (run.error_occurred) continue;
      const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
      const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
      if (!median && !single) continue;
      Median &m = results_[run.run_name.function_name];
      m.seconds = run.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(run.time_unit);
      m.repetitions = run.repetitions;
      for (const auto &[name, c] : run.counters) m.counters[name] = c.value;
    }
    ConsoleReporter::ReportRuns(runs);
  }
  // nullptr when the benchmark did not run (e.g. excluded by --benchmark_filter).
  const Median *find(const std::string &name) const {
    const auto it = results_.find(name);
    return it == results_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, Median> results_;
};

// Wall time in ms, median of `repetitions`. Fast solves: Google Benchmark picks the iteration count
// to fill `min_time` seconds per repetition.
inline benchmark::internal::Benchmark *timed(benchmark::internal::Benchmark *b, int repetitions = 5,
                                             double min_time = 0.1) {
  return b->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->MinTime(min_time)
      ->Repetitions(repetitions)
      ->ReportAggregatesOnly(true);
}
// Slow runs (fine fixed-step baselines, long wear runs): one solve per repetition.
inline benchmark::internal::Benchmark *timed_once(benchmark::internal::Benchmark *b, int repetitions = 3) {
  return b->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(1)
      ->Repetitions(repetitions)
      ->ReportAggregatesOnly(true);
}

// Benchmark name of one configuration, e.g. "cvode_bdf/1e-06" (%g keeps the settings distinct).
inline std::string label(const std::string &method, double setting) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", setting);
  return method + "/" + buffer;
}

// benchmark::Initialize strips --benchmark_* flags; the first remaining argument (if any) is the output.
// Without one, `default_output` goes under the build tree's bench/out (never the caller's cwd: a run from
// the source root would leave its CSVs there).
inline std::string initialize(int &argc, char **argv, const std::string &default_output) {
  benchmark::Initialize(&argc, argv);
  if (argc > 1) return argv[1];
  if (default_output.empty()) return default_output;
  std::filesystem::create_directories(RUNIN_BENCH_OUTPUT_DIR);
  return (std::filesystem::path(RUNIN_BENCH_OUTPUT_DIR) / default_output).lexically_normal().string();
}

// One configuration of a single-case work-precision diagram (feedback model, pin-on-disk).
struct WorkPrecisionRow {
  std::string name, method;  // benchmark name (label(method, setting)) and method
  double setting;            // tolerance or fixed step
};

// The CSV read by tools/plot_wp.py: method,setting,rel_error,wall_time_s,steps (configurations that
// did not run are left out). False, with the reason on stderr, if the file cannot be written.
inline bool write_work_precision_csv(const std::string &path, const std::vector<WorkPrecisionRow> &rows,
                                     const MedianReporter &reporter) {
  FILE *csv = std::fopen(path.c_str(), "w");
  if (!csv) {
    std::perror(path.c_str());
    return false;
  }
  std::fprintf(csv, "method,setting,rel_error,wall_time_s,steps\n");
  for (const WorkPrecisionRow &row : rows)
    if (const Median *m = reporter.find(row.name))
      std::fprintf(csv, "%s,%g,%.6e,%.6e,%ld\n", row.method.c_str(), row.setting, m->counter("rel_error"), m->seconds,
                   std::lround(m->counter("steps")));
  return std::fclose(csv) == 0;
}

inline void run_benchmarks(MedianReporter &reporter) {
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
}

}  // namespace runin::bench
