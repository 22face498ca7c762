// Friction sub-model 'junction' (Tabor 1959 junction growth, src/tribo/contact_model.h): one plastic junction
// of the elastic-plastic sphere, loaded normally and then sheared at constant normal load through
// ContactModel::evaluate (Mindlin spring, as in the hosts). Gross sliding against Tabor's closed form and against
// the growth criterion solved here by fixed-point iteration; the real area's growth against
// sqrt(F_n^2 + alpha F_t^2) / p_m; elastic contacts do not grow; the coefficient checks.
#include "tribo/contact_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace tribo = runin::tribo;
using tribo::SubModelKind;

namespace {

tribo::ContactModelChoice junction_choice(const char *normal = "elastic/plastic")
{
  tribo::ContactModelChoice c;
  c.index[static_cast<int>(SubModelKind::normal)] = tribo::find_sub_model(SubModelKind::normal, normal);
  c.index[static_cast<int>(SubModelKind::friction)] = tribo::find_sub_model(SubModelKind::friction, "junction");
  return c;
}

// AISI 1020 on a hard counter-body (the deck in.wall_brizmer's asperity), e = 1: no damping
tribo::ContactParameters steel(double f, double alpha)
{
  tribo::ContactParameters p;
  p.effective_modulus = 1.092e11;
  p.effective_shear_modulus = 4.3e10;
  p.restitution = 1.0;
  p.wear_coefficient = 0.0;
  p.hardness_i = 1.19e9;
  p.hardness_j = 6.0e9;
  p.yield_strength = 350e6;
  p.poisson_ratio = 0.29;
  p.interface_coefficient = f;
  p.junction_alpha = alpha;
  return p;
}

constexpr double kRadius = 2e-5;

struct Step {
  double normal_force, tangential_force, real_area;
  bool slipping;
};

// Pressed to `omega_over_c` critical interferences in 100 steps, then held there (constant normal load) and
// sheared at 10 mm/s with dt = 1 ns: one record per shear step; the first record is the unsheared contact.
std::vector<Step> press_then_shear(const tribo::ContactModel &model, double omega_over_c, int nshear)
{
  const tribo::ContactParameters p = steel(0.5, 12.0);
  const double omega_c =
      tribo::JacksonGreen(p.effective_modulus, kRadius, p.yield_strength, p.poisson_ratio).critical_interference();
  double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  tribo::ContactGeometry g;
  g.effective_radius = kRadius;
  g.effective_mass = 1e-9;
  g.normal[2] = 1.0;
  for (int k = 1; k <= 100; ++k) {
    g.overlap = omega_over_c * omega_c * k / 100.0;
    model.evaluate<1, 3, 0>(g, history, 1e-9, true);
  }
  std::vector<Step> out;
  for (int k = 0; k <= nshear; ++k) {
    g.tangential_velocity[0] = k == 0 ? 0.0 : 1e-2;
    const tribo::ContactResult r = model.evaluate<1, 3, 0>(g, history, 1e-9, true);
    out.push_back({r.normal_force, r.tangential.force_magnitude, r.normal.real_area, r.tangential.slipping});
  }
  return out;
}

// F_t at gross sliding from the growth criterion itself: A = sqrt(F_n^2 + alpha F_t^2) / p_m with
// p_m = F_n / A_0, sliding once F_t / A = tau_i = f k, k = p_m / sqrt(alpha) (p_m^2 = alpha k^2).
double criterion_sliding_force(double fn, double area0, double f, double alpha)
{
  const double p_m = fn / area0, tau_i = f * p_m / std::sqrt(alpha);
  double ft = tau_i * area0;
  for (int k = 0; k < 2000; ++k) ft = tau_i * std::sqrt(fn * fn + alpha * ft * ft) / p_m;
  return ft;
}

double tabor(double f, double alpha) { return f / std::sqrt(alpha * (1.0 - f * f)); }

std::string message_of(const tribo::ContactParameters &p, const char *normal = "elastic/plastic")
{
  try {
    const auto choice = junction_choice(normal);
    tribo::ContactModel(choice, tribo::contact_coefficients(choice, p), {});
  } catch (const tribo::InvalidCoefficient &e) {
    return e.what();
  }
  return "";
}

}    // namespace

static_assert(std::is_same_v<std::tuple_element_t<3, tribo::FrictionModels>, tribo::JunctionFrictionModel>,
              "the tests dispatch on the junction model's registry index");

