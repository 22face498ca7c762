// Per-node state law of the continuum contacts: pressure-weighted friction, the per-node wear
// integration against a closed form, the range policy and its counters. Synthetic laws only.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "continuum/node_state_law.h"

using namespace runin::coupling;
using runin::continuum::NodeStateLaw;

namespace {

constexpr double kH0 = 1e-6;   // m, depth the synthetic wear saturates at
constexpr double kC = 2e3;     // 1/m at p = 1e7 Pa
constexpr double kQ = 0.25;    // counterface rate / body rate

// mu = (0.3 - 1e5 h) (p / 1e7)^0.1 (linear in h, a power of p: the law's interpolation is exact);
// wear_rate = c(p) (h0 - h), c(p) = kC (p / 1e7)^0.5: exact too.
double mu_exact(double p, double h) { return (0.3 - 1e5 * h) * std::pow(p / 1e7, 0.1); }
double c_of(double p) { return kC * std::pow(p / 1e7, 0.5); }

// The depth grid: 10 equal cells, or (log_spaced) 0 and 16 depths log-spaced from 1e-5 h0 to h0, as the
// shipped laws to the settled depth are.
// zero_low_rates: no wear (body or counterface) at the lowest pressure, 1e6 Pa.
std::shared_ptr<const StateLaw> make_law(bool log_spaced = false, bool zero_low_rates = false) {
  const std::vector<double> p = {1e6, 1e7, 1e8};
  std::vector<double> h;
  if (log_spaced) {
    h.push_back(0.0);
    for (int j = 0; j <= 15; ++j) h.push_back(kH0 * std::pow(10.0, -5.0 + 5.0 * j / 15.0));
  } else {
    for (int j = 0; j <= 10; ++j) h.push_back(kH0 * j / 10.0);
  }
  std::array<StateFieldTable, state_field_count> fields;
  for (std::size_t f = 0; f < state_field_count; ++f) {
    auto &t = fields[f].mean;
    t.assign(p.size(), std::vector<double>(h.size(), 0.0));
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < h.size(); ++j) {
        const double w = zero_low_rates && i == 0 ? 0.0 : c_of(p[i]) * (kH0 - h[j]);
        switch (static_cast<StateField>(f)) {
          case StateField::MuBody: t[i][j] = mu_exact(p[i], h[j]); break;
          case StateField::Rq: t[i][j] = 1e-7; break;
          case StateField::Rsk: t[i][j] = -0.5; break;
          case StateField::AreaFraction: t[i][j] = 0.1; break;
          case StateField::WearRate: t[i][j] = w; break;
          case StateField::CounterfaceWearRate: t[i][j] = kQ * w; break;
          case StateField::SlidingDistance: t[i][j] = h[j] < kH0 ? -std::log(1.0 - h[j] / kH0) / c_of(p[i]) : 1.0; break;
        }
      }
  }
  return std::make_shared<const StateLaw>(p, h, fields);
}

}  // namespace

TEST(NodeStateLaw, UniformPressureGivesTheLawsMu) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 4);
  nodes.reset_state({2e-7, 2e-7, 2e-7, 2e-7});
  const std::vector<double> p(4, 3e7), area = {1.0, 2.0, 0.5, 3.0};
  EXPECT_NEAR(nodes.mu_effective(p, area), mu_exact(3e7, 2e-7), 1e-12);
  EXPECT_EQ(nodes.use().lookups, 4);
}

TEST(NodeStateLaw, TwoNodesArePressureWeightedAndUnloadedNodesAreNotLookedUp) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 3);
  nodes.reset_state({0.0, 3e-7, 5e-7});
  const std::vector<double> p = {2e6, 5e7, 0.0}, area = {1.0, 0.5, 7.0};  // node 3: p = 0, outside the grid
  const double f1 = 2e6 * 1.0, f2 = 5e7 * 0.5;
  const double expected = (mu_exact(2e6, 0.0) * f1 + mu_exact(5e7, 3e-7) * f2) / (f1 + f2);
  EXPECT_NEAR(nodes.mu_effective(p, area), expected, 1e-12);
  EXPECT_EQ(nodes.use().lookups, 2);
  const auto mu = nodes.node_mu(p);
  EXPECT_NEAR(mu[0], mu_exact(2e6, 0.0), 1e-12);
  EXPECT_NEAR(mu[1], mu_exact(5e7, 3e-7), 1e-12);
  EXPECT_EQ(mu[2], 0.0);
  // friction force = sum_i mu_i p_i A_i = mu_eff * W
  EXPECT_NEAR(mu[0] * f1 + mu[1] * f2, nodes.mu_effective(p, area) * (f1 + f2), 1e-9);
}

