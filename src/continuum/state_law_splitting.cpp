#include "continuum/state_law_splitting.h"

namespace runin::continuum {

const char *to_string(SplitStatus status) {
  switch (status) {
    case SplitStatus::Success: return "success";
    case SplitStatus::FastFailure: return "dynamics failed";
    case SplitStatus::LawOutOfRange: return "state law out of range";
    case SplitStatus::InvalidState: return "invalid state";
    case SplitStatus::SlowFailure: return "wear step failed";
    case SplitStatus::TooManySlowSteps: return "too many wear steps";
  }
  return "unknown";
}

}  // namespace runin::continuum
