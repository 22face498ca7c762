// Piston-ring face on the liner as an elastic half-plane line contact (the boundary-element kernel
// of half_plane_contact.h through RingLinerWear, FaceContact::HalfPlane), checked against the
// closed-form Hertz line contact of the parabolic crown (Johnson, Contact Mechanics, eq. 4.43-4.45):
//   crown g(z) = c (2 z / w)^2 = z^2 / (2 R)  =>  R = w^2 / (8 c)
//   b = sqrt(4 P' R / (pi E*)),   p0 = sqrt(P' E* / (pi R)) = 2 P' / (pi b),   p(z) = p0 sqrt(1 - z^2/b^2)
// with P' = W / (pi D) the load per unit circumference and E* = E / (2 (1 - nu^2)) (ring and liner
// of the same grey cast iron).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "continuum/half_plane_contact.h"
#include "continuum/ring_liner_wear.h"

using namespace runin::continuum;

namespace {
constexpr double kPi = 3.14159265358979323846;
// Thesis ring (ch. 6): bore 100 mm, width 10 mm, E = 66 GPa, nu = 0.27; the 2 um crown of
// inputs/piston_ring.toml; ring tension 0.2 MPa -> W = 628 N, P' = 2000 N/m.
constexpr double kBore = 0.1, kWidth = 0.01, kCrown = 2e-6, kE = 66e9, kNu = 0.27, kTension = 0.2e6;

double contact_modulus() { return kE / (2.0 * (1.0 - kNu * kNu)); }
double load() { return kTension * kPi * kBore * kWidth; }

RingLinerWearSettings half_plane(int cells) {
  RingLinerWearSettings s;
  s.contact = FaceContact::HalfPlane;
  s.bore = kBore;
  s.ring_width = kWidth;
  s.crown_height = kCrown;
  s.ring_cells = cells;
  s.liner_begin = 0.0;
  s.liner_end = 0.1;
  s.liner_cells = 512;
  s.contact_modulus = contact_modulus();
  return s;
}

struct Hertz {
  double b, p0;
  double at(double z) const { return std::abs(z) < b ? p0 * std::sqrt(1.0 - z * z / (b * b)) : 0.0; }
};
Hertz hertz() {
  const double q = load() / (kPi * kBore), radius = kWidth * kWidth / (8.0 * kCrown), es = contact_modulus();
  return {std::sqrt(4.0 * q * radius / (kPi * es)), std::sqrt(q * es / (kPi * radius))};
}

struct Errors {
  double peak, half_width, rms;  // relative to p0, b, p0
};
// Peak: the largest panel pressure against the closed form at that panel's centre. Half-width:
// from the second moment of the pressure, sum p z^2 / sum p = b^2 / 4 for the Hertz ellipse (the
// edge of the loaded panels is quantised by dz). rms: over all panels, relative to p0.
Errors errors_at(int cells, ContactPressure *out = nullptr) {
  const RingLinerWear face(half_plane(cells), runin::tribo::ArchardWear(1e-4, 2e9));
  const ContactPressure c = face.pressure(0.05, load());
  if (out) *out = c;
  const Hertz h = hertz();
  double m0 = 0.0, m2 = 0.0, sq = 0.0, peak_error = 0.0, peak = 0.0;
  for (int i = 0; i < cells; ++i) {
    const double z = face.ring_cell_centre(i), p = c.pressure[i];
    m0 += p;
    m2 += p * z * z;
    sq += std::pow(p - h.at(z), 2);
    if (p > peak) {
      peak = p;
      peak_error = std::abs(p - h.at(z)) / h.p0;
    }
  }
  return {peak_error, std::abs(2.0 * std::sqrt(m2 / m0) - h.b) / h.b, std::sqrt(sq / cells) / h.p0};
}
}  // namespace

TEST(RingFaceHalfPlane, ClosedFormNumbersOfTheThesisRing) {
  // The numbers: p0 about 1.9 MPa over 2b about 1.3 mm.
  const Hertz h = hertz();
  EXPECT_NEAR(h.p0, 1.9e6, 0.02e6);
  EXPECT_NEAR(2.0 * h.b, 1.34e-3, 0.02e-3);
}

TEST(RingFaceHalfPlane, MatchesTheHertzLineContactWithinOnePercent) {
  ContactPressure c;
  const Errors e = errors_at(1024, &c);
  std::printf("1024 cells: peak %.4g MPa (Hertz %.4g), peak error %.3e, half-width error %.3e, rms %.3e\n",
              1e-6 * c.peak, 1e-6 * hertz().p0, e.peak, e.half_width, e.rms);
  EXPECT_LT(e.peak, 0.01);
  EXPECT_LT(e.half_width, 0.01);
  EXPECT_LT(e.rms, 0.01);
  // load balance pi D sum p dz = W
  double sum = 0.0;
  for (double p : c.pressure) sum += p;
  EXPECT_NEAR(kPi * kBore * sum * kWidth / 1024, load(), 1e-9 * load());
}

