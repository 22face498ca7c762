// Surface film on the contact nodes of an element (continuum/node_film.h): the cell's film kinetics per node, exact
// against their closed forms, the film limits of the friction scaling, and the node state law carrying it.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <tuple>

#include "continuum/node_film.h"
#include "continuum/node_state_law.h"

using namespace runin::coupling;
using runin::continuum::FilmSettings;
using runin::continuum::NodeFilm;
using runin::continuum::NodeStateLaw;

namespace {

double tabor(double f, double alpha) { return f / std::sqrt(alpha * (1.0 - f * f)); }

FilmSettings film(double coverage, double s_r, double k_g) {
  FilmSettings s;
  s.coverage = coverage;
  s.f_film = 0.1;
  s.f_base = 0.8921;
  s.alpha = 12.0;
  s.removal_distance = s_r;
  s.growth_rate = k_g;
  return s;
}

// mu_body 0.57 everywhere; contact fraction phi = 0.05 (p / 1e7) (proportional to the load, constant in h).
std::shared_ptr<const StateLaw> make_law(bool with_contact_fraction = true) {
  const std::vector<double> p = {1e6, 1e7}, h = {0.0, 1e-9};
  std::array<StateFieldTable, state_field_count> fields;
  for (std::size_t f = 0; f < state_field_count; ++f) {
    const auto field = static_cast<StateField>(f);
    if (field == StateField::ContactFraction && !with_contact_fraction) continue;
    auto &t = fields[f].mean;
    t.assign(p.size(), std::vector<double>(h.size(), 0.0));
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < h.size(); ++j) {
        double v = 0.0;
        if (field == StateField::MuBody) v = 0.57;
        if (field == StateField::Rq) v = 2e-7;
        if (field == StateField::WearRate || field == StateField::CounterfaceWearRate) v = 1e-14 * p[i];
        if (field == StateField::ContactFraction) v = 0.05 * p[i] / 1e7;
        t[i][j] = v;
      }
  }
  return std::make_shared<const StateLaw>(p, h, fields);
}

}  // namespace

TEST(NodeFilm, FilmLimitsScaleTheBareLawByTaborsClosedForm) {
  NodeFilm covered(film(1.0, 0.0, 0.0), 1), bare(film(0.0, 0.0, 0.0), 1);
  EXPECT_NEAR(covered.friction_factor(0), tabor(0.1, 12.0) / tabor(0.8921, 12.0), 1e-15);
  EXPECT_EQ(bare.friction_factor(0), 1.0);
  NodeFilm half(film(0.5, 0.0, 0.0), 1);  // f is linear in theta, mu is Tabor's of that f
  EXPECT_NEAR(half.friction_factor(0), tabor(0.49605, 12.0) / tabor(0.8921, 12.0), 1e-14);
}

TEST(NodeFilm, RemovalAloneDecaysAsExpOfTheSummitSlip) {
  NodeFilm f(film(1.0, 0.02, 0.0), 2);
  const std::vector<double> phi = {0.05, 0.0};  // node 2 carries no load: its film stays
  double s = 0.0;
  for (double ds : {1e-3, 0.05, 0.3, 1.7}) {  // uneven steps: the update is exact whatever the step
    f.advance(phi, ds, 0.0);
    s += ds;
    EXPECT_NEAR(f.coverage()[0], std::exp(-0.05 * s / 0.02), 1e-14);
    EXPECT_EQ(f.coverage()[1], 1.0);
  }
}

TEST(NodeFilm, GrowthAloneRecoversAsLangmuirAndTheSteadyStateBalancesBoth) {
  NodeFilm g(film(0.2, 0.0, 3.0), 1);
  g.advance({0.05}, 0.0, 0.4);
  EXPECT_NEAR(g.coverage()[0], 1.0 - 0.8 * std::exp(-3.0 * 0.4), 1e-14);
  // removal and growth at a steady sliding speed v: theta* = k_g / (k_g + phi v / s_r)
  NodeFilm both(film(1.0, 0.02, 0.5), 1);
  const double v = 0.5, phi = 0.05;
  for (int k = 0; k < 400; ++k) both.advance({phi}, v * 0.1, 0.1);
  EXPECT_NEAR(both.coverage()[0], 0.5 / (0.5 + phi * v / 0.02), 1e-12);
}

