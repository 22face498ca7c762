#include "tribo/cycle_jump.h"

#include "tribo/contact.h"

#include <algorithm>
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

double jump_depth_by_rate(double depth, double change, double tolerance, double floor_reference)
{
  if (!(depth > 0.0) || !std::isfinite(depth)) throw InvalidCoefficient("rate: jump depth must be > 0 and finite");
  if (!(change >= 0.0) || !std::isfinite(change))
    throw InvalidCoefficient("rate: measured change must be >= 0 and finite");
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw InvalidCoefficient("rate: tolerance T must be in (0, 1)");
  if (!(floor_reference > 0.0) || !std::isfinite(floor_reference))
    throw InvalidCoefficient("max_depth: must be > 0 and finite");
  const double factor = change > 0.5 * tolerance ? std::clamp(tolerance / change, 0.5, 2.0) : 2.0;
  return std::max(depth * factor, 1e-3 * floor_reference);
}

void check_max_change(double max_change)
{
  if (!(max_change > 0.0) || !std::isfinite(max_change))
    throw InvalidCoefficient("max_change: largest change of a summit's height per jump must be > 0 and finite");
}

}    // namespace runin::tribo
