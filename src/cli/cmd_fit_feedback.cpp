#include "cli/cmd_fit_feedback.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <variant>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli/case_file.h"  // InputError
#include "cli/homogenise_plan.h"  // sha256_hex
#include "cli/staged_file.h"
#include "coupling/csv_table.h"
#include "coupling/feedback_fit.h"

namespace runin::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string input, t_column, mu_column, r_column, output, kind = "lubricated", title;
  double t_scale = 1.0, r_scale = 1.0, max_rms_error = 0.05;
  bool no_plot = false, drop_repeated_t = false;
};

// One case-file entry; rendered as TOML (with its comment) or JSON.
using Value = std::variant<std::string, double, long, bool>;
struct Entry {
  std::string key;
  Value value;
  std::string comment;
};
struct Section {
  std::string name;  // "" for the top level
  std::vector<Entry> entries;
};

std::string toml_string(const std::string &s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) out += fmt::format("\\u{:04X}", static_cast<unsigned char>(c));
    else out += c;
  }
  return out + "\"";
}

std::string toml_value(const Value &v) {
  if (const auto *s = std::get_if<std::string>(&v)) return toml_string(*s);
  if (const auto *d = std::get_if<double>(&v)) {
    std::string text = fmt::format("{}", *d);  // shortest text that reads back to the same double
    if (text.find_first_of(".eE") == std::string::npos) text += ".0";  // a TOML float, not an integer
    return text;
  }
  if (const auto *l = std::get_if<long>(&v)) return std::to_string(*l);
  return std::get<bool>(v) ? "true" : "false";
}

std::string render_toml(const std::vector<std::string> &header, const std::vector<Section> &sections) {
  std::string out;
  for (const auto &line : header) out += "# " + line + "\n";
  for (const auto &section : sections) {
    if (!section.name.empty()) out += "\n[" + section.name + "]\n";
    for (const auto &e : section.entries) {
      out += e.key + " = " + toml_value(e.value);
      if (!e.comment.empty()) out += "  # " + e.comment;
      out += "\n";
    }
  }
  return out;
}

std::string render_json(const std::vector<Section> &sections) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::object();
  for (const auto &section : sections) {
    auto &target = section.name.empty() ? doc : doc[section.name];
    for (const auto &e : section.entries) std::visit([&](const auto &v) { target[e.key] = v; }, e.value);
  }
  return doc.dump(2) + "\n";
}

