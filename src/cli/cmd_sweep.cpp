#include "cli/child_process.h"
#include "cli/cmd_sweep.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/core.h>
#include <toml++/toml.h>

#include "cli/case_file.h"
#include "cli/case_reader.h"
#include "cli/run_summary.h"
#include "cli/staged_file.h"


namespace runin::cli {
namespace {

namespace fs = std::filesystem;

struct Element {
  const char *command, *prefix;
  std::vector<const char *> free_parameters;  // swept when no --key is given and the case sets them
};

// The parameters the thesis does not fix and RunIn chose (doc/validation.md): coupling stiffness and damping,
// the run-in law's relaxation (feedback A and B: length 1 / (2 A K1)), and the geometry that sets a stiffness
// computed from it (shaft length for the journal bearing's G J / L, land width for the piston ring's land).
// An array key (one value per ring of a pack) is scaled as a whole; its `value` column is the first element.
const std::vector<Element> &elements() {
  static const std::vector<Element> list = {
      {"pin-on-disk", "pin_on_disk", {"friction.A", "friction.B", "pin.mass"}},
      {"journal-bearing", "journal_bearing",
       {"drive.stiffness", "shaft.length", "drive.damping_ratio", "friction.A", "friction.B"}},
      {"piston-ring", "piston_ring",
       {"ring.land_stiffness", "ring_pack.land_stiffness", "ring_pack.land_width", "ring.land_damping_ratio",
        "friction.A", "friction.B"}},
  };
  return list;
}

struct Options {
  std::string element, case_path, output_dir;
  std::vector<std::string> keys;
  std::optional<std::string> law_path;
  double span = 10.0;
  int points = 3;
  bool no_plot = false;
};

struct Run {
  std::string key;  // "" for the base case
  double factor = 1.0, value = 0.0;
  std::string case_name;
  std::optional<RunSummary> summary;
  std::string problem;  // why the run failed
  double seconds = 0.0;
};

// A key's real values: one number, or an array of them (a per-ring key of a ring pack); empty when the key is
// absent or holds anything else.
std::vector<double> numbers_at(const toml::table &root, const std::string &key) {
  const toml::node *node = root.at_path(key).node();
  if (!node) return {};
  if (const auto *v = node->as_floating_point()) return {v->get()};
  std::vector<double> values;
  if (const auto *array = node->as_array())
    for (const auto &element : *array) {
      if (!element.is_floating_point()) return {};
      values.push_back(element.as_floating_point()->get());
    }
  return values;
}

std::optional<double> number_at(const toml::table &root, const std::string &key) {
  const auto values = numbers_at(root, key);
  if (values.empty()) return std::nullopt;
  return values.front();
}

// Multiplies the key's value (every element of an array) by `factor`.
void scale_key(toml::table &root, const std::string &key, double factor) {
  const auto dot = key.rfind('.');
  toml::table *table = dot == std::string::npos ? &root : root.at_path(key.substr(0, dot)).as_table();
  const std::string name = dot == std::string::npos ? key : key.substr(dot + 1);
  const auto values = numbers_at(root, key);
  if (table->get(name)->is_array()) {
    toml::array scaled;
    for (double v : values) scaled.push_back(v * factor);
    table->insert_or_assign(name, std::move(scaled));
  } else {
    table->insert_or_assign(name, values.front() * factor);
  }
}

// The variants live in DIR/cases/, so a file the case names relative to its own directory (a materials file)
// is written as an absolute path, or the variant would look for it next to itself.
void absolute_file_paths(toml::table &table, const fs::path &case_dir) {
  for (auto &&[key, node] : table) {
    if (auto *sub = node.as_table()) {
      absolute_file_paths(*sub, case_dir);
    } else if (auto *text = node.as_string()) {
      const fs::path named(text->get());
      std::error_code error;
      if (!text->get().empty() && named.is_relative() && fs::is_regular_file(case_dir / named, error))
        *text = fs::absolute(case_dir / named).lexically_normal().string();
    }
  }
}

std::string to_toml(const toml::table &root) {
  std::ostringstream text;
  text << toml::toml_formatter(root) << "\n";
  return text.str();
}

// The cell as a time: empty = not reached (-1, as in the element's own summary).
double parse_time(const std::string &cell) { return cell.empty() ? -1.0 : std::stod(cell); }

RunSummary read_summary(const fs::path &file) {
  std::ifstream in(file);
  std::string header, row;
  // an element may append columns of its own (pin-on-disk with adaptive wear steps): the first six are read
  const std::string common = kRunSummaryHeader;
  if (!std::getline(in, header) || header.compare(0, common.size(), common) != 0 ||
      (header.size() > common.size() && header[common.size()] != ',') || !std::getline(in, row))
    throw std::runtime_error("no run summary in " + file.string());
  std::vector<std::string> cells;
  std::stringstream split(row);
  for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
  if (row.back() == ',') cells.emplace_back();
  if (cells.size() < 6 || (header.size() == common.size() && cells.size() != 6))
    throw std::runtime_error("malformed run summary in " + file.string());
  return {std::stod(cells[0]), std::stod(cells[1]), parse_time(cells[2]), parse_time(cells[3]), std::stod(cells[4]),
          std::stod(cells[5])};
}

// This runin, as a child process on one case file; its stderr goes to `log`. Returns the exit status.
int run_element(const Options &o, const fs::path &case_file, const fs::path &run_dir, const fs::path &log) {
  const std::string self = fs::read_symlink("/proc/self/exe").string();
  std::vector<std::string> args = {self, o.element, case_file.string(), "--output-dir", run_dir.string(), "--no-plot"};
  if (o.law_path) args.insert(args.end(), {"--law", *o.law_path});
  ChildStreams streams;
  streams.stderr_file = log;
  return wait_child(start_child(args, streams));
}

std::string csv_quote(const std::string &text) {
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// The keys to vary: --key, else the element's free parameters the case sets; each a positive number or array.
std::vector<std::string> sweep_keys(const Options &o, const Element &element, const toml::table &base) {
  std::vector<std::string> keys = o.keys;
  if (keys.empty())
    for (const char *key : element.free_parameters)
      if (number_at(base, key)) keys.emplace_back(key);
  if (keys.empty())
    throw InputError(fmt::format("{}: sets none of the {} free parameters; name keys with --key", o.case_path,
                                 element.command));
  for (const auto &key : keys) {
    const toml::node *node = base.at_path(key).node();
    if (!node)
      throw InputError(fmt::format("{}: key '{}': not set in the case file; a sweep varies a value the case sets",
                                   o.case_path, key));
    const auto values = numbers_at(base, key);
    if (values.empty())
      throw InputError(fmt::format(
          "{}: key '{}': is {}, a sweep varies a real number or an array of them (write it with a decimal point)",
          o.case_path, key, type_name(*node)));
    for (double v : values)
      if (!(v > 0.0))
        throw InputError(fmt::format("{}: key '{}': a sweep over decades needs positive values", o.case_path, key));
  }
  return keys;
}

// Runs every case (the base case first: it validates every key, so a bad case stops there with the element's own
// message) and reads its summary; a failed run keeps its last log line.
void run_cases(const Options &o, const Element &element, const toml::table &base, std::vector<Run> &runs,
               StagedOutput &out) {
  for (std::size_t n = 0; n < runs.size(); ++n) {
    Run &r = runs[n];
    toml::table variant = base;
    if (!r.key.empty()) scale_key(variant, r.key, r.factor);
    out.write(r.case_name, to_toml(variant));
    const fs::path run_dir = out.scratch(fmt::format("runs/{}", n)), log = out.scratch(fmt::format("runs/{}.log", n));
    fs::create_directories(run_dir.parent_path());
    const auto start = std::chrono::steady_clock::now();
    const int status = run_element(o, out.file(r.case_name), run_dir, log);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status == 0) {
      r.summary = read_summary(run_dir / (std::string(element.prefix) + "_summary.csv"));
    } else {
      r.problem = last_line(log);
      if (r.key.empty()) {
        if (status == 2) throw InputError("sweep: the base case: " + r.problem);
        throw std::runtime_error("sweep: the base case failed: " + r.problem);
      }
    }
    fmt::print("runin sweep: [{}/{}] {} {} ({:.2f} s)\n", n + 1, runs.size(),
               r.key.empty() ? std::string("base case") : fmt::format("{} = {:.6g} (x {:.4g})", r.key, r.value, r.factor),
               r.summary ? "ok" : "FAILED: " + r.problem, r.seconds);
    std::fflush(stdout);
  }

}

// The table: the runs were queued key by key, smallest value first, after the base case; the table takes them in that
// order, with the base case's row in the middle of each key's rows. Returns the number of failed runs.
int sweep_table(const Options &o, const std::vector<std::string> &keys, const toml::table &base,
                const std::vector<Run> &runs, std::string &csv) {
  csv = std::string("key,factor,value,") + kRunSummaryHeader + ",case,status\n";
  int failed = 0;
  auto add_row = [&](const std::string &key, double factor, double value, const Run &r) {
    csv += fmt::format("{},{:.12g},{:.12g},", key, factor, value);
    csv += r.summary ? run_summary_row(*r.summary) : std::string(",,,,,");
    csv += fmt::format(",{},{}\n", r.case_name, r.summary ? std::string("ok") : csv_quote("failed: " + r.problem));
  };
  std::size_t next = 1;
  for (const auto &key : keys)
    for (int i = 0; i < o.points; ++i) {
      if (i == o.points / 2) {
        add_row(key, 1.0, *number_at(base, key), runs.front());
      } else {
        const Run &r = runs[next++];
        add_row(key, r.factor, r.value, r);
        failed += !r.summary;
      }
    }
  return failed;
}

int run_sweep(const Options &o, const PlotRunner &plot) {
  const Element *element = nullptr;
  for (const auto &e : elements())
    if (o.element == e.command) element = &e;
  if (!element) throw InputError("sweep: unknown element '" + o.element + "'");
  if (!(o.span > 1.0) || !std::isfinite(o.span)) throw InputError("--span: must be a finite number > 1");
  if (o.points < 3 || o.points > 9 || o.points % 2 == 0) throw InputError("--points: must be odd, 3 to 9");

  toml::table base = parse_toml(o.case_path);
  if (o.element == "journal-bearing" && base.contains("lubrication"))
    throw InputError(o.case_path + ": a lubricated journal-bearing case (a [lubrication] table) writes no run summary "
                     "(break-away, steady friction) to sweep; its [stribeck] table sweeps the speed");
  if (o.element == "piston-ring" && (base.contains("lubrication") || base.contains("stribeck")))
    throw InputError(o.case_path + ": a lubricated piston-ring case ([lubrication]) writes no run summary to sweep; "
                     "run `runin piston-ring` once per value");
  base.erase("sweep");  // one run per case file: the element's own mu0 sweep is not part of this study
  absolute_file_paths(base, fs::absolute(o.case_path).parent_path());
  const std::vector<std::string> keys = sweep_keys(o, *element, base);

  std::vector<double> factors;  // log-spaced over one span, centred on 1
  for (int i = 0; i < o.points; ++i)
    factors.push_back(std::pow(o.span, (static_cast<double>(i) / (o.points - 1)) - 0.5));

  StagedOutput out(o.output_dir, {"sweep.csv", "sweep_tornado.png", "cases/*.toml"});
  std::vector<Run> runs;
  runs.push_back({"", 1.0, 0.0, "cases/base.toml", std::nullopt, "", 0.0});
  for (const auto &key : keys)
    for (int i = 0; i < o.points; ++i)
      if (i != o.points / 2)
        runs.push_back({key, factors[i], *number_at(base, key) * factors[i], fmt::format("cases/{}_{}.toml", key, i),
                        std::nullopt, "", 0.0});
  run_cases(o, *element, base, runs, out);

  std::string csv;
  const int failed = sweep_table(o, keys, base, runs, csv);
  out.write("sweep.csv", csv);
  std::vector<std::string> written = {"sweep.csv"};
  if (!o.no_plot) {
    plot("plot_sweep.py", {out.file("sweep.csv").string(), out.file("sweep_tornado.png").string(), "--title",
                           o.element + ": " + fs::path(o.case_path).filename().string()});
    written.push_back("sweep_tornado.png");
  }
  out.commit();
  fmt::print("runin sweep: {} keys x {} values of {} ({} runs, {} failed); each row's case file reruns it directly\n",
             keys.size(), o.points, o.case_path, runs.size(), failed);
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i) fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  fmt::print(", {}\n", out.destination("cases").string());
  // the table is written and kept; the exit status and the one error line say that not every run completed
  if (failed)
    throw std::runtime_error(fmt::format("sweep: {} of {} runs failed; their rows in {} name the errors", failed,
                                         runs.size() - 1, out.destination("sweep.csv").string()));
  return 0;
}

}  // namespace

