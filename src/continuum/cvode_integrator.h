// Thin RAII wrapper around SUNDIALS CVODE (6.x API) with root finding. It knows nothing
// about physics: systems hand it a right-hand side and root functions.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace runin::continuum {

class CvodeIntegrator {
 public:
  using Rhs = std::function<void(double t, const double *y, double *ydot)>;
  using Roots = std::function<void(double t, const double *y, double *g)>;

  enum class Method { Bdf, Adams };
  struct Settings {
    Method method = Method::Bdf;
    double rtol = 1e-8;
    double atol = 1e-12;  // scalar, same for every component
    long max_steps = 100000;  // per advance_to_stop()/advance_to_output() call
  };

  enum class Outcome { ReachedTarget, FoundRoot, Failed };
  struct StepResult {
    Outcome outcome = Outcome::Failed;
    double t = 0.0;
    std::vector<int> roots_found;  // per root function: 0, or +-1 crossing direction
    // When Failed: one line saying what happened ("could not advance past t = ... (too much work
    // ...)"), ending in CVODE's flag name, e.g. "[CV_TOO_MUCH_WORK]".
    std::string message;
  };

  CvodeIntegrator(std::size_t size, Settings settings);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator &) = delete;
  CvodeIntegrator &operator=(const CvodeIntegrator &) = delete;

  // (Re)starts the integration at (t0, y0). `directions[i]` restricts root i to
  // increasing (+1), decreasing (-1) or any (0) crossings.
  void restart(double t0, const std::vector<double> &y0, Rhs rhs, Roots roots,
               const std::vector<int> &directions);
  // Two ways to advance; both stop early at a root (FoundRoot, the state at the root), and CVODE
  // never steps past `t_stop` (a kink or jump of the right-hand side, e.g. a drive's ramp end, or
  // the end of the run: the right-hand side is not evaluated beyond it).
  //
  // To a stop: integrates to `t_stop` and lands on it (CVODE's stop time); the state is CVODE's
  // solution there, and the next step starts from it, so the next phase may restart at a kink.
  StepResult advance_to_stop(double t_stop);
  // To an output time `t_out` <= `t_stop` (dense output): CVODE steps as its error control allows,
  // past `t_out` when it can (never past `t_stop`), and the state is its interpolating polynomial at
  // `t_out` (CVodeGetDky), within the local error of the steps. Outputs then cost no steps of their
  // own: the step count follows the solution, not the output grid. With t_out == t_stop it is
  // advance_to_stop(t_stop).
  StepResult advance_to_output(double t_out, double t_stop);

  const std::vector<double> &state() const { return state_; }
  long total_steps() const;

 private:
  StepResult advance(double target, double t_stop);
  std::string failure_message(int flag, double t, double target) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<double> state_;
  Settings settings_;
};

}  // namespace runin::continuum