// A plastic junction (30 omega_c) sheared at constant normal load: F_t / F_n at the first slipping step is
// Tabor's f / sqrt(alpha (1 - f^2)) (to 1 %, and to 1e-12: the model is exact) and the fixed point of the growth
// criterion; before it the contact sticks below that ratio. A law without growth (f / sqrt(alpha)) is 2 to 3 x off.
TEST(JunctionGrowth, GrossSlidingRatioIsTaborsClosedForm)
{
  for (double alpha : {12.0, 9.0})
    for (double f : {0.2, 0.5, 0.8, 0.95}) {
      const auto choice = junction_choice();
      const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, steel(f, alpha)), {});
      const std::vector<Step> steps = press_then_shear(model, 30.0, 3000);
      std::size_t first_slip = 0;
      while (first_slip < steps.size() && !steps[first_slip].slipping) ++first_slip;
      ASSERT_LT(first_slip, steps.size()) << "no gross sliding for f = " << f;
      ASSERT_GT(first_slip, 10u) << "the junction must stick first";
      const Step &s = steps[first_slip];
      const double ratio = s.tangential_force / s.normal_force;
      EXPECT_NEAR(ratio, tabor(f, alpha), 1e-2 * tabor(f, alpha)) << "f = " << f << ", alpha = " << alpha;
      EXPECT_NEAR(ratio, tabor(f, alpha), 1e-12 * tabor(f, alpha)) << "f = " << f << ", alpha = " << alpha;
      const double criterion = criterion_sliding_force(s.normal_force, steps[0].real_area, f, alpha);
      EXPECT_NEAR(s.tangential_force, criterion, 1e-9 * criterion) << "f = " << f;
      for (std::size_t k = 1; k < first_slip; ++k) EXPECT_LT(steps[k].tangential_force, s.tangential_force);
      // the whole sliding stretch stays at the limit
      EXPECT_NEAR(steps.back().tangential_force / steps.back().normal_force, tabor(f, alpha), 1e-12);
    }
}

// The junction's real area under the growing tangential force is sqrt(F_n^2 + alpha F_t^2) / p_m, p_m the mean
// pressure of the unsheared plastic contact (F_n / pi a^2 of Jackson-Green); at gross sliding A_0 / sqrt(1 - f^2).
TEST(JunctionGrowth, RealAreaGrowsAsTaborsCriterion)
{
  const double f = 0.8, alpha = 12.0;
  const auto choice = junction_choice();
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, steel(f, alpha)), {});
  const std::vector<Step> steps = press_then_shear(model, 30.0, 3000);
  const double fn = steps[0].normal_force, area0 = steps[0].real_area, p_m = fn / area0;
  EXPECT_GT(p_m, 2.0 * 350e6);    // a plastic junction: Jackson-Green's mean pressure is well above yield
  int grown = 0;
  for (const Step &s : steps) {
    EXPECT_EQ(s.normal_force, fn);    // constant normal load
    const double want = std::sqrt(s.normal_force * s.normal_force + alpha * s.tangential_force * s.tangential_force) / p_m;
    EXPECT_NEAR(s.real_area, want, 1e-12 * want);
    grown += s.real_area > 1.01 * area0;
  }
  EXPECT_GT(grown, 100);
  EXPECT_NEAR(steps.back().real_area, area0 / std::sqrt(1.0 - f * f), 1e-12 * area0);
}

// A contact below yield (0.5 omega_c, Hertz) is not a plastic junction: no growth, it shears at tau_i over its
// area, F_t / F_n = f / sqrt(alpha).
TEST(JunctionGrowth, ElasticContactDoesNotGrow)
{
  const double f = 0.8, alpha = 12.0;
  const auto choice = junction_choice();
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, steel(f, alpha)), {});
  const std::vector<Step> steps = press_then_shear(model, 0.5, 3000);
  EXPECT_TRUE(steps.back().slipping);
  EXPECT_NEAR(steps.back().tangential_force / steps.back().normal_force, f / std::sqrt(alpha), 1e-12);
  for (const Step &s : steps) EXPECT_EQ(s.real_area, steps[0].real_area);
}

