// The state-law splitting driver (doc/state_law_continuum.md): one stepper for the two-way coupling of a machine
// element's dynamics with the surface states of its contact nodes, used by the pin-on-disk, the journal bearing and
// the piston ring.
//
// Two subsystems, each with its own stepper:
//  - fast: the element's dynamics (its simulate(): CVODE in the stick/slip loop), which sees the friction as the
//    held coefficients of StateLawFriction (kinetic mu_eff, static limit);
//  - slow: the node states h_i and the worn geometry (a SlowSystem): the law's wear rates over a slid distance,
//    the contact re-solved, new held coefficients.
// Lie splitting at the output interval: the fast stepper integrates one interval with the coefficients held; at
// each of its samples the slow system advances over the interval that ends there (the distance slid in it, the
// pressures held) and sets the coefficients of the next; the fast stepper restarts from the sample when they
// changed. The observer sees each sample after the slow step, so the slow state it reads is the sample's.
// The error is first order in the interval (tests/unit/test_state_law_splitting.cpp).
//
// Failure is a status, not an exception: the fast stepper's (IntegratorFailure, TooManyEvents) and the slow one's
// (a law lookup outside its pressure grid, an invalid state, a failed wear step or too many of them), each with
// the time and a one-line message. The observer's own exceptions pass through.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

#include "continuum/stick_slip_loop.h"  // SolveReport

namespace runin::continuum {

enum class SplitStatus {
  Success,
  FastFailure,       // the fast stepper failed: fast.status and the message say how
  LawOutOfRange,     // a law lookup left the pressure grid under OutOfRange::Error (std::out_of_range)
  InvalidState,      // the slow step was given an invalid state (std::invalid_argument)
  SlowFailure,       // a wear step failed (contact not converged, worn through, ...)
  TooManySlowSteps,  // the slow stepper's own step limit was reached
};
const char *to_string(SplitStatus status);

struct SplitReport {
  SplitStatus status = SplitStatus::Success;
  std::string message;  // empty on success; the fast stepper's message on FastFailure
  double time = 0.0;    // s, the sample whose slow step failed (or 0: before the run), else where the run ended
  long slow_steps = 0;  // slow steps that changed the held coefficients
  // Adaptive wear steps (pin_state_law.h, run_pin_split): steps taken back, and (torque drive) the stretches of
  // full dynamics after the first (each chunk of 10 output intervals).
  long rejected_steps = 0, fallbacks = 0;
  // Adaptive wear steps that failed at their smallest step (SlowFailure): that step's sliding (m) and duration (s).
  double failed_step_distance = 0.0, failed_step_duration = 0.0;
  SolveReport fast;     // the fast stepper's report (partial when the slow stepper stopped the run)

  bool ok() const { return status == SplitStatus::Success; }
};

// A slow step that cannot continue throws this with its status (SlowFailure or TooManySlowSteps) and message.
struct SlowStepError : std::runtime_error {
  SlowStepError(SplitStatus s, const std::string &message) : std::runtime_error(message), status(s) {}
  SplitStatus status;
};

// The slow subsystem of a split element. Its steps may throw std::out_of_range (a law lookup), std::invalid_argument
// or SlowStepError; the driver turns them into statuses. Any other exception (a bug, a resource failure) passes
// through.
template <class Sample>
class SlowSystem {
 public:
  virtual ~SlowSystem() = default;
  // Sets the held coefficients from the initial state, before the fast stepper starts.
  virtual void start() = 0;
  // Advances the slow state over the interval that ends at `sample` and sets the held coefficients of the next;
  // true when they changed (the fast stepper then restarts from the sample).
  virtual bool step(const Sample &sample) = 0;
};

// The fast stepper of an element: integrates from t = 0 to the end, calling `on_sample` with every output sample
// (and the samples at events) and, after each output-grid sample, `refresh`, which says whether the held
// coefficients changed there (then the integrator restarts from that sample).
template <class Sample>
using FastStepper = std::function<SolveReport(const std::function<void(const Sample &)> &on_sample,
                                              const std::function<bool()> &refresh)>;

// Runs the split. Bad settings of the fast stepper (std::invalid_argument from its validation) still throw.
template <class Sample>
SplitReport split_run(SlowSystem<Sample> &slow, const FastStepper<Sample> &fast,
                      const std::function<void(const Sample &)> &observer) {
  struct Stop {
    SplitStatus status;
    std::string message;
  };
  SplitReport report;
  // The slow step's exceptions as a status; anything else (the observer's own) passes through.
  const auto guarded = [](const auto &step) {
    try {
      return step();
    } catch (const SlowStepError &e) {
      throw Stop{e.status, e.what()};
    } catch (const std::out_of_range &e) {
      throw Stop{SplitStatus::LawOutOfRange, e.what()};
    } catch (const std::invalid_argument &e) {
      throw Stop{SplitStatus::InvalidState, e.what()};
    }
  };
  bool changed = false;
  try {
    guarded([&] {
      slow.start();
      return true;
    });
    const auto on_sample = [&](const Sample &s) {
      report.time = s.t;
      if (guarded([&] { return slow.step(s); })) {
        changed = true;
        ++report.slow_steps;
      }
      if (observer) observer(s);
    };
    report.fast = fast(on_sample, [&] { return std::exchange(changed, false); });
  } catch (Stop &stop) {
    report.status = stop.status;
    report.message = std::move(stop.message);
    return report;
  }
  report.time = report.fast.end_time;
  if (!report.fast.ok()) {
    report.status = SplitStatus::FastFailure;
    report.message = report.fast.message;
  }
  return report;
}

}  // namespace runin::continuum