Subcommand add_sweep_command(CLI::App &app, PlotRunner plot) {
  auto o = std::make_shared<Options>();
  auto *cmd = app.add_subcommand(
      "sweep", "Sensitivity of peak friction, break-away and steady time to each free parameter (a decade each)");
  std::vector<std::string> names;
  for (const auto &e : elements()) names.emplace_back(e.command);
  cmd->add_option("element", o->element, "machine element")->required()->check(CLI::IsMember(names));
  cmd->add_option("case", o->case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  cmd->add_option("--output-dir", o->output_dir, "directory for sweep.csv, sweep_tornado.png and cases/")
      ->required()
      ->check(output_directory());
  cmd->add_option("--key", o->keys,
                  "a real-valued case key to vary (repeatable); default: the element's free parameters the case sets");
  cmd->add_option("--span", o->span, "ratio of the largest to the smallest value of each key")->capture_default_str();
  cmd->add_option("--points", o->points, "values per key, log-spaced, the case's own in the middle (odd, 3-9)")
      ->capture_default_str();
  cmd->add_option("--law", o->law_path, "law file from fit-law, passed to every run");
  cmd->add_flag("--no-plot", o->no_plot, "write the CSV and case files only");
  return {cmd, [o, plot] { return run_sweep(*o, plot); }};
}

}  // namespace runin::cli
