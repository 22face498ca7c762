#include "tribo/wear.h"

#include "tribo/contact.h"

#include <cmath>

namespace runin::tribo {

ArchardWear::ArchardWear(double k, double hardness, ArchardForm form)
    : k_(k), hardness_(hardness), form_(form)
{
  if (!(k >= 0.0)) throw InvalidCoefficient("k: wear coefficient must be >= 0");
  if (!(hardness > 0.0)) throw InvalidCoefficient("H: hardness must be > 0");
  factor_ = k / (form == ArchardForm::thesis ? 3.0 * hardness : hardness);
}

double ArchardWear::volume(double normal_force, double slip_distance) const
{
  return factor_ * std::fabs(normal_force) * std::fabs(slip_distance);
}

}    // namespace runin::tribo
