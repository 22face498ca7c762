#include "continuum/cvode_integrator.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

namespace runin::continuum {

struct CvodeIntegrator::Impl {
  SUNContext context = nullptr;
  void *memory = nullptr;
  N_Vector y = nullptr;
  SUNMatrix jacobian = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  Rhs rhs;
  Roots roots;
  int root_count = 0;
  bool initialised = false;
  double t = 0.0;
  long steps_before_restart = 0;
  std::string last_message;

  static int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void *user) {
    auto *self = static_cast<Impl *>(user);
    self->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
  }
  static int root_callback(sunrealtype t, N_Vector y, sunrealtype *g, void *user) {
    auto *self = static_cast<Impl *>(user);
    self->roots(t, N_VGetArrayPointer(y), g);
    return 0;
  }
  // Keep CVODE's message for the status report instead of printing it to stderr.
  static void error_callback(int, const char *, const char *function, char *message, void *user) {
    static_cast<Impl *>(user)->last_message = std::string(function) + ": " + message;
  }

  long steps_since_restart() const {
    long steps = 0;
    if (initialised) CVodeGetNumSteps(memory, &steps);
    return steps;
  }
};

namespace {
void check(int flag, const char *call) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE setup failed in ") + call);
}
}  // namespace

CvodeIntegrator::CvodeIntegrator(std::size_t size, Settings settings)
    : impl_(std::make_unique<Impl>()), state_(size, 0.0), settings_(settings) {
  if (!(settings.rtol > 0.0) || !(settings.atol > 0.0) || settings.max_steps <= 0)
    throw std::invalid_argument("CVODE settings: rtol, atol and max_steps must be positive");
  Impl &s = *impl_;
  check(SUNContext_Create(nullptr, &s.context), "SUNContext_Create");
  s.memory = CVodeCreate(settings.method == Method::Bdf ? CV_BDF : CV_ADAMS, s.context);
  s.y = N_VNew_Serial(static_cast<sunindextype>(size), s.context);
  s.jacobian = SUNDenseMatrix(static_cast<sunindextype>(size), static_cast<sunindextype>(size), s.context);
  if (!s.memory || !s.y || !s.jacobian) throw std::runtime_error("CVODE: out of memory");
  s.linear_solver = SUNLinSol_Dense(s.y, s.jacobian, s.context);
  N_VConst(0.0, s.y);
  check(CVodeInit(s.memory, Impl::rhs_callback, 0.0, s.y), "CVodeInit");
  check(CVodeSetUserData(s.memory, &s), "CVodeSetUserData");
  check(CVodeSetErrHandlerFn(s.memory, Impl::error_callback, &s), "CVodeSetErrHandlerFn");
  check(CVodeSStolerances(s.memory, settings.rtol, settings.atol), "CVodeSStolerances");
  check(CVodeSetLinearSolver(s.memory, s.linear_solver, s.jacobian), "CVodeSetLinearSolver");
  check(CVodeSetMaxNumSteps(s.memory, settings.max_steps), "CVodeSetMaxNumSteps");
  check(CVodeSetNoInactiveRootWarn(s.memory), "CVodeSetNoInactiveRootWarn");
}

CvodeIntegrator::~CvodeIntegrator() {
  Impl &s = *impl_;
  CVodeFree(&s.memory);
  SUNLinSolFree(s.linear_solver);
  SUNMatDestroy(s.jacobian);
  N_VDestroy(s.y);
  SUNContext_Free(&s.context);
}

void CvodeIntegrator::restart(double t0, const std::vector<double> &y0, Rhs rhs, Roots roots,
                              const std::vector<int> &directions) {
  if (y0.size() != state_.size()) throw std::invalid_argument("CvodeIntegrator::restart: wrong state size");
  Impl &s = *impl_;
  s.steps_before_restart += s.steps_since_restart();
  s.rhs = std::move(rhs);
  s.roots = std::move(roots);
  s.root_count = static_cast<int>(directions.size());
  state_ = y0;
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(s.y));
  check(CVodeReInit(s.memory, t0, s.y), "CVodeReInit");
  s.initialised = true;
  s.t = t0;
  check(CVodeRootInit(s.memory, s.root_count, s.root_count > 0 ? Impl::root_callback : nullptr),
        "CVodeRootInit");
  if (s.root_count > 0) {
    std::vector<int> dirs = directions;
    check(CVodeSetRootDirection(s.memory, dirs.data()), "CVodeSetRootDirection");
  }
}

