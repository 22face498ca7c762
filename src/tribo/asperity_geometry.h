// Worn-asperity geometry and the normal contact of a worn (flat-topped) asperity.
// Pure functions, no LAMMPS, no I/O; SI units. Derivations: doc/worn_asperity_geometry.md.
#pragma once

namespace runin::tribo {

// A sphere of radius R whose summit cap of height h has been removed (exact truncated sphere).
// h is valid in [0, 2R]; the flat is widest at h = R (a hemisphere).
class TruncatedSphere {
 public:
  explicit TruncatedSphere(double radius);

  // Removed cap volume V(h) = pi h^2 (3R - h) / 3.
  double cap_volume(double cap_height) const;
  // Radius of the flat left by the cut: a_w^2 = 2 R h - h^2.
  double flat_radius(double cap_height) const;
  // Exact inverse of cap_volume on [0, 4/3 pi R^3]: the root of h^3 - 3 R h^2 + 3 V / pi = 0 in [0, 2R]
  // (trigonometric closed form, polished by Newton to round-off). Volumes beyond the whole sphere clamp.
  double cap_height(double removed_volume) const;
  double sphere_volume() const;
  double radius() const { return radius_; }

 private:
  double radius_;
};

// Geometry of one asperity after wear (volume_lost) and transfer (volume_gained).
// Gained material refills the worn cap first; a net gain beyond the intact sphere raises the summit
// as a layer of the same volume spread over the projected disc pi R^2 (summit_drop < 0, no flat).
struct WornAsperity {
  double summit_drop = 0.0;    // h > 0: summit lowered by wear; < 0: raised by deposited material [m]
  double flat_radius = 0.0;    // a_w [m]
};
WornAsperity worn_asperity(double radius, double volume_lost, double volume_gained);

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
