#include "tribo/cycle_jump.h"

#include "tribo/contact.h"

#include <cmath>

namespace runin::tribo {

double jump_extra(double requested, double phase_depth, double max_depth)
{
  if (!(requested >= 0.0) || !std::isfinite(requested))
    throw InvalidCoefficient("M: jump factor must be >= 1 and finite");
  if (!(max_depth > 0.0) || !std::isfinite(max_depth))
    throw InvalidCoefficient("max_depth: largest mean worn depth per jump must be > 0 and finite");
  if (!(phase_depth >= 0.0) || !std::isfinite(phase_depth))
    throw InvalidCoefficient("phase worn depth must be >= 0 and finite");
  if (phase_depth == 0.0) return 0.0;    // nothing wore (no contact in the phase): nothing to repeat
  return requested * phase_depth > max_depth ? max_depth / phase_depth : requested;
}

}    // namespace runin::tribo
