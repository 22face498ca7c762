#include "continuum/stick_slip_loop.h"

namespace runin::continuum {

const char *to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::Success: return "success";
    case SolveStatus::IntegratorFailure: return "integrator failure";
    case SolveStatus::TooManyEvents: return "too many stick/slip events";
  }
  return "unknown";
}

}  // namespace runin::continuum
