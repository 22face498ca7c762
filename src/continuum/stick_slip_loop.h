// Event-driven stick/slip integration shared by the continuum solvers (pin-on-disk, journal
// bearing, piston ring). The system supplies its physics through a hooks object, CVODE is the
// stepper, the hooks' emit() is the observer; numerical failure ends up in the status.
//
// One CVODE problem per contact phase: stick ends when the break-away function crosses zero
// upwards, slip ends when the sliding velocity y[speed_index] (signed by the direction) crosses
// zero downwards. The integrator is restarted after each event and at the drive's kink, and
// the output grid gets a sample before and after each event and one at the kink. CVODE stops
// (lands exactly) only at the kink and at t_end; it steps across output times and returns them
// from its interpolant (CvodeIntegrator::advance_to_output), so outputs cost no steps.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "continuum/cvode_integrator.h"

namespace runin::continuum {

enum class ContactState { Stick = 0, Slip = 1 };

enum class SolveStatus { Success, IntegratorFailure, TooManyEvents };
const char *to_string(SolveStatus status);

struct SolveReport {
  SolveStatus status = SolveStatus::Success;
  std::string message;            // empty on success
  double end_time = 0.0;          // where the integration stopped
  std::vector<double> breakaway_times;
  std::vector<double> restick_times;
  long steps = 0;                 // CVODE internal steps

  bool ok() const { return status == SolveStatus::Success; }
};

struct StickSlipState {
  double t = 0.0;
  std::vector<double> y;
  ContactState state = ContactState::Stick;
  int direction = 0;  // sliding direction (+-1) in slip, 0 in stick
};

struct StickSlipGrid {
  double t_end = 0.0;
  double output_interval = 0.0;
  double kink = -1.0;              // time of a kink in the drive (ramp end), <= 0: none
  int max_events = 0;
  bool events = true;              // false: no stick/slip events (the drive keeps the contact sliding)
};

// Defaults for the optional hooks: no roots besides the stick/slip ones.
struct StickSlipHooksBase {
  void extra_roots(double, const double *, ContactState, double *) const {}
  std::vector<int> extra_root_directions(ContactState) const { return {}; }
  // Called when any extra root is found; false (with `message`) stops the run as a failure.
  bool on_extra_roots(StickSlipState &, const std::vector<int> &, std::string &) { return true; }
  // Called after each output-grid sample has been emitted: true when the system changed there (operator
  // splitting: the friction of the next interval was updated), so the integrator restarts from that sample.
  bool refresh(StickSlipState &) { return false; }
};

// rhs and emit for a system class with rhs(t, y, dydt, state, direction) and
// sample(t, y, state, direction) members, the sample going to `observer`.
template <class System, class Observer>
struct SystemHooks : StickSlipHooksBase {
  const System &system;
  const Observer &observer;

  SystemHooks(const System &sys, const Observer &obs) : system(sys), observer(obs) {}
  void rhs(double t, const double *y, double *dydt, ContactState state, int direction) const {
    system.rhs(t, y, dydt, state, direction);
  }
  void emit(const StickSlipState &s) { observer(system.sample(s.t, s.y.data(), s.state, s.direction)); }
};

// Hooks requirements (derive from StickSlipHooksBase for the optional ones):
//   std::size_t speed_index;   index of the sliding velocity in y, zeroed in stick
//   void rhs(double t, const double *y, double *dydt, ContactState state, int direction) const;
//   double breakaway_function(double t, const double *y) const;  // > 0: past the static limit
//   int breakaway_direction(double t, const double *y) const;    // direction of the slip that follows
//   void emit(const StickSlipState &s);
template <class Hooks>
class StickSlipLoop {
 public:
  StickSlipLoop(Hooks &hooks, const StickSlipGrid &grid, CvodeIntegrator &integrator, StickSlipState initial,
                SolveReport &report)
      : hooks_(hooks), grid_(grid), integrator_(integrator), s_(std::move(initial)), report_(report) {}

  StickSlipState &state() { return s_; }
  void emit() { hooks_.emit(s_); }

  void break_away() {
    report_.breakaway_times.push_back(s_.t);
    s_.state = ContactState::Slip;
    s_.direction = hooks_.breakaway_direction(s_.t, s_.y.data());
    s_.y[hooks_.speed_index] = 0.0;
  }