std::string read_bytes(const std::string &path) {
  std::error_code error;
  if (fs::is_directory(path, error)) throw InputError("--input: '" + path + "' is a directory, not a CSV file");
  if (!fs::exists(path, error))
    throw InputError("--input: no such file '" + path + "' (a relative path is taken from the current directory, " +
                     fs::current_path(error).string() + ")");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--input: cannot open '" + path + "'");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Column `name` (given by `option`) of the table; a missing column names the option.
std::vector<double> column(const coupling::CsvTable &table, const std::string &option, const std::string &name) {
  try {
    return table.numbers(name);
  } catch (const coupling::InputFormatError &e) {
    throw InputError(option + ": " + e.what());
  }
}

void check_scale(const std::string &option, double value) {
  if (!std::isfinite(value) || !(value > 0.0))
    throw InputError(option + ": must be a positive finite factor, got " + fmt::format("{:g}", value));
}

// The run's output interval: the data's spacing when the data are on a uniform grid (so `runin feedback`
// reproduces the data times), else the case default t_end / 1000.
double output_interval(const std::vector<double> &t) {
  const double span = t.back() - t.front();
  const double dt = span / static_cast<double>(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i)
    if (std::abs((t[i] - t[i - 1]) - dt) > 1e-6 * dt) return span / 1000.0;
  return dt;
}

// The options' checks; returns the absolute output path (a .toml or .json case file).
fs::path checked_output(const Options &o) {
  if (o.r_column.empty())
    throw InputError("--r-column: required: mu(t) alone does not fix the roughness scale (C1 R + C2/R is unchanged "
                     "under R -> s R, C1 -> C1/s, C2 -> C2 s); give the column with the roughness R");
  check_scale("--t-scale", o.t_scale);
  check_scale("--r-scale", o.r_scale);
  if (!std::isfinite(o.max_rms_error) || !(o.max_rms_error > 0.0))
    throw InputError("--max-rms-error: must be a positive relative error, e.g. 0.05, got " +
                     fmt::format("{:g}", o.max_rms_error));
  const fs::path output = fs::absolute(o.output);
  const std::string extension = output.extension().string();
  if (extension != ".toml" && extension != ".json")
    throw InputError("--output: '" + o.output + "' must end in .toml or .json (the case file `runin feedback` reads)");
  std::error_code error;
  if (fs::is_directory(output, error)) throw InputError("--output: '" + o.output + "' is a directory; name a case file");
  return output;
}

// The series as read (t in column units, unscaled), the table row of each series row, the rows dropped.
struct Series {
  coupling::FeedbackSeries series;
  std::vector<std::size_t> kept_rows;
  std::size_t dropped = 0;
};

Series read_series(const Options &o, const coupling::CsvTable &table) {
  Series s;
  auto &series = s.series;
  series.t = column(table, "--t-column", o.t_column);
  series.mu = column(table, "--mu-column", o.mu_column);
  series.R = column(table, "--r-column", o.r_column);
  series.t_name = o.t_column, series.mu_name = o.mu_column, series.R_name = o.r_column;
  for (std::size_t i = 0; i < series.t.size(); ++i) s.kept_rows.push_back(i);
  if (!o.drop_repeated_t) return s;
  // Rows at the same t as the row before (a pin that sticks does not slide): the first of them is kept.
  coupling::FeedbackSeries kept = series;
  kept.t.clear(), kept.mu.clear(), kept.R.clear(), s.kept_rows.clear();
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    if (!kept.t.empty() && series.t[i] == kept.t.back()) {
      ++s.dropped;
      continue;
    }
    kept.t.push_back(series.t[i]), kept.mu.push_back(series.mu[i]), kept.R.push_back(series.R[i]);
    s.kept_rows.push_back(i);
  }
  series = std::move(kept);
  return s;
}

// A fit that failed, as one line naming the data row.
[[noreturn]] void fit_failed(const Options &o, const coupling::CsvTable &table, const Series &s,
                             const coupling::FeedbackFitResult &fit) {
  const auto &series = s.series;
  const std::string where = fit.bad_row != coupling::FeedbackFitResult::kNoRow
                                ? o.input + ":" + std::to_string(table.line_of(s.kept_rows[fit.bad_row]))
                                : o.input;
  using S = coupling::FeedbackFitStatus;
  const bool data_error = fit.status == S::TooFewPoints || fit.status == S::NonFinite ||
                          fit.status == S::TimeNotIncreasing || fit.status == S::NonPositive;
  const bool repeated = fit.status == S::TimeNotIncreasing && series.t[fit.bad_row] == series.t[fit.bad_row - 1];
  throw InputError(where + ": " + (data_error ? "" : "not fitted (" + std::string(to_string(fit.status)) + "): ") +
                   fit.message + (repeated ? "; --drop-repeated-t keeps the first of rows with equal t" : ""));
}

// What the written case and its comparison name.
struct Written {
  fs::path output, csv_path, png_path;
  std::string title, source, bytes;
  double t0 = 0.0;  // the first data time, column units
};

