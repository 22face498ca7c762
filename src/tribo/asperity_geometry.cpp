#include "tribo/asperity_geometry.h"

#include "tribo/contact.h"

#include <algorithm>
#include <cmath>

namespace runin::tribo {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double TruncatedSphere::sphere_volume() const
{
  return 4.0 / 3.0 * kPi * radius_ * radius_ * radius_;
}

double TruncatedSphere::cap_volume(double h) const
{
  h = std::clamp(h, 0.0, 2.0 * radius_);
  return kPi * h * h * (3.0 * radius_ - h) / 3.0;
}

// In x = h/R and q = 3V/(pi R^3) in [0, 4]: x^2 (3 - x) = q. With x = 1 + y this is the depressed
// cubic y^3 - 3y + (q - 2) = 0, whose root in [-1, 1] is y = 2 cos((acos(1 - q/2) + 4 pi) / 3).
// That form loses relative accuracy as x -> 0 (1 + y cancels), so Newton on g(x) = x^2 (3 - x) - q
// finishes; g carries no cancellation beyond that of q itself.
double TruncatedSphere::cap_height(double volume) const
{
  if (!(volume > 0.0)) return 0.0;
  const double q = 3.0 * volume / (kPi * radius_ * radius_ * radius_);
  if (q >= 4.0) return 2.0 * radius_;
  double x = q < 1e-6 ? std::sqrt(q / 3.0) : 1.0 + 2.0 * std::cos((std::acos(1.0 - 0.5 * q) + 4.0 * kPi) / 3.0);
  for (int iteration = 0; iteration < 8; ++iteration) {
    const double slope = 3.0 * x * (2.0 - x);
    if (!(slope > 0.0)) break;    // x = 0 or 2: the ends, reached only for q = 0 or 4
    const double step = (x * x * (3.0 - x) - q) / slope;
    const double next = std::clamp(x - step, 0.0, 2.0);
    if (next == x) break;
    x = next;
    if (std::fabs(step) <= 1e-17 * x) break;
  }
  return x * radius_;
}

WornAsperity worn_asperity(double radius, double volume_lost, double volume_gained)
{
  const TruncatedSphere sphere(radius);
  const double net_removed = volume_lost - volume_gained;
  if (!(net_removed >= 0.0)) return raised_by_deposit(radius, net_removed);
  WornAsperity out;
  out.summit_drop = sphere.cap_height(net_removed);
  out.flat_radius = sphere.flat_radius(out.summit_drop);
  return out;
}

FlatHertzNormal::FlatHertzNormal(double effective_modulus, double effective_radius, double flat_radius)
    : e_eff_(effective_modulus), r_eff_(effective_radius), flat_(flat_radius)
{
  if (!(e_eff_ > 0.0)) throw InvalidCoefficient("E*: effective modulus must be > 0");
  if (!(r_eff_ > 0.0)) throw InvalidCoefficient("R*: effective radius must be > 0");
  if (!(flat_ >= 0.0)) throw InvalidCoefficient("b: flat radius must be >= 0");
}

// c^2 = a^2 - b^2 = 2 R^2 delta^2 / (sqrt(b^4 + 4 R^2 delta^2) + b^2): no cancellation for b >> sqrt(R delta).
double FlatHertzNormal::curved_radius(double overlap) const
{
  if (!(overlap > 0.0)) return 0.0;
  const double b2 = flat_ * flat_;
  const double rd = r_eff_ * overlap;
  const double root = std::sqrt(b2 * b2 + 4.0 * rd * rd);
  return std::sqrt(2.0 * rd * rd / (root + b2));
}

double FlatHertzNormal::contact_radius(double overlap) const
{
  if (!(overlap > 0.0)) return 0.0;
  const double c = curved_radius(overlap);
  return std::sqrt(flat_ * flat_ + c * c);
}

double FlatHertzNormal::force(double overlap) const
{
  if (!(overlap > 0.0)) return 0.0;
  const double c = curved_radius(overlap);
  const double a2 = flat_ * flat_ + c * c;
  return 2.0 * e_eff_ / (3.0 * r_eff_) * c * (2.0 * a2 + flat_ * flat_);
}

double FlatHertzNormal::stiffness(double overlap) const
{
  return 2.0 * e_eff_ * contact_radius(overlap);
}

// With delta = a c / R: F d(delta)/da = 2 E* (4 a^4 - b^4) / (3 R^2), integrated from a = b:
// U = 2 E* / (3 R^2) [4 (a^5 - b^5) / 5 - b^4 (a - b)], a - b = c^2 / (a + b) to avoid cancellation.
double FlatHertzNormal::elastic_energy(double overlap) const
{
  if (!(overlap > 0.0)) return 0.0;
  const double c = curved_radius(overlap);
  const double b = flat_;
  const double a = std::sqrt(b * b + c * c);
  const double a_minus_b = c * c / (a + b);
  const double a5_minus_b5 = a_minus_b * (a * a * a * a + a * a * a * b + a * a * b * b + a * b * b * b + b * b * b * b);
  return 2.0 * e_eff_ / (3.0 * r_eff_ * r_eff_) * (0.8 * a5_minus_b5 - b * b * b * b * a_minus_b);
}

}    // namespace runin::tribo
