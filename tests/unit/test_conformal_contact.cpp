// Conformal bore contact (continuum/conformal_contact.h) against Hertz line contact and a
// fine-grid reference.
#include <gtest/gtest.h>

#include <cmath>

#include "continuum/conformal_contact.h"

using namespace runin::continuum;

namespace {

// Thesis ch. 5 bearing: d = 25 mm, c = 25 um, l = 25 mm, AISI 1020, W = 9.81 N.
BoreGeometry bearing(int nodes, double arc_half_angle = 0.05, double clearance = 25e-6) {
  return BoreGeometry{12.5e-3, clearance, 25e-3, 200e9, 0.29, arc_half_angle, nodes};
}
const double kLoadPerLength = 9.81 / 25e-3;

double hertz_a(const BoreGeometry &g) {
  const double reff = hertz_effective_radius(g.shaft_radius, g.shaft_radius + g.clearance);
  return hertz_half_width(kLoadPerLength, reff, g.contact_modulus());
}

}  // namespace

TEST(ConformalContact, LoadBalanceAndComplementarity) {
  const ConformalContact contact(bearing(200));
  const auto s = contact.solve(kLoadPerLength);
  ASSERT_EQ(s.status, ConformalStatus::Converged);
  double load = 0.0;
  for (int i = 0; i < contact.nodes(); ++i) load += s.pressure[i] * std::cos(contact.node_angle(i)) * contact.panel_length();
  EXPECT_NEAR(load / kLoadPerLength, 1.0, 1e-12);  // round-off tier
  // gap = c - e cos + K p: zero where p > 0, >= 0 elsewhere (active-set tolerance 1e-10 c).
  const auto &g = contact.geometry();
  Eigen::VectorXd p = Eigen::Map<const Eigen::VectorXd>(s.pressure.data(), contact.nodes());
  const Eigen::VectorXd up = contact.compliance() * p;
  for (int i = 0; i < contact.nodes(); ++i) {
    const double gap = g.clearance - s.approach * std::cos(contact.node_angle(i)) + up[i];
    EXPECT_GE(s.pressure[i], 0.0);
    if (s.pressure[i] > 0.0)
      EXPECT_NEAR(gap, 0.0, 1e-9 * g.clearance) << "node " << i;
    else
      EXPECT_GE(gap, -1e-10 * g.clearance) << "node " << i;
  }
  EXPECT_GT(s.normal_force_per_length, kLoadPerLength);  // cos(theta) < 1 over the arc
}

TEST(ConformalContact, HertzLineContactInTheLargeClearanceLimit) {
  // a / R = 0.014: the cylinder-in-concave-cylinder Hertz solution with R_eff = R1 R2 / (R2 - R1).
  const BoreGeometry g = bearing(400);
  const ConformalContact contact(g);
  const auto s = contact.solve(kLoadPerLength);
  ASSERT_EQ(s.status, ConformalStatus::Converged);
  const double a = hertz_a(g), p0 = hertz_peak_pressure(kLoadPerLength, a);
  // Half-width from the loaded panels (resolution one panel) and from the second moment
  // int p x^2 / int p = a^2 / 4 of the elliptical distribution.
  EXPECT_NEAR(s.contact_half_angle * g.shaft_radius, a, contact.panel_length());
  double m0 = 0.0, m2 = 0.0, rms = 0.0;
  for (int i = 0; i < contact.nodes(); ++i) {
    const double x = contact.node_angle(i) * g.shaft_radius;
    m0 += s.pressure[i];
    m2 += s.pressure[i] * x * x;
    const double hertz = std::abs(x) < a ? p0 * std::sqrt(1.0 - x * x / (a * a)) : 0.0;
    rms += (s.pressure[i] - hertz) * (s.pressure[i] - hertz);
  }
  EXPECT_NEAR(2.0 * std::sqrt(m2 / m0) / a, 1.0, 5e-3);
  EXPECT_NEAR(s.peak_pressure / p0, 1.0, 5e-3);  // O(c/R) = 2e-3 model difference + sampling
  EXPECT_LT(std::sqrt(rms / s.active_nodes) / p0, 0.02);
}

TEST(ConformalContact, PeakPressureConvergesWithGridRefinement) {
  // Observed order against a 1600-panel reference (measured 1.7 and 2.2).
  const double reference = ConformalContact(bearing(1600)).solve(kLoadPerLength).peak_pressure;
  double error[3];
  const int grids[3] = {100, 200, 400};
  for (int k = 0; k < 3; ++k)
    error[k] = std::abs(ConformalContact(bearing(grids[k])).solve(kLoadPerLength).peak_pressure - reference);
  EXPECT_GE(std::log2(error[0] / error[1]), 1.5);
  EXPECT_GE(std::log2(error[1] / error[2]), 1.5);
}

TEST(ConformalContact, SmallClearanceWidensTheContactAndRaisesThePressureIntegral) {
  // Closer conformity: wider arc, lower peak pressure, and N / W = int p / int p cos grows.
  const auto loose = ConformalContact(bearing(400, 0.3, 25e-6)).solve(kLoadPerLength);
  const auto close = ConformalContact(bearing(400, 0.3, 0.2e-6)).solve(kLoadPerLength);
  ASSERT_TRUE(loose.ok());
  ASSERT_TRUE(close.ok());
  EXPECT_GT(close.contact_half_angle, 2.0 * loose.contact_half_angle);
  EXPECT_LT(close.peak_pressure, 0.5 * loose.peak_pressure);
  EXPECT_GT(close.normal_force_per_length / kLoadPerLength, loose.normal_force_per_length / kLoadPerLength);
}

TEST(ConformalContact, ReportsAnArcTooShortForTheLoad) {
  const auto s = ConformalContact(bearing(100, 0.002)).solve(kLoadPerLength);
  EXPECT_EQ(s.status, ConformalStatus::ArcTooShort);
}

TEST(ConformalContact, StiffnessBoundsTheActiveSetModes) {
  // k_c ~ 1 / lambda_min(K) bounds every active-set stiffness (interlacing); checked against the
  // dense eigen solver.
  const ConformalContact contact(bearing(120));
  const double lambda_min =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(contact.compliance(), Eigen::EigenvaluesOnly).eigenvalues()[0];
  const double ratio = contact.contact_stiffness_per_area() * lambda_min;
  EXPECT_GE(ratio, 1.0);   // safe side
  EXPECT_LE(ratio, 1.05);  // and not needlessly small steps
}

TEST(ConformalContact, RejectsBadGeometry) {
  EXPECT_THROW(ConformalContact(bearing(2)), std::invalid_argument);
  EXPECT_THROW(ConformalContact(bearing(100, 2.0)), std::invalid_argument);
  EXPECT_THROW(ConformalContact(bearing(100, 0.05, -1e-6)), std::invalid_argument);
}