// Grid convergence of the kernel itself. The error at one grid jumps with where the contact edge
// falls inside its panel (the panel just past b can carry a little pressure), so each level averages
// over 8 positions of the crown's centre within a panel (z_c = 0, dz/8, ..., 7 dz/8). Errors: L1 of
// the pressure against the closed form at the panel centres, relative to P' (the sqrt edge gives
// O(dz^1.5)); peak as above.
TEST(RingFaceHalfPlane, GridConvergesAtOrderOneOrMore) {
  const Hertz hz = hertz();
  const double q = load() / (kPi * kBore), radius = kWidth * kWidth / (8.0 * kCrown);
  std::vector<double> l1, peak;
  const std::vector<int> levels = {128, 256, 512, 1024, 2048};
  for (int n : levels) {
    const double dz = kWidth / n;
    const Eigen::MatrixXd k = symmetric_toeplitz(half_plane_influence_row(n, dz, contact_modulus(), kWidth));
    constexpr int kPhases = 8;
    double e1 = 0.0, ep = 0.0;
    for (int phase = 0; phase < kPhases; ++phase) {
      const double centre = dz * phase / kPhases;
      Eigen::VectorXd gap(n);
      for (int i = 0; i < n; ++i) gap[i] = std::pow(-0.5 * kWidth + (i + 0.5) * dz - centre, 2) / (2.0 * radius);
      std::vector<char> active(n, 0);
      const auto r = solve_line_contact(k, gap, Eigen::VectorXd::Ones(n), dz, q, 1e-10 * kCrown, active);
      ASSERT_TRUE(r.converged);
      double sum = 0.0, top = 0.0, top_error = 0.0;
      for (int i = 0; i < n; ++i) {
        const double z = -0.5 * kWidth + (i + 0.5) * dz - centre;
        sum += std::abs(r.pressure[i] - hz.at(z)) * dz;
        if (r.pressure[i] > top) {
          top = r.pressure[i];
          top_error = std::abs(top - hz.at(z)) / hz.p0;
        }
      }
      e1 += sum / q / kPhases;
      ep += top_error / kPhases;
    }
    l1.push_back(e1);
    peak.push_back(ep);
  }
  for (std::size_t k = 1; k < levels.size(); ++k) {
    const double l1_order = std::log2(l1[k - 1] / l1[k]), peak_order = std::log2(peak[k - 1] / peak[k]);
    std::printf("cells %4d -> %4d: L1 error %.3e -> %.3e (order %.2f), peak error %.3e -> %.3e (order %.2f)\n",
                levels[k - 1], levels[k], l1[k - 1], l1[k], l1_order, peak[k - 1], peak[k], peak_order);
    EXPECT_GE(l1_order, 1.0);
    EXPECT_GE(peak_order, 1.0);
  }
  EXPECT_LT(l1.back(), 1e-3);
}

TEST(RingFaceHalfPlane, ThesisGridOf128CellsIsWithinOnePercentOfHertz) {
  // inputs/piston_ring.toml: 128 ring cells, 17 across the contact (64 cells: half-width 1.8 % off)
  const Errors e = errors_at(128);
  std::printf("128 cells: peak error %.3e, half-width error %.3e\n", e.peak, e.half_width);
  EXPECT_LT(e.peak, 0.01);
  EXPECT_LT(e.half_width, 0.01);
}

TEST(RingFaceHalfPlane, CachedToeplitzBlocksGiveTheDirectSolve) {
  // The ring face reuses factorisations of contiguous blocks; the bore arc (ConformalContact) does not.
  const auto s = half_plane(256);
  const RingLinerWear face(s, runin::tribo::ArchardWear(1e-4, 2e9));
  const ContactPressure cached = face.pressure(0.05, load());
  const double dz = kWidth / 256;
  const Eigen::MatrixXd k = symmetric_toeplitz(half_plane_influence_row(256, dz, s.contact_modulus, kWidth));
  Eigen::VectorXd gap(256);
  for (int i = 0; i < 256; ++i) gap[i] = kCrown * std::pow(2.0 * face.ring_cell_centre(i) / kWidth, 2);
  std::vector<char> active(256, 0);
  const auto direct = solve_line_contact(k, gap, Eigen::VectorXd::Ones(256), dz, load() / (kPi * kBore),
                                         1e-10 * kCrown, active);
  ASSERT_TRUE(direct.converged);
  for (int i = 0; i < 256; ++i) EXPECT_NEAR(cached.pressure[i], direct.pressure[i], 1e-9 * hertz().p0);
}

TEST(RingFaceHalfPlane, WinklerLayerIsWiderAndLowerThanTheHalfPlane) {
  // The former model (k_c = E' / t): 1.08 MPa over 2.8 mm on 64 cells; the half-plane gives the Hertz contact.
  auto w = half_plane(64);
  w.contact = FaceContact::Winkler;
  w.foundation_modulus = kE / (1.0 - kNu * kNu) / 0.01;
  const ContactPressure winkler = RingLinerWear(w, runin::tribo::ArchardWear(1e-4, 2e9)).pressure(0.05, load());
  const ContactPressure bem = RingLinerWear(half_plane(64), runin::tribo::ArchardWear(1e-4, 2e9)).pressure(0.05, load());
  std::printf("64 cells: Winkler peak %.4g MPa over %.4g mm; half-plane peak %.4g MPa over %.4g mm\n",
              1e-6 * winkler.peak, 1e3 * winkler.width, 1e-6 * bem.peak, 1e3 * bem.width);
  EXPECT_GT(winkler.width, 1.8 * bem.width);
  EXPECT_LT(winkler.peak, 0.65 * bem.peak);
}
