// Subsurface stress of the line contacts (continuum/contact_stress.h, doc/subsurface_stress.md): the element
// wiring of the journal bearing (bore_contact_stress / bore_hertz_stress) and the piston ring face
// (ring_face_stress / ring_face_hertz_stress). The influence tier on the pressure each element's contact solver
// gives for the unworn, Hertzian start must reproduce McEwen's closed form on the Hertz contact.
#include "continuum/contact_stress.h"
#include "continuum/conformal_contact.h"
#include "continuum/journal_bearing.h"
#include "continuum/ring_liner_wear.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

using namespace runin;

namespace {

tribo::Material steel() {
  tribo::Material m;
  m.youngs_modulus = 200e9, m.poisson_ratio = 0.29, m.hardness = 1.19e9, m.yield_strength = 350e6;
  return m;
}
tribo::Material grey_iron() {
  tribo::Material m;
  m.youngs_modulus = 66e9, m.poisson_ratio = 0.27, m.hardness = 1.53e9;
  return m;
}

double rel(double a, double b) { return std::abs(a / b - 1.0); }

// inputs/journal_bearing.toml: R = 12.5 mm, c = 25 um, L = 25 mm, W = 9.81 N per half, 256 nodes on +-0.3 rad.
continuum::BoreGeometry thesis_bore() {
  continuum::BoreGeometry b;
  b.shaft_radius = 12.5e-3, b.clearance = 25e-6, b.axial_width = 25e-3;
  b.youngs_modulus = 200e9, b.poisson_ratio = 0.29, b.arc_half_angle = 0.3, b.nodes = 256;
  return b;
}

}  // namespace

// Thesis journal bearing at the start of the run: the solved conformal pressure (about 12 nodes across the
// contact) through the Flamant tier gives McEwen's peak von Mises stress of both bodies within 2 % at mu = 0,
// 0.3 and the thesis's 0.95 (doc/subsurface_stress.md lists the measured differences).
TEST(LineContactStress, JournalStartMatchesMcEwen) {
  const auto bore = thesis_bore();
  const continuum::ConformalContact contact(bore);
  const double w = 9.81 / bore.axial_width;
  const auto solution = contact.solve(w);
  ASSERT_TRUE(solution.ok());
  for (double mu : {0.0, 0.3, 0.95, -0.95}) {
    const auto solved = continuum::bore_contact_stress(contact, solution.pressure, mu, steel(), steel());
    const auto hertz = continuum::bore_hertz_stress(bore, w, mu, steel(), steel());
    std::cout << "journal mu = " << mu << ": bearing " << solved.a.peak.von_mises << " vs McEwen "
              << hertz.a.peak.von_mises << " Pa (" << 100 * rel(solved.a.peak.von_mises, hertz.a.peak.von_mises)
              << " %), shaft " << solved.b.peak.von_mises << " vs " << hertz.b.peak.von_mises << " Pa ("
              << 100 * rel(solved.b.peak.von_mises, hertz.b.peak.von_mises) << " %)\n";
    EXPECT_LT(rel(solved.a.peak.von_mises, hertz.a.peak.von_mises), 0.02) << "mu = " << mu;
    EXPECT_LT(rel(solved.b.peak.von_mises, hertz.b.peak.von_mises), 0.02) << "mu = " << mu;
    EXPECT_LT(rel(solved.half_width, hertz.half_width), 0.1);
    // q = mu p on the bearing in +x, -q on the shaft: with like materials the fields are mirror images.
    EXPECT_NEAR(solved.a.peak.von_mises, solved.b.peak.von_mises, 1e-2 * solved.a.peak.von_mises);  // grid not mirror-symmetric
    EXPECT_FALSE(solved.a.yields());
  }
  // mu = 0: the subsurface maximum of Johnson eq. 4.50, 0.557 p0 at 0.70 b (nu = 0.3; 0.29 here).
  const auto frictionless = continuum::bore_hertz_stress(bore, w, 0.0, steel(), steel());
  EXPECT_NEAR(frictionless.a.peak.von_mises / frictionless.peak_pressure, 0.56, 0.01);
  EXPECT_NEAR(frictionless.a.peak.z / frictionless.half_width, 0.70, 0.03);
}

