// Contact kernels against closed forms (Johnson, Contact Mechanics, 1985).
#include "tribo/contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

using namespace runin::tribo;

namespace {
constexpr double kRoundOff = 1e-13;    // tier 1: identities
const Material kCopper{110e9, 0.37, 0.87e9};
const Material kAluminium{69e9, 0.33, 0.245e9};
}    // namespace

TEST(Hertz, ForceMatchesJohnsonInversion)
{
  // Johnson eq. 4.22-4.23: a^3 = 3 F R* / (4 E*), delta = a^2 / R*. Independent route to F(delta).
  const double e_eff = effective_modulus(kCopper, kAluminium);
  const double r_eff = effective_radius(2e-6, 5e-6);
  const HertzNormal hertz(e_eff, r_eff);
  for (double delta : {1e-12, 3e-10, 1e-9, 2.5e-8}) {
    const double force = hertz.force(delta);
    const double a = std::cbrt(3.0 * force * r_eff / (4.0 * e_eff));
    EXPECT_NEAR(a * a / r_eff, delta, 1e-10 * delta);
    EXPECT_NEAR(hertz.contact_radius(delta), a, 1e-10 * a);
  }
}

TEST(Hertz, EffectiveModulusClosedForm)
{
  const double expected = 1.0 / ((1 - 0.37 * 0.37) / 110e9 + (1 - 0.33 * 0.33) / 69e9);
  EXPECT_NEAR(effective_modulus(kCopper, kAluminium), expected, kRoundOff * expected);
  EXPECT_NEAR(effective_radius(1.0, 1.0), 0.5, kRoundOff);
}

TEST(Hertz, StiffnessAndEnergyAreConsistentDerivatives)
{
  const HertzNormal hertz(5e10, 1e-6);
  const double delta = 1e-8, h = 1e-13;
  const double dforce = (hertz.force(delta + h) - hertz.force(delta - h)) / (2 * h);
  EXPECT_NEAR(hertz.stiffness(delta), dforce, 1e-7 * dforce);
  const double denergy = (hertz.elastic_energy(delta + h) - hertz.elastic_energy(delta - h)) / (2 * h);
  EXPECT_NEAR(hertz.force(delta), denergy, 1e-7 * denergy);
  EXPECT_EQ(hertz.force(-1e-9), 0.0);
}

TEST(Hertz, RejectsNonPositiveModulus)
{
  EXPECT_THROW(HertzNormal(-1.0, 1e-6), InvalidCoefficient);
  EXPECT_THROW(HertzNormal(1e9, 0.0), InvalidCoefficient);
  Material bad = kCopper;
  bad.hardness = -1.0;
  EXPECT_THROW(bad.validate("Cu"), InvalidCoefficient);
}

TEST(Damping, OffAtUnitRestitutionAndOpposesApproach)
{
  EXPECT_EQ(RestitutionDamping(1.0).force(1e6, 1e-9, -1.0), 0.0);
  const RestitutionDamping damping(0.5);
  EXPECT_GT(damping.force(1e6, 1e-9, -1.0), 0.0);    // approaching: repulsive
  EXPECT_LT(damping.force(1e6, 1e-9, +1.0), 0.0);
  // Tsuji form: proportional to sqrt(k_n m*) v_n (the factor itself is checked by the impact test below)
  EXPECT_NEAR(damping.force(4.0, 1.0, -1.0), 2.0 * damping.force(1.0, 1.0, -1.0), kRoundOff);
  EXPECT_NEAR(damping.force(1.0, 9.0, -2.0), 6.0 * damping.force(1.0, 1.0, -1.0), kRoundOff);
  EXPECT_THROW(RestitutionDamping(0.0), InvalidCoefficient);
  EXPECT_THROW(RestitutionDamping(1.2), InvalidCoefficient);
}