  // Emits the current state, then integrates to grid.t_end (or to a failure) and fills the report.
  void run() {
    const double round_off = 64.0 * std::numeric_limits<double>::epsilon() * grid_.t_end;
    emit();
    start_phase();
    long next_grid = 1;
    int events = 0;
    while (s_.t < grid_.t_end - round_off) {
      const double grid_time = std::min(static_cast<double>(next_grid) * grid_.output_interval, grid_.t_end);
      // CVODE stops only at the drive's kink and at the end; output times are sampled from its
      // interpolant (dense output), so the steps follow the solution, not the output grid.
      const bool kink_ahead = grid_.kink > 0.0 && s_.t < grid_.kink - round_off && grid_.kink < grid_.t_end - round_off;
      const double stop = kink_ahead ? grid_.kink : grid_.t_end;
      const bool at_stop = grid_time >= stop - round_off;  // the next output is the stop (or lies past it)
      const auto step = at_stop ? integrator_.advance_to_stop(stop) : integrator_.advance_to_output(grid_time, stop);
      s_.y = integrator_.state();
      s_.t = step.t;
      if (step.outcome == CvodeIntegrator::Outcome::Failed) {
        fail(SolveStatus::IntegratorFailure, "CVODE failed at t = " + std::to_string(s_.t) + " s: " + step.message);
        break;
      }
      // a non-finite state is reported, never written to the output
      if (!std::all_of(s_.y.begin(), s_.y.end(), [](double v) { return std::isfinite(v); })) {
        fail(SolveStatus::IntegratorFailure, "non-finite state at t = " + std::to_string(s_.t) + " s");
        break;
      }
      if (step.outcome == CvodeIntegrator::Outcome::FoundRoot) {
        if (found_extra_root(step.roots_found) && !hooks_.on_extra_roots(s_, step.roots_found, report_.message)) {
          report_.status = SolveStatus::IntegratorFailure;
          break;
        }
        if (step.roots_found[0] != 0) {
          emit();  // the event time joins the output, before and after the transition
          if (++events > grid_.max_events) {
            fail(SolveStatus::TooManyEvents, "more than " + std::to_string(grid_.max_events) +
                                                 " stick/slip events by t = " + std::to_string(s_.t) + " s");
            break;
          }
          transition();
          emit();
        }
        start_phase();
        continue;
      }
      emit();
      // a hook that changed the system (state law: mu_eff after the wear update) restarts CVODE from the sample
      const bool changed = hooks_.refresh(s_);
      if ((at_stop && kink_ahead) || changed) start_phase();  // restart at the kink instead of stepping across it
      if (!at_stop || grid_time <= stop + round_off) ++next_grid;  // the kink on an output time: one sample
    }
    report_.end_time = s_.t;
    report_.steps = integrator_.total_steps();
  }

 private:
  void fail(SolveStatus status, std::string message) {
    report_.status = status;
    report_.message = std::move(message);
  }

  bool found_extra_root(const std::vector<int> &roots_found) const {
    return std::any_of(roots_found.begin() + 1, roots_found.end(), [](int r) { return r != 0; });
  }

  void transition() {
    if (s_.state == ContactState::Stick) {
      break_away();
    } else if (hooks_.breakaway_function(s_.t, s_.y.data()) <= 0.0) {  // stopped below the static limit
      report_.restick_times.push_back(s_.t);
      s_.state = ContactState::Stick;
      s_.direction = 0;
    } else {  // stopped, but the drive exceeds the static limit: slide the other way
      report_.breakaway_times.push_back(s_.t);
      s_.direction = hooks_.breakaway_direction(s_.t, s_.y.data());
      s_.y[hooks_.speed_index] = 0.0;
    }
  }

  void start_phase() {
    Hooks &h = hooks_;
    const ContactState state = s_.state;
    const int dir = s_.direction;
    if (!grid_.events) {
      integrator_.restart(
          s_.t, s_.y, [&h, state, dir](double t, const double *y, double *dy) { h.rhs(t, y, dy, state, dir); },
          [](double, const double *, double *) {}, {});
      return;
    }
    std::vector<int> directions = {state == ContactState::Stick ? +1 : -1};
    for (int d : h.extra_root_directions(state)) directions.push_back(d);
    if (state == ContactState::Stick) {
      s_.y[h.speed_index] = 0.0;
      integrator_.restart(
          s_.t, s_.y, [&h](double t, const double *y, double *dy) { h.rhs(t, y, dy, ContactState::Stick, 0); },
          [&h](double t, const double *y, double *g) {
            g[0] = h.breakaway_function(t, y);
            h.extra_roots(t, y, ContactState::Stick, g + 1);
          },
          directions);
    } else {
      const std::size_t v = h.speed_index;
      integrator_.restart(
          s_.t, s_.y, [&h, dir](double t, const double *y, double *dy) { h.rhs(t, y, dy, ContactState::Slip, dir); },
          [&h, dir, v](double t, const double *y, double *g) {
            g[0] = dir * y[v];
            h.extra_roots(t, y, ContactState::Slip, g + 1);
          },
          directions);
    }
  }

  Hooks &hooks_;
  StickSlipGrid grid_;
  CvodeIntegrator &integrator_;
  StickSlipState s_;
  SolveReport &report_;
};

}  // namespace runin::continuum