// Thesis ring A (inputs/piston_ring.toml): crown 2 um on a 10 mm face, W = 628 N, 128 ring cells (half-plane
// BEM): the ring-face wiring against McEwen within 2 %, and the crown's Hertz contact (b = 0.67 mm).
TEST(LineContactStress, RingFaceStartMatchesMcEwen) {
  continuum::RingLinerWearSettings s;
  s.contact = continuum::FaceContact::HalfPlane;
  s.bore = 0.1, s.ring_width = 0.01, s.crown_height = 2e-6, s.ring_cells = 128;
  s.liner_begin = 0.0, s.liner_end = 0.1, s.liner_cells = 512;
  s.contact_modulus = 66e9 / (2.0 * (1.0 - 0.27 * 0.27));
  const continuum::RingLinerWear face(s, tribo::ArchardWear(1e-4, 2e9));
  const double load = 0.2e6 * M_PI * 0.1 * 0.01;
  const auto contact = face.pressure(0.05, load);
  for (double mu : {0.0, 0.3, 0.95}) {
    const auto solved = continuum::ring_face_stress(face, contact.pressure, mu, grey_iron(), grey_iron());
    const auto hertz = continuum::ring_face_hertz_stress(s, load, mu, grey_iron(), grey_iron());
    ASSERT_TRUE(hertz.has_value());
    std::cout << "ring face mu = " << mu << ": liner " << solved.a.peak.von_mises << " vs McEwen "
              << hertz->a.peak.von_mises << " Pa (" << 100 * rel(solved.a.peak.von_mises, hertz->a.peak.von_mises)
              << " %)\n";
    EXPECT_NEAR(hertz->half_width, 0.6687e-3, 0.001e-3);
    EXPECT_LT(rel(solved.a.peak.von_mises, hertz->a.peak.von_mises), 0.02) << "mu = " << mu;
    EXPECT_LT(rel(solved.b.peak.von_mises, hertz->b.peak.von_mises), 0.02) << "mu = " << mu;
  }
  // A flat face (no crown) is not Hertzian: no closed form.
  s.crown_height = 0.0;
  EXPECT_FALSE(continuum::ring_face_hertz_stress(s, load, 0.3, grey_iron(), grey_iron()).has_value());
}

// The yield verdict: S_y when known, Tabor's H / 2.8 otherwise; yields() above it.
TEST(LineContactStress, YieldVerdict) {
  bool tabor = true;
  EXPECT_DOUBLE_EQ(continuum::verdict_yield_strength(steel(), &tabor), 350e6);
  EXPECT_FALSE(tabor);
  EXPECT_NEAR(continuum::verdict_yield_strength(grey_iron(), &tabor), 1.53e9 / 2.8, 1.0);
  EXPECT_TRUE(tabor);
  tribo::Material weak = steel();
  weak.yield_strength = 1e6;  // below the start peak of the thesis journal (2.6 MPa at mu = 0.95)
  const auto s = continuum::bore_hertz_stress(thesis_bore(), 9.81 / 25e-3, 0.95, weak, steel());
  EXPECT_TRUE(s.a.yields());
  EXPECT_FALSE(s.b.yields());
}

TEST(LineContactStress, BadInput) {
  const std::vector<double> x = {0.0, 1.0, 2.0}, p = {0.0, 1.0, 0.0};
  EXPECT_THROW(continuum::line_contact_stress(x, {1.0, 2.0}, 0.3, steel(), steel()), std::invalid_argument);
  EXPECT_THROW(continuum::line_contact_stress(x, {0.0, 0.0, 0.0}, 0.3, steel(), steel()), std::invalid_argument);
  EXPECT_THROW(continuum::line_contact_stress({0.0, 1.0, 3.0}, p, 0.3, steel(), steel()), std::invalid_argument);
  EXPECT_NO_THROW(continuum::line_contact_stress(x, p, 0.3, steel(), steel()));
}