TEST(NodeFilm, BadSettingsNameTheirKey) {
  const auto message = [](FilmSettings s) {
    try {
      s.validate();
    } catch (const std::invalid_argument &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  FilmSettings s = film(1.5, 0.0, 0.0);
  EXPECT_EQ(message(s).rfind("film.coverage:", 0), 0u) << message(s);
  s = film(1.0, 0.0, -1.0);
  EXPECT_EQ(message(s).rfind("film.growth_rate:", 0), 0u) << message(s);
  s = film(1.0, -1e-3, 0.0);
  EXPECT_EQ(message(s).rfind("film.removal_distance:", 0), 0u) << message(s);
  s = film(1.0, 0.0, 0.0), s.f_film = 1.0;
  EXPECT_EQ(message(s).rfind("film.f_film:", 0), 0u) << message(s);
  s = film(1.0, 0.0, 0.0), s.alpha = 0.0;
  EXPECT_EQ(message(s).rfind("film.alpha:", 0), 0u) << message(s);
  s = film(1.0, 0.0, std::nan(""));
  EXPECT_EQ(message(s).rfind("film.growth_rate:", 0), 0u) << message(s);
}

TEST(NodeFilm, NodeStateLawScalesFrictionAndMovesTheFilmAtTheLawsContactFraction) {
  NodeStateLaw nodes(make_law(), OutOfRange::Error, 2);
  const std::vector<double> p = {2e6, 8e6}, area = {1.0, 1.0};
  nodes.set_film(film(1.0, 0.02, 0.0));
  const double covered = tabor(0.1, 12.0) / tabor(0.8921, 12.0);
  EXPECT_NEAR(nodes.mu_effective(p, area), 0.57 * covered, 1e-12);
  EXPECT_NEAR(nodes.peak_mu(p, area), 0.57 * covered, 1e-12);
  nodes.advance(p, 0.3, 0.6);
  // phi of each node from the law at its pressure (proportional to p): 0.01 and 0.04
  EXPECT_NEAR(nodes.film()->coverage()[0], std::exp(-0.01 * 0.3 / 0.02), 1e-12);
  EXPECT_NEAR(nodes.film()->coverage()[1], std::exp(-0.04 * 0.3 / 0.02), 1e-12);
  const auto mu = nodes.node_mu(p);
  EXPECT_NEAR(mu[1], 0.57 * nodes.film()->friction_factor(1), 1e-12);
  // the wear does not see the film: dh = k p ds / H as without it
  EXPECT_NEAR(nodes.state()[1], 1e-14 * 8e6 * 0.3, 1e-22);
}

TEST(NodeFilm, ALawWithoutContactFractionIsRefused) {
  NodeStateLaw nodes(make_law(false), OutOfRange::Error, 1);
  EXPECT_FALSE(nodes.law().has(StateField::ContactFraction));
  try {
    nodes.set_film(film(1.0, 0.02, 0.0));
    FAIL() << "no error";
  } catch (const std::invalid_argument &e) {
    EXPECT_NE(std::string(e.what()).find("contact_fraction"), std::string::npos) << e.what();
  }
}

TEST(NodeFilm, ACounterfaceFilmHasItsOwnKineticsAndContactsShearAtTheMeanCoverage) {
  FilmSettings s = film(1.0, 0.02, 0.0);
  s.counterface = runin::continuum::CounterfaceFilm{0.0, 0.5, 2.0};
  NodeFilm f(s, 1);
  EXPECT_EQ(f.contact_coverage(0), 0.5);
  EXPECT_NEAR(f.friction_factor(0), tabor(0.5 * 0.1 + 0.5 * 0.8921, 12.0) / tabor(0.8921, 12.0), 1e-14);
  const double phi = 0.05, duty = 0.02, ds = 0.3, dt = 0.6;
  f.advance({phi}, ds, dt, duty);
  EXPECT_NEAR(f.coverage()[0], std::exp(-phi * ds / 0.02), 1e-14);
  // the counter body's summits slip phi duty ds and regrow over dt: the exact solution from 0
  const double r = phi * duty * ds / 0.5, g = 2.0 * dt, steady = g / (r + g);
  EXPECT_NEAR(f.counterface_coverage()[0], steady * -std::expm1(-(r + g)), 1e-14);
  EXPECT_NEAR(f.contact_coverage(0), 0.5 * (f.coverage()[0] + f.counterface_coverage()[0]), 1e-15);
  s.counterface->growth_rate = -1.0;
  EXPECT_THROW(s.validate(), std::invalid_argument);
}

// The bound an adaptive run uses to blame the film (film_step_bound) holds against the film itself: over steps of
// every size, on removal, growth and both, the node's |d ln mu| at full contact (phi = 1) never exceeds it; it names
// the fastest kinetic input once the coverage's exposure passes the tolerance, f_film when only T(f)'s steepness does.
TEST(NodeFilm, StepBoundHoldsAgainstTheFilmAndNamesItsInput) {
  using runin::continuum::FilmInput;
  using runin::continuum::film_step_bound;
  const double tolerance = 0.01;
  for (const auto &[s_r, k_g, theta0] : {std::tuple{1e-3, 0.0, 1.0}, std::tuple{0.0, 50.0, 0.0},
                                         std::tuple{2e-3, 30.0, 0.5}}) {
    for (double ds : {1e-9, 1e-7, 1e-5, 1e-3, 1e-1}) {
      const double dt = ds / 0.5;  // 0.5 m/s
      FilmSettings s = film(theta0, s_r, k_g);
      NodeFilm node(s, 1);
      const double before = std::log(node.friction_factor(0));
      node.advance({1.0}, ds, dt);
      const double moved = std::fabs(std::log(node.friction_factor(0)) - before);
      const auto bound = film_step_bound(s, ds, dt, tolerance);
      EXPECT_LE(moved, bound.change * (1.0 + 1e-12)) << "s_r " << s_r << " k_g " << k_g << " ds " << ds;
      const double exposure = (s_r > 0.0 ? ds / s_r : 0.0) + k_g * dt;
      if (exposure > tolerance)
        EXPECT_EQ(bound.input, ds / (s_r > 0.0 ? s_r : 1e300) >= k_g * dt ? FilmInput::RemovalDistance
                                                                           : FilmInput::GrowthRate);
      if (bound.change <= tolerance) EXPECT_EQ(bound.input, FilmInput::None);
    }
  }
  // f_film a hair below 1: T(f) so steep that a coverage change of 1e-6 moves mu by far more than the tolerance
  FilmSettings steep = film(1.0, 1.0, 0.0);
  steep.f_film = 0.9999999999999999;
  const auto b = film_step_bound(steep, 1e-6, 2e-6, tolerance);
  EXPECT_EQ(b.input, FilmInput::FFilm);
  EXPECT_GT(b.change, 1e3);
  // the counterface's own kinetics count
  FilmSettings both = film(1.0, 1.0, 0.0);
  both.counterface = runin::continuum::CounterfaceFilm{1.0, 1e-9, 0.0};
  EXPECT_EQ(film_step_bound(both, 1e-6, 2e-6, tolerance).input, FilmInput::CounterfaceRemovalDistance);
}