TEST(NodeStateLaw, WearIntegrationMatchesTheExponentialSolution) {
  // dh/ds = c (h0 - h), h(0) = 0: h = h0 (1 - exp(-c s)); counterface c_d = (kQ) h.
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 3);
  const std::vector<double> p = {1e7, 3.3e7, 0.0};
  double s = 0.0;
  for (double ds : {1e-4, 2.5e-4, 7e-4, 1e-3})  // uneven chunks: sub-stepping inside each
    for (int k = 0; k < 3; ++k) {
      nodes.advance(p, ds);
      s += ds;
      for (int i = 0; i < 2; ++i) {
        const double exact = kH0 * (1.0 - std::exp(-c_of(p[i]) * s));
        EXPECT_NEAR(nodes.state()[i], exact, 1e-6 * kH0) << "node " << i << " s = " << s;
        EXPECT_NEAR(nodes.counterface()[i], kQ * exact, 1e-6 * kH0);
      }
      EXPECT_EQ(nodes.state()[2], 0.0);  // unloaded: not worn
    }
  // monotone and bounded by the saturation depth
  EXPECT_LE(nodes.state()[0], kH0);
}

TEST(NodeStateLaw, ALargeSlideIsSubdividedStably) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 1);
  EXPECT_NEAR(nodes.substep_bound(), 0.05 / c_of(1e8), 1e-12);
  const auto inc = nodes.advance({1e7}, 0.05);  // 100 e-foldings in one call
  EXPECT_GT(inc.substeps, 100);
  EXPECT_NEAR(nodes.state()[0], kH0, 1e-9 * kH0);
  EXPECT_LE(nodes.state()[0], kH0 * (1 + 1e-12));
}

// On a log-spaced depth grid each node's sub-steps follow the cell it is in: a slide through all 16 cells takes
// tens of sub-steps, not the (finest cell / fastest rate) ones a global bound would take (3e5 here), and stays exact.
TEST(NodeStateLaw, SubStepsFollowTheNodesOwnDepthCell) {
  NodeStateLaw nodes(make_law(true), OutOfRange::Error, 2);
  const std::vector<double> p = {1e6, 1e7};
  const double ds = 1.0 / c_of(p[1]);   // one e-folding of the faster node
  const auto inc = nodes.advance(p, ds);
  for (int i = 0; i < 2; ++i) {
    const double exact = kH0 * (1.0 - std::exp(-c_of(p[i]) * ds));
    EXPECT_NEAR(nodes.state()[i], exact, 1e-6 * exact) << "node " << i;
    EXPECT_NEAR(nodes.counterface()[i], kQ * exact, 1e-6 * exact) << "node " << i;
  }
  const double global = 1e-5 * kH0 / (c_of(1e8) * kH0);   // finest cell over the law's fastest rate
  EXPECT_GT(ds / global, 1e5);
  EXPECT_LT(inc.substeps, 100);
}

// A slide of 2e6 e-foldings in one call: the node saturates at the depth where its rate vanishes (the law's last
// worn depth, h0, which it never reaches) in a bounded number of sub-steps; at the law's stiffness bound the slide
// was 1.3e8 sub-steps and threw "needs more than 1e8 sub-steps".
TEST(NodeStateLaw, AHugeSlideTowardsAVanishingRateEndsInFewSubSteps) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 1);
  const double ds = 1e3;
  ASSERT_GT(ds / nodes.substep_bound(), 1e8);
  const auto inc = nodes.advance({1e7}, ds);
  EXPECT_LT(inc.substeps, 100000);
  EXPECT_NEAR(nodes.state()[0], kH0, 1e-9 * kH0);
  EXPECT_LE(nodes.state()[0], kH0);
  EXPECT_NEAR(nodes.counterface()[0], kQ * kH0, 1e-9 * kH0);
}

// A node whose rate is zero (a law row without wear) stays put in one sub-step however far it slides.
TEST(NodeStateLaw, ANodeWithoutWearTakesOneSubStep) {
  NodeStateLaw nodes(make_law(false, true), OutOfRange::Error, 2);
  nodes.reset_state({3e-7, 0.0});
  const auto inc = nodes.advance({1e6, 1e7}, 1e3);
  EXPECT_EQ(nodes.state()[0], 3e-7);
  EXPECT_EQ(nodes.counterface()[0], 0.0);
  EXPECT_NEAR(nodes.state()[1], kH0, 1e-9 * kH0);
  EXPECT_LT(inc.substeps, 100000);
}

