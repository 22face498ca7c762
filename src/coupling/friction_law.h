// Homogenised friction laws mu(s) (s = sliding distance) built from micro-scale output:
// a tabulated law and the fitted run-in form, stored together in a JSON law file.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "coupling/ave_time_reader.h"

namespace runin::coupling {

// mu at tabulated distances; linear between nodes, clamped (held constant) outside.
class TabulatedLaw {
 public:
  // Throws std::invalid_argument unless sizes match, n >= 2, values are finite and
  // distances strictly increase.
  TabulatedLaw(std::vector<double> distance, std::vector<double> mu);

  double operator()(double s) const;
  const std::vector<double> &distance() const { return distance_; }
  const std::vector<double> &mu() const { return mu_; }
  std::size_t peak_index() const;  // first node of maximum mu

 private:
  std::vector<double> distance_;
  std::vector<double> mu_;
};

// mu(s) = mu_ss + (mu_0 - mu_ss) exp(-(s - s_peak) / s0), valid for s >= s_peak.
struct RunInFit {
  double mu_0 = 0.0;
  double mu_ss = 0.0;
  double s0 = 0.0;      // decay distance, same unit as s
  double s_peak = 0.0;  // distance of the friction peak; the fit starts there
  double rms_residual = 0.0;  // sqrt(mean squared residual) over the fitted points
  std::size_t points = 0;

  double operator()(double s) const;
};

enum class FitStatus { Converged, TooFewPoints, NoDecay, NotConverged };
const char *to_string(FitStatus status);

struct FitResult {
  FitStatus status = FitStatus::NotConverged;
  RunInFit fit;          // meaningful only when status == Converged
  std::string message;   // why not, otherwise
};

// Least-squares (Levenberg-Marquardt) fit of the run-in form to the data from the peak on.
FitResult fit_run_in(const TabulatedLaw &data);

// A law file: the table (including the spring-loading part before the peak) and, if
// the fit converged, the fitted decay from the peak on.
struct FrictionLaw {
  enum class Branch { Table, Fit };

  std::string source_file;
  std::string distance_column;
  std::string mu_column;
  std::string distance_unit = "m";
  double distance_unit_in_m = 1.0;
  TabulatedLaw table;
  std::optional<RunInFit> fit;

  double peak_distance() const { return table.distance()[table.peak_index()]; }
  // Table branch: the table everywhere. Fit branch: table before the peak, fit after
  // (falls back to the table if there is no fit).
  double evaluate(double s, Branch branch) const;
};

// Length units accepted for the micro distance column; returns metres per unit or
// throws std::invalid_argument.
double metres_per_unit(const std::string &unit);

FrictionLaw build_law(const AveTimeTable &table, const std::string &distance_column,
                      const std::string &mu_column, const std::string &distance_unit,
                      FitResult *fit_report = nullptr);

std::string law_to_json_text(const FrictionLaw &law);
// Throws InputFormatError("<source_name>: ...") for invalid content.
FrictionLaw law_from_json_text(const std::string &text, const std::string &source_name);
FrictionLaw read_law_file(const std::string &path);

}  // namespace runin::coupling