std::vector<Section> fit_sections(const Options &o, const Written &w, const Series &s,
                                  const coupling::FeedbackFitResult &fit) {
  const tribo::FeedbackModel &m = *fit.model;
  const auto &k = m.coefficients();
  const bool dry = m.kind() == tribo::FeedbackKind::dry;
  return {
      {"", {{"title", w.title, ""}}},
      {"model",
       {{"kind", std::string(tribo::to_string(m.kind())), ""},
        {"C1", k.C1, m.thesis_name("C1") + (dry ? ", deformation" : ", viscous erosion")},
        {"C2", k.C2, m.thesis_name("C2") + (dry ? ", adhesion" : ", capillarity")},
        {"K1", k.K1, "= A K1 (fitted rate)"},
        {"K2", k.K2, "= B K2 = A K1 R*^2"},
        {"A", k.A, "not identifiable apart from K1"},
        {"B", k.B, "not identifiable apart from K2"}}},
      {"run",
       {{"R0", fit.R0, "fitted R at the first data point"},
        {"t_end", s.series.t.back() - fit.t0, "the data's span"},
        {"output_interval", output_interval(s.series.t), ""}}},
      {"fit",
       {{"source", w.source, ""},
        {"source_sha256", sha256_hex(w.bytes), ""},
        {"t_column", o.t_column, ""},
        {"mu_column", o.mu_column, ""},
        {"r_column", o.r_column, ""},
        {"t_scale", o.t_scale, "model t = t_scale (t_column - t0)"},
        {"r_scale", o.r_scale, "model R = r_scale r_column"},
        {"t0", w.t0, "first data time, column units"},
        {"points", static_cast<long>(fit.points), ""},
        {"dropped_repeated_t", static_cast<long>(s.dropped), "rows at the t of the row before (--drop-repeated-t)"},
        {"status", std::string(to_string(fit.status)), ""},
        {"method", std::string("Levenberg-Marquardt on the relative error of R^2 (R0, R*, A K1); QR least squares "
                               "of mu / mu_i on (R, 1/R) (C1, C2 >= 0)"), ""},
        {"R_star", fit.R_star, ""},
        {"A_K1", fit.rate, ""},
        {"B_K2", fit.B_K2, ""},
        {"R_star_squared_std_error", fit.R_star_squared_error, ""},
        {"R0_squared_std_error", fit.R0_squared_error, ""},
        {"A_K1_std_error", fit.rate_error, ""},
        {"C1_std_error", fit.C1_error, ""},
        {"C2_std_error", fit.C2_error, "0 when clamped"},
        {"C2_clamped", fit.C2_clamped, "the unconstrained C2 was < 0"},
        {"R_max_rel_error", fit.R_max_rel_error, "fitted R(t) (exact solution) vs data"},
        {"R_rms_rel_error", fit.R_rms_rel_error, ""},
        {"mu_max_rel_error", fit.mu_max_rel_error, "mu(R(t)) of the fitted model vs data"},
        {"mu_rms_rel_error", fit.mu_rms_rel_error, ""},
        {"mu_of_R_max_rel_error", fit.mu_of_R_max_rel_error, "C1 R + C2/R at the measured R vs data"},
        {"mu_of_R_rms_rel_error", fit.mu_of_R_rms_rel_error, ""},
        {"max_rms_rel_error", o.max_rms_error, "acceptance limit (--max-rms-error)"},
        {"comparison", w.csv_path.filename().string(), "data vs fit"}}}};
}

std::string case_text(const Options &o, const Written &w, const Series &s, const coupling::FeedbackFitResult &fit) {
  const std::vector<std::string> header = {
      "Fitted by `runin fit-feedback` (doc/feedback_model.md, \"Fitting the model to a run-in\").",
      "R(t) identifies R0, R* and the rate A K1 only; B K2 = A K1 R*^2 and the wear rate is not in the data,",
      "so the model is written with A = B = 1, K1 = A K1, K2 = B K2 (wear in units where A = B = 1).",
      fmt::format("t = {:g} * ({} - {:.17g}), R = {:g} * {}, mu = {}.", o.t_scale, o.t_column, w.t0,
                  o.r_scale, o.r_column, o.mu_column),
      "Run: runin feedback " + w.output.filename().string() + " --output-dir DIR"};
  const auto sections = fit_sections(o, w, s, fit);
  return w.output.extension() == ".json" ? render_json(sections) : render_toml(header, sections);
}

