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

double ArchardWear::stable_slip_step(double contact_stiffness_per_area) const
{
  if (!(contact_stiffness_per_area > 0.0)) throw InvalidCoefficient("k_c: contact stiffness per area must be > 0");
  if (factor_ == 0.0) return HUGE_VAL;
  return 2.0 / (factor_ * contact_stiffness_per_area);
}

}    // namespace runin::tribo
