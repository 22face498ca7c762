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

double ArchardWear::stable_slip_step(double contact_stiffness_per_area) const
{
  if (!(contact_stiffness_per_area > 0.0)) throw InvalidCoefficient("k_c: contact stiffness per area must be > 0");
  if (factor_ == 0.0) return HUGE_VAL;
  return 2.0 / (factor_ * contact_stiffness_per_area);
}

WearExchangeRule::WearExchangeRule(double share_a, double transfer) : share_a_(share_a), transfer_(transfer)
{
  if (!(transfer >= 0.0 && transfer <= 1.0)) throw InvalidCoefficient("transfer: fraction must be in [0, 1]");
}

WearExchange exchange_wear(double removed, double share_a, double transfer)
{
  return WearExchangeRule(share_a, transfer).split(removed);
}

}    // namespace runin::tribo
