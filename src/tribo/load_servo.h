// Load-control servo for a rigid counterface (fix runin/wall): how far to move the wall toward the
// asperities in one step to approach a target normal force. Header-only, no LAMMPS, SI units.
#pragma once

#include "tribo/contact.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace runin::tribo {

// F(u) is the total contact force at wall approach u and K = dF/du the contact stiffness.
// Above the target the step is Newton's on F; below it, Newton's on ln F:
//   u += g (F_t - F) / K          (F > F_t)
//   u += g (F / K) ln(F_t / F)    (F < F_t)
// A sum of Hertz contacts is convex in u, so the first never undershoots; F is log-concave for one
// Hertz contact (ln F = 3/2 ln delta + c) and for the Gaussian Greenwood-Williamson load, so the second
// never overshoots. With 0 < g <= 1 the force therefore approaches the target monotonically. Steps
// are capped at max_step; without contact (F = 0 or K = 0) the wall advances by max_step.
class LoadServo {
 public:
  LoadServo(double gain, double max_step) : gain_(gain), max_step_(max_step)
  {
    if (!(gain > 0.0 && gain <= 1.0))
      throw InvalidCoefficient("gain: servo gain must be in (0, 1], got " + std::to_string(gain));
    if (!(max_step > 0.0))
      throw InvalidCoefficient("max_step: servo step limit must be > 0, got " + std::to_string(max_step));
  }

  double approach(double force, double stiffness, double target) const
  {
    if (!(force > 0.0) || !(stiffness > 0.0)) return max_step_;
    const double step = force > target ? gain_ * (target - force) / stiffness
                                       : gain_ * force / stiffness * std::log(target / force);
    return std::clamp(step, -max_step_, max_step_);
  }

  double gain() const { return gain_; }
  double max_step() const { return max_step_; }

 private:
  double gain_, max_step_;
};

}    // namespace runin::tribo
