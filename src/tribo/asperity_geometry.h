// Worn-asperity geometry and the normal contact of a worn (flat-topped) asperity.
// Pure functions, no LAMMPS, no I/O; SI units. Derivations: doc/worn_asperity_geometry.md.
#pragma once

#include "tribo/contact.h"    // InvalidCoefficient

#include <algorithm>
#include <cmath>

namespace runin::tribo {

// A sphere of radius R whose summit cap of height h has been removed (exact truncated sphere).
// h is valid in [0, 2R]; the flat is widest at h = R (a hemisphere).
class TruncatedSphere {
 public:
  explicit TruncatedSphere(double radius) : radius_(radius)
  {
    if (!(radius > 0.0) || !std::isfinite(radius)) throw InvalidCoefficient("R: asperity radius must be > 0");
  }

  // Removed cap volume V(h) = pi h^2 (3R - h) / 3.
  double cap_volume(double cap_height) const;
  // Radius of the flat left by the cut: a_w^2 = 2 R h - h^2.
  double flat_radius(double cap_height) const
  {
    cap_height = std::clamp(cap_height, 0.0, 2.0 * radius_);
    return std::sqrt(cap_height * (2.0 * radius_ - cap_height));
  }
  // Exact inverse of cap_volume on [0, 4/3 pi R^3]: the root of h^3 - 3 R h^2 + 3 V / pi = 0 in [0, 2R]
  // (trigonometric closed form, polished by Newton to round-off). Volumes beyond the whole sphere clamp.
  double cap_height(double removed_volume) const;
  // The same root from a nearby height (the previous one of an asperity that wears a little per step), by
  // a fifth-order step and a Newton step instead of the acos/cos: exact to the same round-off. A
  // near_height that is already the root is returned unchanged (a refresh of an unchanged volume, e.g.
  // after a restart, is bit for bit). Falls back to cap_height(V) for near_height outside (0, 1.5 R)
  // (h(V) is ill-conditioned towards 2R) or when a few steps do not settle. Header-inline: it runs for
  // every worn asperity and step.
  double cap_height(double removed_volume, double near_height) const;
  double sphere_volume() const;
  double radius() const { return radius_; }