TEST(Mindlin, StickIsLinearSpringThenSlipsAtStaticThenKineticLimit)
{
  const StaticKineticFriction friction(0.6, 0.4, 0.0);
  const double n[3] = {0, 0, 1}, vt[3] = {1e-3, 0, 0};
  const double kt = 2e5, fn = 1e-3, dt = 1e-9;
  double spring[3] = {0, 0, 0}, slip = 0.0;

  // Stick: F_t = -k_t * u, with u the accumulated tangential displacement.
  auto step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
  EXPECT_FALSE(step.slipping);
  EXPECT_NEAR(step.force[0], -kt * 1e-12, kRoundOff * kt * 1e-12);

  // Load until the first slip: the force at slip is exactly mu_s F_n.
  int steps = 1;
  while (!(step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true)).slipping) ++steps;
  EXPECT_NEAR(std::fabs(step.force[0]), 0.6 * fn, kRoundOff);
  EXPECT_NEAR(steps * vt[0] * dt, 0.6 * fn / kt, vt[0] * dt);    // stick distance = mu_s F_n / k_t

  // First kinetic step: the spring relaxes from mu_s F_n / k_t to mu_k F_n / k_t.
  double slip_before = slip;
  step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
  EXPECT_TRUE(step.slipping);
  EXPECT_NEAR(std::fabs(step.force[0]), 0.4 * fn, kRoundOff);
  EXPECT_NEAR(slip - slip_before, (0.6 - 0.4) * fn / kt + vt[0] * dt, 1e-12 * fn / kt);

  // Steady sliding: slip accumulates at exactly the imposed rate.
  slip_before = slip;
  step = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
  EXPECT_NEAR(std::fabs(step.force[0]), 0.4 * fn, kRoundOff);
  EXPECT_NEAR(slip - slip_before, vt[0] * dt, 1e-9 * vt[0] * dt);
}

TEST(Mindlin, SetupCallLeavesHistoryUntouched)
{
  const StaticKineticFriction friction(0.5, 0.5, 0.0);
  const double n[3] = {0, 0, 1}, vt[3] = {1.0, 0, 0};
  double spring[3] = {1e-9, 0, 0}, slip = 0.25;
  auto out = mindlin_coulomb(1e5, 1.0, friction, n, vt, 1e-6, spring, slip, false);
  EXPECT_EQ(spring[0], 1e-9);
  EXPECT_EQ(slip, 0.25);
  EXPECT_NEAR(out.force[0], -1e-4, kRoundOff);
}

TEST(StaticKinetic, SlipWeakeningIsLinearOverDc)
{
  const StaticKineticFriction friction(0.8, 0.2, 1e-6);
  EXPECT_DOUBLE_EQ(friction.coefficient(0.0), 0.8);
  EXPECT_NEAR(friction.coefficient(0.5e-6), 0.5, kRoundOff);
  EXPECT_DOUBLE_EQ(friction.coefficient(2e-6), 0.2);
  EXPECT_THROW(StaticKineticFriction(0.2, 0.3, 0.0), InvalidCoefficient);
}

// Slide past d_c (limit mu_k F_n), stop, then push again: with re-stick the contact breaks away at
// mu_s F_n a second time; without it the second peak stays at mu_k F_n.
TEST(Mindlin, RestickHealsToStaticLimitAfterAStop)
{
  const double kt = 7.6e3, fn = 1.6e-5, dt = 1e-10, speed = 1.0;
  const StaticKineticFriction friction(0.6, 0.4, 5e-9);
  const double n[3] = {0.0, 0.0, 1.0};
  for (double restick_speed : {0.0, 0.1}) {
    double spring[3] = {0.0, 0.0, 0.0}, slip = 0.0, second_peak = 0.0;
    auto push = [&](double v, int steps, double *peak) {
      const double vt[3] = {v, 0.0, 0.0};
      for (int k = 0; k < steps; ++k) {
        const TangentialUpdate update = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring, slip, true);
        if (resticks(update, std::fabs(v), restick_speed)) slip = 0.0;
        if (peak) *peak = std::max(*peak, std::fabs(update.force[0]));
      }
    };
    push(speed, 200, nullptr);
    EXPECT_NEAR(kt * std::fabs(spring[0]), 0.4 * fn, 1e-12 * fn);    // sliding at mu_k
    push(0.0, 3, nullptr);
    push(speed, 200, &second_peak);
    const double expected = restick_speed > 0.0 ? 0.6 * fn : 0.4 * fn;
    EXPECT_NEAR(second_peak, expected, 1e-12 * fn) << "restick speed " << restick_speed;
  }
  TangentialUpdate slipping;
  slipping.slipping = true;
  EXPECT_FALSE(resticks(slipping, 0.0, 0.1));    // a slipping contact never re-sticks
  EXPECT_FALSE(resticks(TangentialUpdate(), 0.2, 0.1));
  EXPECT_TRUE(resticks(TangentialUpdate(), 0.05, 0.1));
}