TEST(NodeStateLaw, PressureOutsideTheLawIsAnErrorNamingPAndTheRange) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 2);
  try {
    nodes.mu_effective({5e5, 1e7}, {1.0, 1.0});
    FAIL() << "no error";
  } catch (const std::out_of_range &e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("500000 Pa"), std::string::npos) << what;
    EXPECT_NE(what.find("[1e+06, 1e+08]"), std::string::npos) << what;
  }
  EXPECT_THROW(nodes.advance({1e7, 2e8}, 1e-4), std::out_of_range);
}

TEST(NodeStateLaw, ClampsAreCountedAndUseTheNearestGridPressure) {
  NodeStateLaw nodes(make_law(), OutOfRange::Clamp, 2);
  EXPECT_NEAR(nodes.mu_effective({5e5, 2e8}, {1.0, 0.0}), mu_exact(1e6, 0.0), 1e-12);
  EXPECT_EQ(nodes.use().below_pressure, 1);
  EXPECT_EQ(nodes.use().above_pressure, 1);
  EXPECT_EQ(nodes.use().lookups, 2);
  nodes.advance({5e5, 1e7}, 1e-4);
  EXPECT_GE(nodes.use().below_pressure, 5);  // every RK stage of node 0
  EXPECT_NEAR(nodes.state()[0], kH0 * (1.0 - std::exp(-c_of(1e6) * 1e-4)), 1e-6 * kH0);
  const std::string text = runin::continuum::describe(nodes.use(), nodes.law());
  EXPECT_NE(text.find("clamped below"), std::string::npos);
}

// Below the grid the Archard policy wears a node at its own pressure: rate (p / p_min) x the edge's rate, so
// h = h0 (1 - exp(-(p / p_min) c(p_min) s)); friction stays the edge's. The summary's WARNING names the policy.
TEST(NodeStateLaw, ArchardPolicyWearsBelowTheGridInProportionToPressure) {
  NodeStateLaw nodes(make_law(), OutOfRange::Archard, 2);
  EXPECT_NEAR(nodes.mu_effective({5e5, 1e7}, {1.0, 0.0}), mu_exact(1e6, 0.0), 1e-12);
  nodes.advance({2.5e5, 1e7}, 1e-4);
  EXPECT_NEAR(nodes.state()[0], kH0 * (1.0 - std::exp(-0.25 * c_of(1e6) * 1e-4)), 1e-6 * kH0);
  EXPECT_NEAR(nodes.counterface()[0], kQ * nodes.state()[0], 1e-6 * kQ * kH0);
  const std::string warning = runin::continuum::out_of_range_warning(nodes.use(), nodes.law(), nodes.policy());
  EXPECT_NE(warning.find("\"archard\""), std::string::npos) << warning;
  EXPECT_NE(warning.find("wear rates proportional to p"), std::string::npos) << warning;
  NodeStateLaw inside(make_law(), OutOfRange::Archard, 1);
  inside.mu_effective({1e7}, {1.0});
  EXPECT_TRUE(runin::continuum::out_of_range_warning(inside.use(), inside.law(), inside.policy()).empty());
  NodeStateLaw clamped(make_law(), OutOfRange::Clamp, 1);
  clamped.mu_effective({5e5}, {1.0});
  EXPECT_NE(runin::continuum::out_of_range_warning(clamped.use(), clamped.law(), clamped.policy())
                .find("breaks Archard's law"),
            std::string::npos);
}

TEST(NodeStateLaw, PeakMuAndStableContactStep) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 2);
  const std::vector<double> p = {1e7, 1e8}, area = {1.0, 1.0};
  const double expected = (mu_exact(1e7, 0.0) * 1e7 + mu_exact(1e8, 0.0) * 1e8) / 1.1e8;  // mu falls with h
  EXPECT_NEAR(nodes.peak_mu(p, area), expected, 1e-12);
  // w/p largest at node 0: c(1e7) h0 / 1e7
  const double factor = std::max(c_of(1e7) * kH0 / 1e7, c_of(1e8) * kH0 / 1e8);
  EXPECT_NEAR(nodes.stable_contact_step(p, 1e12, 0.5), 0.5 * 2.0 / (1e12 * factor), 1e-12);
}