// A worn flat (Archard: no plastic history) reloaded elastically carries its load on the plastic micro-contacts of
// the scar (real area F / 2.84 S_y below pi a^2, doc/elastic_plastic_contact.md section 6): a plastic junction.
// It slides at Tabor's ratio and its area grows by the criterion with p_m = F_n / A_r = 2.84 S_y.
TEST(JunctionGrowth, WornFlatsArePlasticJunctions)
{
  const double f = 0.9, alpha = 12.0, R = 2e-5, drop = 5e-8, pi = 3.14159265358979323846;
  const auto choice = junction_choice();
  const tribo::ContactParameters p = steel(f, alpha);
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, p), {});
  for (double overlap : {1e-11, 1e-10, 1e-9}) {
    double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
    tribo::ContactGeometry g;
    g.overlap = overlap;
    g.effective_radius = R;
    g.effective_mass = 1e-9;
    g.flat_radius = std::sqrt(2.0 * R * drop - drop * drop);
    g.summit_drop = drop;
    g.normal[2] = 1.0;
    const tribo::ContactResult unsheared = model.evaluate<1, 3, 0>(g, history, 1e-9, true);
    const double fn = unsheared.normal_force, area0 = unsheared.normal.real_area;
    const tribo::FlatHertzContact sneddon = tribo::flat_hertz_contact(p.effective_modulus, R, g.flat_radius, overlap);
    ASSERT_NEAR(fn, sneddon.force, 1e-12 * fn) << overlap;    // Sneddon's elastic reload, no groove
    ASSERT_EQ(unsheared.normal.groove_ploughing, 0.0);
    ASSERT_LT(area0, pi * sneddon.contact_radius * sneddon.contact_radius) << overlap;
    EXPECT_NEAR(fn / area0, 2.84 * p.yield_strength, 1e-12 * fn / area0) << overlap;
    g.tangential_velocity[0] = 1e5 * overlap;    // thousands of steps of stick at every overlap
    tribo::ContactResult r;
    int steps = 0;
    do {
      r = model.evaluate<1, 3, 0>(g, history, 1e-9, true);
      const double ft = r.tangential.force_magnitude;
      const double want = area0 * std::sqrt(1.0 + alpha * (ft / fn) * (ft / fn));
      EXPECT_NEAR(r.normal.real_area, want, 1e-12 * want) << overlap;
    } while (!r.tangential.slipping && ++steps < 100000);
    ASSERT_GT(steps, 10) << overlap;
    EXPECT_NEAR(r.tangential.force_magnitude / r.normal_force, tabor(f, alpha), 1e-12) << overlap;
  }
}

// f outside [0, 1), alpha <= 0, no S_y (Tabor's H / 2.8 guess), no f, and Hertz instead of elastic/plastic:
// each refused naming the coefficient.
TEST(JunctionGrowth, BadCoefficientsNameTheCoefficient)
{
  auto starts = [](const std::string &message, const std::string &prefix) {
    return message.rfind(prefix, 0) == 0;
  };
  EXPECT_TRUE(starts(message_of(steel(1.0, 12.0)), "f: interface coefficient must be in [0, 1)")) << message_of(steel(1.0, 12.0));
  EXPECT_TRUE(starts(message_of(steel(-0.1, 12.0)), "f: interface coefficient must be in [0, 1)"));
  EXPECT_TRUE(starts(message_of(steel(0.5, 0.0)), "alpha: junction growth constant must be > 0"));
  EXPECT_TRUE(starts(message_of(steel(0.5, -9.0)), "alpha: junction growth constant must be > 0"));
  tribo::ContactParameters p = steel(0.5, 12.0);
  p.yield_from_hardness = true;
  EXPECT_TRUE(starts(message_of(p), "S_y: friction model 'junction' needs the yield strength")) << message_of(p);
  p = steel(0.5, 12.0);
  p.interface_coefficient = std::nan("");
  EXPECT_TRUE(starts(message_of(p), "f: friction model 'junction' needs the interface coefficient f")) << message_of(p);
  EXPECT_EQ(message_of(steel(0.5, 12.0), "hertz"), "friction model 'junction' needs the normal model 'elastic/plastic'");
  EXPECT_EQ(message_of(steel(0.0, 12.0)), "");    // f = 0: frictionless interface, allowed
}

// Mixing (geometric mean) and the restart record know the model.
TEST(JunctionGrowth, MixingAndRestartRecord)
{
  const auto choice = junction_choice();
  const auto ii = tribo::contact_coefficients(choice, steel(0.25, 9.0));
  const auto jj = tribo::contact_coefficients(choice, steel(0.64, 16.0));
  const auto ij = tribo::mix_coefficients(choice, ii, jj);
  EXPECT_NEAR(ij.of(SubModelKind::friction)[0], 0.4, 1e-15);
  EXPECT_NEAR(ij.of(SubModelKind::friction)[1], 12.0, 1e-14);
  const std::vector<double> record = tribo::serialize(choice, ij);
  const auto back = tribo::deserialize(record.data(), static_cast<int>(record.size()));
  EXPECT_TRUE(back.first == choice);
  EXPECT_EQ(back.second.of(SubModelKind::friction), ij.of(SubModelKind::friction));
}