// --- Restitution calibration: an independent head-on Hertz impact in SI units ---
namespace {
// Fixed-step RK4 of the relative normal motion m* d(v_n)/dt = F_n, d(delta)/dt = -v_n, with the force
// exactly as pair runin/asperity evaluates it (Hertz + damping, clamped at 0). Returns v_out / v_in.
double measured_restitution(const RestitutionDamping &damping, double e_star, double r_star, double mass,
                            double impact_speed)
{
  const HertzNormal hertz(e_star, r_star);
  const auto acceleration = [&](double overlap, double vn) {
    const double fn = hertz.force(overlap) + damping.force(hertz.stiffness(overlap), mass, vn);
    return std::max(fn, 0.0) / mass;
  };
  // Hertz contact time 2.94 delta_max / v0 (undamped; damping shortens it): 2e4 steps per contact
  const double overlap_max = std::pow(15.0 * mass * impact_speed * impact_speed / (16.0 * e_star * std::sqrt(r_star)), 0.4);
  const double h = 2.94 * overlap_max / impact_speed / 2.0e4;
  double overlap = 0.0, vn = -impact_speed;
  for (int step = 0; step < 1000000; ++step) {
    const double k1x = -vn, k1v = acceleration(overlap, vn);
    const double k2x = -(vn + 0.5 * h * k1v), k2v = acceleration(overlap + 0.5 * h * k1x, vn + 0.5 * h * k1v);
    const double k3x = -(vn + 0.5 * h * k2v), k3v = acceleration(overlap + 0.5 * h * k2x, vn + 0.5 * h * k2v);
    const double k4x = -(vn + h * k3v), k4v = acceleration(overlap + h * k3x, vn + h * k3v);
    overlap += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    vn += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
    if (overlap <= 0.0) return vn / impact_speed;    // free flight once the clamped force is zero
  }
  return -1.0;
}
}    // namespace

TEST(RestitutionCalibration, HertzImpactReboundsWithTheInputRestitution)
{
  // Cu/Al asperities of 1 and 0.8 um; the calibration is speed independent (self-similar impact)
  const double e_eff = effective_modulus(kCopper, kAluminium);
  const double r_eff = effective_radius(1e-6, 0.8e-6);
  const double m1 = 8960.0 * 4.0 / 3.0 * M_PI * 1e-18, m2 = 2700.0 * 4.0 / 3.0 * M_PI * 0.512e-18;
  const double mass = m1 * m2 / (m1 + m2);
  for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const RestitutionDamping damping(e);
    for (double impact_speed : {0.05, 2.0}) {
      const double measured = measured_restitution(damping, e_eff, r_eff, mass, impact_speed);
      EXPECT_NEAR(measured, e, 1e-3 * e) << "e = " << e << ", v0 = " << impact_speed << " m/s";
    }
  }
  EXPECT_EQ(RestitutionDamping::hertz_restitution(0.0), 1.0);
  const double elastic = measured_restitution(RestitutionDamping(1.0), e_eff, r_eff, mass, 1.0);
  EXPECT_NEAR(elastic, 1.0, 1e-6);
}

// The style pages quote the calibrated damping factors, what Tsuji's linear-spring mapping would give instead,
// and the range of e: they must stay what the code does (the wall page once gave Tsuji's form).
TEST(RestitutionCalibration, DocPagesQuoteTheCodesFactorsAndRange)
{
  const auto page = [](const char *name) {
    std::ifstream in(std::string(RUNIN_SOURCE_DIR) + "/doc/" + name);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  // |quoted - value| within half a unit of the quoted number's last digit
  const auto agrees = [](const std::string &quoted, double value) {
    const auto dot = quoted.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(quoted.size() - dot - 1);
    return std::fabs(std::stod(quoted) - value) <= 0.5 * std::pow(10.0, -decimals);
  };
  const std::regex zeta(R"(zeta` = ([0-9.]+), ([0-9.]+), ([0-9.]+) for\s+\*e\* = ([0-9.]+), ([0-9.]+), ([0-9.]+))");
  for (const char *name : {"pair_runin_asperity.rst", "fix_runin_wall.rst"}) {
    const std::string text = page(name);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, zeta)) << name << ": no calibrated factors quoted";
    for (int k = 1; k <= 3; ++k) {
      const double e = std::stod(m[k + 3]);
      const double factor = RestitutionDamping(e).force(1.0, 1.0, -1.0);    // F = -factor sqrt(k m) v_n
      EXPECT_TRUE(agrees(m[k], factor)) << name << ": e = " << e << " quoted " << m[k] << ", code " << factor;
    }
    EXPECT_NE(text.find("1e-6 <= e <= 1"), std::string::npos) << name << ": range of e";
    EXPECT_EQ(kMinimumRestitution, 1e-6);
  }
  const std::string pair = page("pair_runin_asperity.rst");
  std::smatch m;
  const std::regex tsuji(R"(Tsuji et al. \(1992\),[\s\S]*?gives \*e\* = ([0-9.]+), ([0-9.]+), ([0-9.]+) instead)");
  ASSERT_TRUE(std::regex_search(pair, m, tsuji)) << "pair page: Tsuji's rebounds not quoted";
  int k = 1;
  for (double e : {0.1, 0.5, 0.9}) {
    const double log_e = std::log(e);
    const double factor = -2.0 * std::sqrt(5.0 / 6.0) * log_e / std::sqrt(log_e * log_e + M_PI * M_PI);
    EXPECT_TRUE(agrees(m[k], RestitutionDamping::hertz_restitution(factor))) << "Tsuji e = " << e;
    ++k;
  }
}

