#include "cli/cmd_feedback.h"

#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/case_file.h"
#include "cli/staged_file.h"
#include "continuum/feedback_system.h"

namespace runin::cli {
namespace {

namespace fs = std::filesystem;

std::string g17(double x) { return fmt::format("{:.17g}", x); }

struct FeedbackCurve {
  std::vector<continuum::FeedbackSample> samples;
  continuum::FeedbackReport report;
};

FeedbackCurve run_feedback(const tribo::FeedbackModel &model, const continuum::FeedbackRun &run) {
  FeedbackCurve curve;
  curve.report = continuum::simulate(continuum::FeedbackSystem(model), run,
                                     [&](const auto &s) { curve.samples.push_back(s); });
  if (!curve.report.ok())
    throw std::runtime_error(std::string(continuum::to_string(curve.report.status)) + ": " + curve.report.message);
  return curve;
}

// The sweep: one run per value, everything else as in the case.
struct SweepRow {
  double value, r_star, mu_star, k_star, settle, settle_exact;
};

std::vector<SweepRow> run_sweep(const FeedbackCase &c, std::string &sweep_curves) {
  std::vector<SweepRow> rows;
  sweep_curves = "value,t,R,mu\n";
  if (!c.sweep) return rows;
  const tribo::FeedbackModel &m = *c.model;
  for (double value : c.sweep->values) {
    auto coefficients = c.coefficients;
    auto run = c.run;
    set_feedback_parameter(coefficients, run.initial_roughness, c.sweep->parameter, value);
    const tribo::FeedbackModel model(coefficients, m.kind());
    const auto sweep_curve = run_feedback(model, run);
    const double r = model.stationary_roughness();
    rows.push_back({value, r, model.mu(r), model.k(r), continuum::settling_time(sweep_curve.samples, r, 0.01),
                    model.exact_settling_time(run.initial_roughness, 0.01)});
    for (const auto &s : sweep_curve.samples)
      sweep_curves += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g}\n", value, s.t, s.roughness, s.mu);
  }
  return rows;
}

// The CSV files and the plots, staged; returns their names in order.
std::vector<std::string> write_feedback(StagedOutput &out, const FeedbackCase &c, const FeedbackCurve &curve,
                                        const std::vector<SweepRow> &rows, const std::string &sweep_curves, bool plot,
                                        const PlotRunner &run_python_plot) {
  const tribo::FeedbackModel &m = *c.model;
  std::string text = "t,R,mu,k,wear\n";
  for (const auto &s : curve.samples)
    text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", s.t, s.roughness, s.mu, s.wear_rate, s.wear);
  out.write("feedback.csv", text);
  std::vector<std::string> written = {"feedback.csv"};
  if (c.sweep) {
    std::string sweep_text = c.sweep->parameter + ",R_star,mu_R_star,k_R_star,time_to_1pct,time_to_1pct_exact\n";
    for (const auto &r : rows)
      sweep_text += fmt::format("{:.12g},{:.12g},{:.12g},{:.12g},{},{:.12g}\n", r.value, r.r_star, r.mu_star, r.k_star,
                                r.settle < 0.0 ? std::string() : fmt::format("{:.12g}", r.settle),  // empty: not within t_end
                                r.settle_exact);
    out.write("feedback_sweep.csv", sweep_text);
    written.push_back("feedback_sweep.csv");
  }
  if (!plot) return written;
  run_python_plot("plot_feedback.py",
                  {"curve", out.file("feedback.csv").string(), out.file("feedback.png").string(), "--title",
                   c.title, "--r-star", g17(m.stationary_roughness()), "--r-min-wear", g17(m.min_wear_roughness()),
                   "--r-min-friction", g17(m.min_friction_roughness()), "--mu-min", g17(m.min_mu())});
  written.push_back("feedback.png");
  if (c.sweep) {
    const fs::path curves_csv = out.scratch("feedback_sweep_curves.csv");  // plot input only
    {
      std::ofstream curves(curves_csv, std::ios::binary);
      curves << sweep_curves;
      if (!curves) throw std::runtime_error("cannot write " + curves_csv.string());
    }
    run_python_plot("plot_feedback.py", {"sweep", curves_csv.string(), out.file("feedback_sweep.csv").string(),
                                         out.file("feedback_sweep.png").string(), "--title", c.title,
                                         "--parameter", c.sweep->parameter});
    written.push_back("feedback_sweep.png");
  }
  return written;
}

// The model's closed-form numbers (thesis ch. 3).
void print_model(const tribo::FeedbackModel &m) {
  const auto &k = m.coefficients();
  const bool dry = m.kind() == tribo::FeedbackKind::dry;
  const double rs = m.stationary_roughness();
  fmt::print("  model             {} ({} smooths, {} roughens)\n", tribo::to_string(m.kind()),
             dry ? "deformation" : "viscous erosion", dry ? "adhesion" : "capillarity");
  fmt::print("  coefficients      C1 = {} = {:.6g}, C2 = {} = {:.6g}, K1 = {} = {:.6g}, K2 = {} = {:.6g}, A = {:.6g}, B = {:.6g}\n",
             m.thesis_name("C1"), k.C1, m.thesis_name("C2"), k.C2, m.thesis_name("K1"), k.K1, m.thesis_name("K2"), k.K2,
             k.A, k.B);
  fmt::print("  R*                {:.10g}  = sqrt(B K2 / (A K1)), eq. 3.7\n", rs);
  fmt::print("  R_min_wear        {:.10g}  = sqrt(K2 / K1), eq. 3.9; R* minimises wear: {} (A {} B)\n",
             m.min_wear_roughness(), m.stationary_minimises_wear() ? "yes" : "no",
             m.stationary_minimises_wear() ? "==" : "!=");
  fmt::print("  R_min_friction    {:.10g}  = sqrt(C2 / C1), eq. 3.10; R* minimises friction: {} (B K2/(A K1) {} C2/C1)\n",
             m.min_friction_roughness(), m.stationary_minimises_friction() ? "yes" : "no",
             m.stationary_minimises_friction() ? "==" : "!=");
  fmt::print("  mu_min            {:.10g}  = 2 sqrt(C1 C2); mu(R*) = {:.10g}\n", m.min_mu(), m.mu(rs));
  fmt::print("  k_min             {:.10g}  = 2 sqrt(K1 K2); k(R*) = {:.10g}\n", m.min_k(), m.k(rs));
}

int feedback(const std::string &case_path, const std::string &output_dir, bool plot, const PlotRunner &run_python_plot) {
  const FeedbackCase c = read_feedback_case(case_path);
  const tribo::FeedbackModel &m = *c.model;
  const FeedbackCurve curve = run_feedback(m, c.run);
  const auto &samples = curve.samples;
  const double rs = m.stationary_roughness();
  const double settle = continuum::settling_time(samples, rs, 0.01);
  std::string sweep_curves;
  const std::vector<SweepRow> rows = run_sweep(c, sweep_curves);

  // Everything is computed; the output set is staged and moved in only when complete.
  StagedOutput out(output_dir, {"feedback.csv", "feedback.png", "feedback_sweep.csv", "feedback_sweep.png"});
  const std::vector<std::string> written = write_feedback(out, c, curve, rows, sweep_curves, plot, run_python_plot);
  out.commit();

  auto or_none = [](double t) { return t < 0.0 ? std::string("not reached") : fmt::format("{:.6g}", t); };
  const auto &first = samples.front(), &last = samples.back();
  fmt::print("runin feedback: {}\n  {}\n", case_path, c.title);
  if (c.fitted_from) fmt::print("  fitted from       {}\n", *c.fitted_from);
  print_model(m);
  fmt::print("  run               R {:.6g} -> {:.10g}, mu {:.6g} -> {:.10g}, wear W = {:.6g} at t = {:g}\n",
             first.roughness, last.roughness, first.mu, last.mu, last.wear, last.t);
  fmt::print("  time to 1% of R*  {} (output grid {:g}); closed form {:.6g}\n", or_none(settle),
             c.run.output_interval, m.exact_settling_time(c.run.initial_roughness, 0.01));
  fmt::print("  CVODE             {} steps, rtol {:g}, atol {:g}\n", curve.report.steps, c.run.integrator.rtol,
             c.run.integrator.atol);
  if (c.sweep) {
    fmt::print("  sweep             {} over {} values:\n", c.sweep->parameter, rows.size());
    fmt::print("    {:>12} {:>12} {:>12} {:>12} {:>12}\n", c.sweep->parameter, "R*", "mu(R*)", "k(R*)", "t_1%");
    for (const auto &r : rows)
      fmt::print("    {:>12.6g} {:>12.6g} {:>12.6g} {:>12.6g} {:>12}\n", r.value, r.r_star, r.mu_star, r.k_star,
                 or_none(r.settle));
  }
  fmt::print("  wrote            ");
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{} {}", i ? "," : "", out.destination(written[i]).string());
  fmt::print("\n");
  return 0;
}

}  // namespace

Subcommand add_feedback_command(CLI::App &app, PlotRunner plot) {
  struct Options {
    std::string case_path, output_dir;
    bool no_plot = false;
  };
  auto o = std::make_shared<Options>();
  auto *cmd = app.add_subcommand("feedback", "Two-mechanism roughness-feedback model R(t), mu(t) (thesis ch. 3)");
  cmd->add_option("case", o->case_path, "case file (TOML, or JSON if it ends in .json)")->required();
  cmd->add_option("--output-dir", o->output_dir, "directory for feedback.csv and feedback.png (+ sweep files)")
      ->required()
      ->check(output_directory());
  cmd->add_flag("--no-plot", o->no_plot, "write the CSV(s) only");
  return {cmd, [o, plot] { return feedback(o->case_path, o->output_dir, !o->no_plot, plot); }};
}

}  // namespace runin::cli
