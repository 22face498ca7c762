// Subsurface stress below the contacts of the three elements (doc/subsurface_stress.md): the
// per-body von Mises peak against the yield strength, shared by the pin-on-disk (axisymmetric, in
// pin_on_disk.h) and the line contacts of the journal bearing (arc x = R theta along the bore) and the piston
// ring (axial coordinate along the ring face).
#pragma once

#include <string>
#include <vector>

#include "tribo/contact.h"
#include "tribo/subsurface_stress.h"

namespace runin::continuum {

// One body of a contact: its von Mises field on the section and the peak against S_y.
struct BodyStress {
  double poisson_ratio = 0.0;
  double yield_strength = 0.0;  // Pa; 0: unknown (no verdict)
  tribo::StressPeak peak;       // largest von Mises stress on the section and its place (z = depth)
  tribo::StressField field;
  bool yields() const { return yield_strength > 0.0 && peak.von_mises > yield_strength; }
};
// The body's stress summary from its field (peak on the whole grid).
BodyStress body_stress(const tribo::Material &material, tribo::StressField field);

// A 2-D (plane strain) line contact between two bodies a and b. The friction shear on body a is q = +mu p
// in +x (the counterface b slides over a in +x); b carries -q. mu may have either sign (sliding direction).
// Both fields use the same x (surface coordinate) and z (depth) grid.
struct LineContactStress {
  std::string method;                 // "Hertz closed form (McEwen 1949)" or "influence functions (...)"
  double friction_coefficient = 0.0;  // mu: q = mu p on body a
  double centre = 0.0;                // m, middle of the loaded width
  double half_width = 0.0;            // m, b of the pressure used (half the loaded width)
  double peak_pressure = 0.0;         // Pa
  BodyStress a, b;
};

// Subsurface stress at the start and the end of a run (doc/subsurface_stress.md). Start: the unworn contact, McEwen's
// closed form on its Hertz contact when the solved peak pressure is within 5 % of Hertz p0 (else the influence
// tier), with mu at break-away; end: the influence tier on the last solved (worn) pressure with the mu of the last
// slip sample. mu is signed by the sliding direction.
struct StartEndStress {
  double mu_start = 0.0, mu_end = 0.0;
  LineContactStress start, end;
  double solved_peak = 0.0;          // Pa, peak of the solved unworn pressure
  double hertz_peak = 0.0;           // Pa, Hertz p0 of the unworn contact; 0: not Hertzian in shape
  bool closed_form = false;          // the start frame is the closed form
  static constexpr double hertz_tolerance = 0.05;
};

// Hertzian line contact p = p0 sqrt(1 - (x - centre)^2/b^2): McEwen's closed form on points x points, the
// section [centre - 1.5 b, centre + 1.5 b] x [0, 1.5 b] (x at cell centres).
LineContactStress hertz_line_contact_stress(double peak_pressure, double half_width, double friction_coefficient,
                                            const tribo::Material &a, const tribo::Material &b, double centre = 0.0,
                                            int points = 48);

// Any nodal line pressure (a contact solver's output at uniformly spaced nodes x_nodes, the worn profile): the
// Flamant influence tier on the strips of the loaded nodes (LineTraction::from_nodes), q = mu p. The section is
// 1.5 b either side of the loaded width's centre and 1.5 b deep, about `points` x `points` points (48 by default); the x
// points are spaced h / m (m odd) from a node, so none lies on a strip edge (where the surface stress of a
// shear jump is log-singular). Throws std::invalid_argument for mismatched sizes, non-uniform nodes or no load.
LineContactStress line_contact_stress(const std::vector<double> &x_nodes, const std::vector<double> &pressure,
                                      double friction_coefficient, const tribo::Material &a,
                                      const tribo::Material &b, int points = 48);

// The yield strength of a material for the verdict: S_y if known, else Tabor's H / 2.8 (0 if neither);
// `tabor` tells which.
double verdict_yield_strength(const tribo::Material &material, bool *tabor = nullptr);

}  // namespace runin::continuum