std::string CvodeIntegrator::failure_message(int flag, double t, double target) const {
  char *name = CVodeGetReturnFlagName(flag);  // malloc'ed by SUNDIALS
  const std::string tag = std::string(" [") + name + "]";
  std::free(name);
  char buffer[320];
  switch (flag) {
    case CV_TOO_MUCH_WORK:
      std::snprintf(buffer, sizeof buffer,
                    "could not advance past t = %.6g (too much work: %ld steps, the solver.max_steps limit, before "
                    "t = %.6g): the solution changes faster than the tolerances can follow (a runaway or a very "
                    "stiff transient)",
                    t, settings_.max_steps, target);
      return buffer + tag;
    case CV_TOO_MUCH_ACC:
      std::snprintf(buffer, sizeof buffer,
                    "cannot meet rtol = %g, atol = %g at t = %.6g (below round-off for the size of the solution; "
                    "loosen solver.rtol or solver.atol)",
                    settings_.rtol, settings_.atol, t);
      return buffer + tag;
    case CV_ERR_FAILURE:
      std::snprintf(buffer, sizeof buffer,
                    "repeated error-test failures at t = %.6g with the step at its minimum: the solution jumps or "
                    "blows up there",
                    t);
      return buffer + tag;
    case CV_CONV_FAILURE:
      std::snprintf(buffer, sizeof buffer,
                    "the Newton iteration failed repeatedly at t = %.6g with the step at its minimum: the "
                    "right-hand side is discontinuous or extremely stiff there",
                    t);
      return buffer + tag;
    default:
      std::snprintf(buffer, sizeof buffer, "failed at t = %.6g", t);
      return buffer + (impl_->last_message.empty() ? std::string() : " (" + impl_->last_message + ")") + tag;
  }
}

CvodeIntegrator::StepResult CvodeIntegrator::advance_to_stop(double t_stop) { return advance(t_stop, t_stop); }

CvodeIntegrator::StepResult CvodeIntegrator::advance_to_output(double t_out, double t_stop) {
  if (!(t_out <= t_stop)) throw std::invalid_argument("CvodeIntegrator::advance_to_output: t_out past t_stop");
  return advance(t_out, t_stop);
}

CvodeIntegrator::StepResult CvodeIntegrator::advance(double target, double t_stop) {
  Impl &s = *impl_;
  StepResult result;
  result.roots_found.assign(static_cast<std::size_t>(s.root_count), 0);
  // CVODE refuses an output time within round-off of the current time; nothing to do then.
  const double eps = std::numeric_limits<double>::epsilon();
  if (target - s.t <= 8.0 * eps * std::max(std::abs(s.t), std::abs(target))) {
    result.outcome = Outcome::ReachedTarget;
    result.t = s.t;
    return result;
  }
  // Never step across t_stop; set on every call (a stop time, once reached, may be cleared, and a
  // restart keeps the previous one). CV_NORMAL: when a step passes target, CVODE returns y(target)
  // from its interpolant and keeps its own state at the end of that step.
  check(CVodeSetStopTime(s.memory, t_stop), "CVodeSetStopTime");
  sunrealtype t_reached = s.t;
  const int flag = CVode(s.memory, target, s.y, &t_reached, CV_NORMAL);
  const double *y = N_VGetArrayPointer(s.y);
  state_.assign(y, y + state_.size());
  s.t = t_reached;
  result.t = t_reached;
  if (flag == CV_ROOT_RETURN) {
    result.outcome = Outcome::FoundRoot;
    CVodeGetRootInfo(s.memory, result.roots_found.data());
  } else if (flag >= 0) {
    result.outcome = Outcome::ReachedTarget;
  } else {
    result.outcome = Outcome::Failed;
    result.message = failure_message(flag, t_reached, target);
  }
  return result;
}

long CvodeIntegrator::total_steps() const { return impl_->steps_before_restart + impl_->steps_since_restart(); }

}  // namespace runin::continuum