// Data against the fit: t (column units and model), R, mu and their relative errors.
std::string comparison_csv(const std::vector<double> &t_data, const coupling::FeedbackSeries &series,
                           const coupling::FeedbackFitResult &fit) {
  const tribo::FeedbackModel &m = *fit.model;
  std::string csv = "t,t_model,R,R_fit,mu,mu_fit,R_rel_error,mu_rel_error\n";
  for (std::size_t i = 0; i < series.t.size(); ++i) {
    const double R_fit = m.exact_roughness(fit.R0, series.t[i] - fit.t0), mu_fit = m.mu(R_fit);
    csv += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.6g},{:.6g}\n", t_data[i],
                       series.t[i] - fit.t0, series.R[i], R_fit, series.mu[i], mu_fit,
                       (R_fit - series.R[i]) / series.R[i], (mu_fit - series.mu[i]) / series.mu[i]);
  }
  return csv;
}

// Everything is computed: stage the files, plot, then move them in together. Directories made for the output are
// removed again if the run fails before the commit.
void write_outputs(const Options &o, const Written &w, const std::string &text, const std::string &csv,
                   double r_star, const PlotRunner &plot) {
  std::error_code error;
  fs::path made;
  for (fs::path p = w.output.parent_path(); !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
    made = p;
    if (p == p.parent_path()) break;
  }
  fs::create_directories(w.output.parent_path(), error);
  if (error) throw std::runtime_error("cannot create " + w.output.parent_path().string() + ": " + error.message());
  struct RemoveUnlessKept {
    fs::path path;
    bool keep = false;
    ~RemoveUnlessKept() {
      std::error_code ignored;
      if (!keep && !path.empty()) fs::remove_all(path, ignored);
    }
  } made_directories{made};
  StagedFile case_file(w.output), csv_file(w.csv_path), png_file(w.png_path);
  case_file.write(text);
  csv_file.write(csv);
  const std::string t_label =
      o.t_scale == 1.0 ? fmt::format("{} - {:g}", o.t_column, w.t0)
                       : fmt::format("{:g} x ({} - {:g})", o.t_scale, o.t_column, w.t0);
  if (!o.no_plot)
    plot("plot_feedback_fit.py",
         {csv_file.temp_path().string(), png_file.temp_path().string(), "--title", w.title, "--r-star",
          fmt::format("{:.17g}", r_star), "--t-label", t_label});
  case_file.commit();
  csv_file.commit();
  if (!o.no_plot) png_file.commit();
  made_directories.keep = true;
}

void print_fit(const Options &o, const Written &w, std::size_t dropped, const coupling::FeedbackFitResult &fit) {
  const tribo::FeedbackModel &m = *fit.model;
  fmt::print("runin fit-feedback: {} ({} rows{}) -> {}\n", o.input, fit.points,
             o.drop_repeated_t ? fmt::format(", {} at a repeated t dropped", dropped) : "", o.output);
  fmt::print("  columns      t '{}' x {:g}, mu '{}', R '{}' x {:g}; model time from t0 = {:.6g}\n", o.t_column,
             o.t_scale, o.mu_column, o.r_column, o.r_scale, w.t0);
  fmt::print("  R(t)         R0 = {:.8g}, R* = {:.8g}, A K1 = {:.8g} (+- {:.2g}), B K2 = A K1 R*^2 = {:.8g}\n", fit.R0,
             fit.R_star, fit.rate, fit.rate_error, fit.B_K2);
  fmt::print("  mu(R)        C1 = {} = {:.8g} (+- {:.2g}), C2 = {} = {:.8g} (+- {:.2g}){}\n", m.thesis_name("C1"),
             fit.C1, fit.C1_error, m.thesis_name("C2"), fit.C2, fit.C2_error,
             fit.C2_clamped ? " (clamped: the unconstrained C2 was < 0)" : "");
  fmt::print("  written as   A = B = 1, K1 = A K1, K2 = B K2 (only the products are identified)\n");
  fmt::print("  residuals    R(t): max {:.3g}, rms {:.3g}; mu(t): max {:.3g}, rms {:.3g} (relative; LM status {}, "
             "{} evaluations)\n",
             fit.R_max_rel_error, fit.R_rms_rel_error, fit.mu_max_rel_error, fit.mu_rms_rel_error, fit.lm_status,
             fit.lm_evaluations);
  fmt::print("  wrote        {}, {}{}\n", w.output.string(), w.csv_path.string(),
             o.no_plot ? "" : ", " + w.png_path.string());
}

