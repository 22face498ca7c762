// Archard wear kernels.
#pragma once

#include <cmath>

namespace runin::tribo {

// The thesis's eq. 1.4 carries a factor 1/3 (V = k W s / (3H)); most texts omit it.
enum class ArchardForm { plain, thesis };

class ArchardWear {
 public:
  // k: dimensionless wear coefficient; hardness of the softer body in Pa.
  ArchardWear(double wear_coefficient, double hardness, ArchardForm form = ArchardForm::plain);

  // Worn volume for a normal load |W| and a slip distance |ds|: k |W| |ds| / H (or / 3H).
  double volume(double normal_force, double slip_distance) const
  {
    return factor_ * std::fabs(normal_force) * std::fabs(slip_distance);
  }
  // Wear depth per unit slip under contact pressure p: dh/ds = (k/H) p (or k p / 3H).
  double depth_rate(double pressure) const { return factor_ * pressure; }
  // Largest stable explicit wear step (slip distance) on a surface whose pressure falls by
  // k_c [Pa/m] per unit wear depth. The linearised update h += (k/H)(p0 - k_c h) ds has the
  // amplification factor 1 - (k/H) k_c ds, so it is stable for ds < 2H/(k k_c).
  double stable_slip_step(double contact_stiffness_per_area) const;
  double coefficient() const { return k_; }
  double hardness() const { return hardness_; }
  ArchardForm form() const { return form_; }

 private:
  double k_, hardness_;
  ArchardForm form_;
  double factor_;    // k / H, or k / (3H)
};

// Share of a contact's worn volume taken by body a: proportional to 1/H (the softer body wears more).
inline double wear_share(double hardness_a, double hardness_b)
{
  return hardness_b / (hardness_a + hardness_b);
}

// Where one contact's removed volume goes: each body loses its 1/H share, and the fraction
// 'transfer' of what it loses is deposited on the other body; the rest leaves as debris.
// removed = lost_a + lost_b = gained_a + gained_b + debris.
struct WearExchange {
  double lost_a = 0.0, lost_b = 0.0;
  double gained_a = 0.0, gained_b = 0.0;
  double debris = 0.0;
};
// share_a from wear_share; transfer in [0, 1] (throws InvalidCoefficient otherwise).
WearExchange exchange_wear(double removed_volume, double share_a, double transfer);

// exchange_wear for one body pair, with the transfer fraction checked once (by the constructor) instead of
// per contact and step; header-inline for force loops. split(V) == exchange_wear(V, share_a, transfer).
class WearExchangeRule {
 public:
  WearExchangeRule(double share_a, double transfer);
  WearExchange split(double removed) const
  {
    WearExchange out;
    out.lost_a = removed * share_a_;
    out.lost_b = removed - out.lost_a;
    out.gained_a = transfer_ * out.lost_b;
    out.gained_b = transfer_ * out.lost_a;
    out.debris = (1.0 - transfer_) * removed;
    return out;
  }
  double share_a() const { return share_a_; }
  double transfer() const { return transfer_; }

 private:
  double share_a_, transfer_;
};

}    // namespace runin::tribo