// --- Fast paths of the force loops: they must agree with the validated kernels ---

// limit_force with the kinetic level mu_k F_n is coefficient(slip) F_n; static_excess is the part above mu_k.
TEST(StaticKinetic, LimitForceAndStaticExcessMatchCoefficient)
{
  const double fn = 3.7e-5;
  for (double d_c : {0.0, 2e-8}) {
    const StaticKineticFriction friction(0.95, 0.55, d_c);
    for (double slip : {0.0, 1e-12, 5e-9, 1.999e-8, 2e-8, 1e-6}) {
      const double expected = friction.coefficient(slip) * fn;
      EXPECT_NEAR(friction.limit_force(slip, fn, 0.55 * fn), expected, 4e-16 * expected) << slip << " " << d_c;
      EXPECT_NEAR(friction.static_excess(slip), friction.coefficient(slip) - 0.55, 4e-16) << slip << " " << d_c;
    }
  }
  EXPECT_EQ(StaticKineticFriction(0.95, 0.55, 2e-8).static_excess(0.0), 0.95 - 0.55);
  EXPECT_EQ(StaticKineticFriction(0.95, 0.55, 0.0).static_excess(1e-15), 0.0);
}

// mindlin_spring given the limit force coefficient(slip) F_n is mindlin_coulomb, bit for bit, over a
// stick - slip - stop - reverse history; force_magnitude is |F_t|.
TEST(Mindlin, SpringWithLimitForceIsMindlinCoulomb)
{
  const StaticKineticFriction friction(0.6, 0.4, 3e-9);
  const double n[3] = {0.0, 0.6, 0.8}, kt = 7.6e3, fn = 1.6e-5, dt = 1e-10;
  double spring_a[3] = {0, 0, 0}, spring_b[3] = {0, 0, 0}, slip_a = 0.0, slip_b = 0.0;
  int slipping_steps = 0;
  for (int step = 0; step < 600; ++step) {
    const double speed = step < 250 ? 1.0 : step < 300 ? 0.0 : -1.0;
    const double vt[3] = {speed, 0.3 * speed, -0.225 * speed};
    const bool advance = step % 7 != 3;    // also calls that only read the history (LAMMPS setup)
    const TangentialUpdate a = mindlin_coulomb(kt, fn, friction, n, vt, dt, spring_a, slip_a, advance);
    const TangentialUpdate b =
        mindlin_spring(kt, friction.coefficient(slip_b) * fn, n, vt, dt, spring_b, slip_b, advance);
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(a.force[k], b.force[k]) << step;
      ASSERT_EQ(spring_a[k], spring_b[k]) << step;
    }
    ASSERT_EQ(slip_a, slip_b) << step;
    ASSERT_EQ(a.slipping, b.slipping) << step;
    ASSERT_EQ(a.slip_increment, b.slip_increment) << step;
    const double magnitude = std::sqrt(a.force[0] * a.force[0] + a.force[1] * a.force[1] + a.force[2] * a.force[2]);
    EXPECT_NEAR(a.force_magnitude, magnitude, 1e-15 * fn) << step;
    slipping_steps += a.slipping ? 1 : 0;
  }
  EXPECT_GT(slipping_steps, 100);    // the history did exercise the slip branch
  EXPECT_LT(slipping_steps, 550);    // and the stick branch
}

TEST(Mindlin, ResticksSquaredAgreesWithResticks)
{
  TangentialUpdate stuck, slipping;
  slipping.slipping = true;
  for (double restick_speed : {0.0, 0.01, 0.1})
    for (double speed : {0.0, 0.005, 0.0099, 0.0101, 0.05, 0.2, 3.0})
      for (const TangentialUpdate *update : {&stuck, &slipping})
        EXPECT_EQ(resticks_squared(*update, speed * speed, restick_speed), resticks(*update, speed, restick_speed))
            << speed << " " << restick_speed;
}