int run(const Options &o, const PlotRunner &plot) {
  Written w;
  w.output = checked_output(o);
  w.bytes = read_bytes(o.input);
  const coupling::CsvTable table = [&] {
    std::istringstream in(w.bytes);
    try {
      return coupling::parse_csv_table(in, o.input);
    } catch (const coupling::InputFormatError &e) {
      throw InputError(std::string("--input: ") + e.what());
    }
  }();
  Series s = read_series(o, table);
  const std::vector<double> t_data = s.series.t;
  for (auto &t : s.series.t) t *= o.t_scale;
  for (auto &r : s.series.R) r *= o.r_scale;
  // runin feedback refuses such a t_end (its integrator's step control underflows): say so before fitting
  const double span = s.series.t.back() - s.series.t.front();
  if (span < kFeedbackMinTimeSpan)
    throw InputError(fmt::format("--t-scale: the data span {:g} s (column '{}' x --t-scale {:g}) is below {:g} s, which "
                                 "runin feedback cannot integrate; give --t-scale to take t in larger units",
                                 span, o.t_column, o.t_scale, kFeedbackMinTimeSpan));

  coupling::FeedbackFitOptions options;
  options.kind = o.kind == "dry" ? tribo::FeedbackKind::dry : tribo::FeedbackKind::lubricated;
  options.max_rms_relative_error = o.max_rms_error;
  const coupling::FeedbackFitResult fit = coupling::fit_feedback(s.series, options);
  if (!fit.ok()) fit_failed(o, table, s, fit);
  w.source = fs::path(o.input).filename().string();
  w.title = o.title.empty() ? "Feedback model (thesis ch. 3) fitted to " + w.source : o.title;
  const fs::path stem = w.output.parent_path() / w.output.stem();
  w.csv_path = stem.string() + "_comparison.csv";
  w.png_path = stem.string() + "_comparison.png";
  w.t0 = t_data.front();
  write_outputs(o, w, case_text(o, w, s, fit), comparison_csv(t_data, s.series, fit), fit.R_star, plot);
  print_fit(o, w, s.dropped, fit);
  return 0;
}

}  // namespace

Subcommand add_fit_feedback_command(CLI::App &app, PlotRunner plot) {
  auto o = std::make_shared<Options>();
  auto *cmd = app.add_subcommand("fit-feedback",
                                 "Fit the roughness-feedback model (thesis ch. 3) to a run-in CSV; writes a feedback case");
  cmd->add_option("input,--input", o->input, "CSV file with a header line of column names")->required();
  cmd->add_option("--t-column", o->t_column, "column with the time or sliding distance (any unit, see --t-scale)")
      ->required();
  cmd->add_option("--mu-column", o->mu_column, "column with the friction coefficient")->required();
  cmd->add_option("--r-column", o->r_column, "column with the roughness R (any unit, see --r-scale)");
  cmd->add_option("--output", o->output, "case file to write (.toml, or .json); CASE_comparison.csv/.png beside it")
      ->required()
      ->check(non_empty_path());
  cmd->add_option("--kind", o->kind, "names of the mechanisms in the case file")
      ->check(CLI::IsMember({"lubricated", "dry"}))
      ->capture_default_str();
  cmd->add_option("--t-scale", o->t_scale, "model t = t-scale * (t column - first t), e.g. 60 for minutes -> s")
      ->capture_default_str();
  cmd->add_option("--r-scale", o->r_scale, "model R = r-scale * R column, e.g. 1e6 for m -> um")->capture_default_str();
  cmd->add_option("--max-rms-error", o->max_rms_error,
                  "reject the fit when the RMS relative error of R(t) or mu(t) exceeds this")
      ->capture_default_str();
  cmd->add_option("--title", o->title, "title of the case (default: names the CSV)");
  cmd->add_flag("--drop-repeated-t", o->drop_repeated_t,
                "keep only the first of rows with equal t (a sliding distance that stands still while a pin sticks)");
  cmd->add_flag("--no-plot", o->no_plot, "write the case file and the comparison CSV only");
  return {cmd, [o, plot = std::move(plot)] { return run(*o, plot); }};
}

}  // namespace runin::cli