 private:
  double radius_;
};

// Steps from h solve F(h + d) = 0 for the cubic F(h) = R h^2 - h^3 / 3 - V / pi (= (V(h) - V) / pi).
// The first is series reversion: with t = -F/F', a = F''/(2F'), b = F'''/(6F') (F' = h (2R - h) = a_w^2,
// F'' = 2 (R - h), F''' = -2), d = t - a t^2 + (2a^2 - b) t^3 + 5a (b - a^2) t^4 leaves an error of about
// (t/h)^5 h: below 1e-10 h for the per-step refresh (|t| <= 1e-2 h). One Newton step then squares it to
// below round-off. Two divisions in a fixed sequence: the branches stay predictable, whatever the step.
inline double TruncatedSphere::cap_height(double volume, double near_height) const
{
  constexpr double kPi = 3.14159265358979323846;
  constexpr double kInvPi = 1.0 / kPi;
  if (!(volume > 0.0)) return 0.0;
  const double R = radius_;
  if (volume >= 4.0 / 3.0 * kPi * R * R * R) return 2.0 * R;
  const double target = volume * kInvPi;
  double h = near_height;
  if (!(h > 0.0 && h < 1.5 * R)) return cap_height(volume);
  for (int iteration = 0; iteration < 4; ++iteration) {
    const double inv_slope = 1.0 / (h * (2.0 * R - h));
    const double t = -(h * h * (R - h * (1.0 / 3.0)) - target) * inv_slope;
    // already the root to ~2 ulp (the round-off of F): keep the stored height
    if (iteration == 0 && std::fabs(t) <= 4e-16 * h) return near_height;
    const double a = (R - h) * inv_slope;
    const double b = -(1.0 / 3.0) * inv_slope;
    const double step = t * (1.0 + t * (-a + t * ((2.0 * a * a - b) + t * (5.0 * a * (b - a * a)))));
    const bool polish = std::fabs(t) <= 1e-2 * h;
    h += step;
    if (!(h > 0.0 && h < 1.5 * R)) break;
    if (polish) return h - (h * h * (R - h * (1.0 / 3.0)) - target) / (h * (2.0 * R - h));
  }
  return cap_height(volume);
}


// Geometry of one asperity after wear (volume_lost) and transfer (volume_gained).
// Gained material refills the worn cap first; a net gain beyond the intact sphere raises the summit
// as a layer of the same volume spread over the projected disc pi R^2 (summit_drop < 0, no flat).
struct WornAsperity {
  double summit_drop = 0.0;    // h > 0: summit lowered by wear; < 0: raised by deposited material [m]
  double flat_radius = 0.0;    // a_w [m]
};
WornAsperity worn_asperity(double radius, double volume_lost, double volume_gained);
// The net-gain branch of worn_asperity (net_removed = lost - gained < 0): the layer raises the summit.
inline WornAsperity raised_by_deposit(double radius, double net_removed)
{
  constexpr double kPi = 3.14159265358979323846;
  return {net_removed / (kPi * radius * radius), 0.0};
}
// The same, starting the cap-height root from the asperity's previous summit drop (see cap_height): the
// per-step refresh of an asperity whose volumes changed a little.
inline WornAsperity worn_asperity(double radius, double volume_lost, double volume_gained,
                                  double previous_summit_drop)
{
  const double net_removed = volume_lost - volume_gained;
  // inline: half the asperities of a transfer run gain
  if (net_removed < 0.0) return raised_by_deposit(radius, net_removed);
  if (!(previous_summit_drop > 0.0)) return worn_asperity(radius, volume_lost, volume_gained);
  const TruncatedSphere sphere(radius);
  WornAsperity out;
  out.summit_drop = sphere.cap_height(net_removed, previous_summit_drop);
  out.flat_radius = sphere.flat_radius(out.summit_drop);
  return out;
}

// The part of a summit's drop (wear depth h > 0) that plastic flattening left, when the summit has lost
// `volume_flattened` to flattening and its cap V(h) = pi h^2 (3R - h) / 3 in all (wear and flattening together):
// h V_flattened / V(h), at most h; 0 for h <= 0. All of h for a summit that was only flattened.
inline double flattened_part_of_drop(double radius, double drop, double volume_flattened)
{
  constexpr double kPiThird = 3.14159265358979323846 / 3.0;
  if (!(drop > 0.0) || !(volume_flattened > 0.0)) return 0.0;
  const double cap = kPiThird * drop * drop * (3.0 * radius - drop);
  return volume_flattened >= cap ? drop : drop * (volume_flattened / cap);
}

// Everything the force loop needs from the Sneddon contact at one overlap (FlatHertzNormal::evaluate).
struct FlatHertzContact {
  double contact_radius = 0.0;    // a [m]
  double curved_radius = 0.0;     // c = sqrt(a^2 - b^2) [m]
  double force = 0.0;             // F [N]
  double stiffness = 0.0;         // 2 E* a [N/m]
};

// FlatHertzNormal's a, c, F and k in one pass (two square roots and a division for a flat, one root for
// b = 0, where it is Hertz), header-inline for force loops. Takes the coefficients as FlatHertzNormal
// validated them (E* > 0, R* > 0, b >= 0) and does not check them again. Agrees with the member functions
// to round-off.
inline FlatHertzContact flat_hertz_contact(double e_eff, double r_eff, double flat, double overlap)
{
  FlatHertzContact out;
  if (!(overlap > 0.0)) return out;
  const double rd = r_eff * overlap;
  if (flat == 0.0) {
    out.contact_radius = out.curved_radius = std::sqrt(rd);
    out.force = 4.0 / 3.0 * e_eff * out.contact_radius * overlap;
  } else {
    // a^2 = (b^2 + sqrt(b^4 + 4 (R delta)^2)) / 2 (a sum, no cancellation) and a c = R delta, so
    // c = R delta / a and F = 2 E* / (3R) c (2a^2 + b^2) = 2/3 E* delta (2a^2 + b^2) / a: one division
    const double b2 = flat * flat;
    const double a2 = 0.5 * (b2 + std::sqrt(b2 * b2 + 4.0 * rd * rd));
    out.contact_radius = std::sqrt(a2);
    const double inv_a = 1.0 / out.contact_radius;
    out.curved_radius = rd * inv_a;
    out.force = 2.0 / 3.0 * e_eff * overlap * (2.0 * a2 + b2) * inv_a;
  }
  out.stiffness = 2.0 * e_eff * out.contact_radius;
  return out;
}

// Normal contact of a truncated paraboloid (flat radius b, curvature radius R) on a flat elastic
// half-space, Sneddon's solution (flat punch + Hertz):
//   a^2 = (b^2 + sqrt(b^4 + 4 R^2 delta^2)) / 2,  c = sqrt(a^2 - b^2) = R delta / a,
//   F = (2 E* / (3 R)) c (2 a^2 + b^2),  dF/ddelta = 2 E* a.
// b = 0 gives Hertz; delta -> 0 gives the flat punch, F = 2 E* b delta.
class FlatHertzNormal {
 public:
  FlatHertzNormal(double effective_modulus, double effective_radius, double flat_radius);

  double contact_radius(double overlap) const;   // a
  double force(double overlap) const;
  double stiffness(double overlap) const;         // 2 E* a
  double elastic_energy(double overlap) const;    // integral of F d(delta)
  // Half-width of the curved (ploughing) ring seen from the axis: c = sqrt(a^2 - b^2).
  double curved_radius(double overlap) const;
  double flat_radius() const { return flat_; }
  FlatHertzContact evaluate(double overlap) const { return flat_hertz_contact(e_eff_, r_eff_, flat_, overlap); }

 private:
  double e_eff_, r_eff_, flat_;
};

// How the flats of two worn asperities combine into one contact: the smaller flat. Exact for equal
// flats (the gap is then (r^2 - b^2) / 2R* outside r = b); see doc/worn_asperity_geometry.md.
inline double combined_flat_radius(double flat_i, double flat_j)
{
  return flat_i < flat_j ? flat_i : flat_j;
}

}    // namespace runin::tribo
