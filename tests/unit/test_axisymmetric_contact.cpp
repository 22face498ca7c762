// Axisymmetric ring-influence contact solver and pin wear against closed forms: Hertz (pressure,
// contact radius, approach, with observed convergence orders), Archard volume, the uniform
// pressure of the steady-wear limit, and the ArchardWear::stable_slip_step bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "continuum/axisymmetric_contact.h"
#include "tribo/contact.h"

using namespace runin::continuum;

namespace {
// Cu pin (E = 110 GPa, nu = 0.37) on Al disk (E = 69 GPa, nu = 0.33), thesis ch. 4.
double cu_al_modulus() {
  runin::tribo::Material cu{110e9, 0.37, 1e9}, al{69e9, 0.33, 0.5e9};
  return runin::tribo::effective_modulus(cu, al);
}
constexpr double kTip = 5e-3, kLoad = 0.981;

std::vector<double> sphere_gap(const AxisymmetricContact &c, double radius) {
  std::vector<double> g(c.rings());
  for (int i = 0; i < c.rings(); ++i) g[i] = c.ring_radius(i) * c.ring_radius(i) / (2.0 * radius);
  return g;
}

// Largest second difference of the pressure inside the contact, relative to the mean pressure:
// O(h^2) for a smooth profile, O(1) for a ring-to-ring sawtooth.
double sawtooth(const ContactSolution &s) {
  double worst = 0.0;
  for (std::size_t i = 2; i < s.pressure.size(); ++i)
    if (s.pressure[i] > 0.0 && s.pressure[i - 1] > 0.0 && s.pressure[i - 2] > 0.0)
      worst = std::max(worst, std::abs(s.pressure[i] - 2.0 * s.pressure[i - 1] + s.pressure[i - 2]));
  return worst / s.mean_pressure;
}
}  // namespace

TEST(AxisymmetricContact, UniformDiskDisplacementAtCentreIsClosedForm) {
  // u(0) = 2 p a / E* for uniform p on a disk of radius a: the sum of all ring columns at r -> 0.
  const double e_star = cu_al_modulus();
  const AxisymmetricContact c(1e-4, 400, e_star);
  double u0 = 0.0;
  for (int j = 0; j < c.rings(); ++j) u0 += c.influence()(0, j);
  // The first collocation point sits at h/2, where u = 4 a E(h/2a) / (pi E*).
  const double exact = 4.0 * 1e-4 * std::comp_ellint_2(0.5 / 400) / (M_PI * e_star);
  EXPECT_NEAR(u0 / exact, 1.0, 1e-12);
}

TEST(AxisymmetricContact, HertzConvergesWithObservedOrders) {
  const double e_star = cu_al_modulus();
  const auto hertz = hertz_sphere_on_flat(kTip, e_star, kLoad);
  // Cross-check the reference against the shared Hertz kernel: F(delta) = W, a = sqrt(R delta).
  const runin::tribo::HertzNormal kernel(e_star, kTip);
  EXPECT_NEAR(kernel.force(hertz.approach) / kLoad, 1.0, 1e-12);
  EXPECT_NEAR(kernel.contact_radius(hertz.approach) / hertz.contact_radius, 1.0, 1e-12);

  // Grid radius 2.3 a, so the contact edge does not fall on a ring boundary.
  std::vector<double> approach_error, peak_error, rms_error, radius_error, widths;
  for (const int rings : {32, 64, 128, 256}) {
    AxisymmetricContact c(2.3 * hertz.contact_radius, rings, e_star);
    const auto s = c.solve(sphere_gap(c, kTip), kLoad);
    ASSERT_TRUE(s.converged) << s.message;
    double load = 0.0, squared = 0.0;
    for (int i = 0; i < rings; ++i) {
      load += c.ring_area(i) * s.pressure[i];
      const double e = s.pressure[i] - hertz.pressure(c.ring_radius(i));
      squared += e * e * c.ring_area(i);
    }
    EXPECT_NEAR(load / kLoad, 1.0, 1e-12) << rings;  // load balance is exact
    approach_error.push_back(std::abs(s.approach / hertz.approach - 1.0));
    peak_error.push_back(std::abs(s.peak_pressure / hertz.peak_pressure - 1.0));
    rms_error.push_back(std::sqrt(squared / (M_PI * std::pow(c.grid_radius(), 2))) / hertz.peak_pressure);
    radius_error.push_back(std::abs(s.contact_radius - hertz.contact_radius));
    widths.push_back(c.ring_width());
  }
  for (std::size_t k = 0; k < widths.size(); ++k) {
    EXPECT_LE(radius_error[k], widths[k]) << "contact radius within one ring";
    if (k == 0) continue;
    // Observed orders: second order for the integral quantities, first for the rms pressure
    // (the Hertz pressure has a square-root edge the piecewise-constant rings cannot follow).
    EXPECT_GT(std::log2(approach_error[k - 1] / approach_error[k]), 1.8) << k;
    EXPECT_GT(std::log2(peak_error[k - 1] / peak_error[k]), 1.8) << k;
    EXPECT_GT(std::log2(rms_error[k - 1] / rms_error[k]), 0.75) << k;  // edge position varies per grid
    std::printf("rings %3d: orders approach %.2f peak %.2f rms pressure %.2f\n", 32 << k,
                std::log2(approach_error[k - 1] / approach_error[k]), std::log2(peak_error[k - 1] / peak_error[k]),
                std::log2(rms_error[k - 1] / rms_error[k]));
  }
  EXPECT_LT(approach_error.back(), 5e-5);
  EXPECT_LT(peak_error.back(), 5e-5);
  EXPECT_LT(rms_error.back(), 2e-3);
}

TEST(AxisymmetricContact, RejectsImpossibleGrids) {
  EXPECT_THROW(AxisymmetricContact(0.0, 10, 1e9), std::invalid_argument);
  EXPECT_THROW(AxisymmetricContact(1e-4, 1, 1e9), std::invalid_argument);
  EXPECT_THROW(AxisymmetricContact(1e-4, 10, -1.0), std::invalid_argument);
}

TEST(AxisymmetricContact, ContactBeyondTheGridIsReported) {
  const double e_star = cu_al_modulus();
  const auto hertz = hertz_sphere_on_flat(kTip, e_star, kLoad);
  AxisymmetricContact c(0.5 * hertz.contact_radius, 32, e_star);
  const auto s = c.solve(sphere_gap(c, kTip), kLoad);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.message.find("edge of the grid"), std::string::npos) << s.message;
}

namespace {
PinWearParameters pin(double grid_radius, int rings) {
  PinWearParameters p;
  p.tip_radius = kTip;
  p.effective_modulus = cu_al_modulus();
  p.grid_radius = grid_radius;
  p.rings = rings;
  return p;
}
}  // namespace

TEST(PinWear, WornVolumeIsArchardAndTheFlatGrowsAsPressureFalls) {
  const runin::tribo::ArchardWear archard(1e-4, 1e9);
  const auto hertz = hertz_sphere_on_flat(kTip, cu_al_modulus(), kLoad);
  PinWear wear(pin(4.0 * hertz.contact_radius, 96), archard, kLoad);
  EXPECT_NEAR(wear.contact().peak_pressure / hertz.peak_pressure, 1.0, 2e-3);
  double previous_peak = wear.contact().peak_pressure, previous_radius = wear.contact().contact_radius;
  for (int k = 1; k <= 10; ++k) {
    ASSERT_TRUE(wear.advance(2e-3)) << wear.message();
    // sum_i A_i dh_i = (k/H) ds sum_i A_i p_i = (k/H) W ds exactly: round-off tier.
    EXPECT_NEAR(wear.wear_volume() / archard.volume(kLoad, k * 2e-3), 1.0, 1e-10);
    EXPECT_LT(wear.contact().peak_pressure, previous_peak);
    EXPECT_GE(wear.contact().contact_radius, previous_radius);
    previous_peak = wear.contact().peak_pressure;
    previous_radius = wear.contact().contact_radius;
  }
  EXPECT_GT(wear.contact().contact_radius, 1.3 * hertz.contact_radius);
}

TEST(PinWear, SteadyWearLimitIsUniformPressure) {
  // Steady wear: dh/ds = (k/H) p equals the rigid approach rate over the contact, so p -> W / (pi a^2).
  const runin::tribo::ArchardWear archard(1e-4, 1e9);
  const double distance = 2.0;
  const double worn_radius = std::pow(4.0 * kTip * archard.volume(kLoad, distance) / M_PI, 0.25);  // cap volume
  PinWear wear(pin(1.3 * worn_radius, 128), archard, kLoad);
  auto spread = [&] {  // largest deviation from the mean pressure inside 0.8 a
    const auto &c = wear.contact();
    double worst = 0.0;
    for (int i = 0; i < wear.grid().rings(); ++i)
      if (wear.grid().ring_radius(i) < 0.8 * c.contact_radius)
        worst = std::max(worst, std::abs(c.pressure[i] / c.mean_pressure - 1.0));
    return worst;
  };
  EXPECT_GT(spread(), 0.3);  // Hertz: p0 / p_mean = 1.5 at the start
  ASSERT_TRUE(wear.advance(distance)) << wear.message();
  EXPECT_LT(spread(), 0.02);
  // The worn flat matches the spherical-cap volume estimate a = (4 R V / pi)^(1/4) (elastic part small).
  EXPECT_NEAR(wear.contact().contact_radius / worn_radius, 1.0, 0.05);
}

TEST(PinWear, FixedStepAboveTheStabilityBoundOscillatesAdaptiveDoesNot) {
  const runin::tribo::ArchardWear archard(1e-4, 1e9);
  const auto hertz = hertz_sphere_on_flat(kTip, cu_al_modulus(), kLoad);
  const auto parameters = pin(4.0 * hertz.contact_radius, 64);
  PinWear fixed(parameters, archard, kLoad), adaptive(parameters, archard, kLoad);
  const double bound = fixed.stable_step() / parameters.step_safety;  // 2H / (k k_c)
  const double step = 3.0 * bound;
  bool fixed_peak_rose = false;
  double fixed_sawtooth = 0.0, adaptive_sawtooth = 0.0;
  for (int k = 0; k < 20; ++k) {
    const double fixed_before = fixed.contact().peak_pressure, adaptive_before = adaptive.contact().peak_pressure;
    ASSERT_TRUE(fixed.step(step)) << fixed.message();
    ASSERT_TRUE(adaptive.advance(step)) << adaptive.message();
    fixed_peak_rose = fixed_peak_rose || fixed.contact().peak_pressure > fixed_before;
    EXPECT_LT(adaptive.contact().peak_pressure, adaptive_before) << k;
    fixed_sawtooth = std::max(fixed_sawtooth, sawtooth(fixed.contact()));
    adaptive_sawtooth = std::max(adaptive_sawtooth, sawtooth(adaptive.contact()));
  }
  EXPECT_TRUE(fixed_peak_rose);
  EXPECT_GT(fixed_sawtooth, 1.0);
  EXPECT_LT(adaptive_sawtooth, 0.25);
  EXPECT_GE(adaptive.steps(), 20 * 6);  // the bound forced sub-steps (safety 0.5: >= 6 per 3 bounds)
}

TEST(PinWear, ThesisArchardFormWearsAThirdOfThePlainForm) {
  // Eq. 1.4 of the thesis, V = k W s / (3H), against the usual V = k W s / H.
  const auto hertz = hertz_sphere_on_flat(kTip, cu_al_modulus(), kLoad);
  const auto parameters = pin(4.0 * hertz.contact_radius, 48);
  PinWear plain(parameters, runin::tribo::ArchardWear(1e-4, 1e9), kLoad);
  PinWear thesis(parameters, runin::tribo::ArchardWear(1e-4, 1e9, runin::tribo::ArchardForm::thesis), kLoad);
  ASSERT_TRUE(plain.advance(5e-3));
  ASSERT_TRUE(thesis.advance(5e-3));
  EXPECT_NEAR(plain.wear_volume() / (1e-4 * kLoad * 5e-3 / 1e9), 1.0, 1e-10);
  EXPECT_NEAR(thesis.wear_volume() / (1e-4 * kLoad * 5e-3 / 3e9), 1.0, 1e-10);
}

// The disk's track: its own Archard k_d/H_d, spread over the swept band.
TEST(DiskTrackWear, VolumeIsTheClosedFormForAConstantLoad) {
  constexpr double k_d = 1e-4, hardness = 0.245e9, track_radius = 0.102, width = 1.9e-4;
  const double circumference = 2.0 * M_PI * track_radius;
  for (auto form : {runin::tribo::ArchardForm::plain, runin::tribo::ArchardForm::thesis}) {
    DiskTrackWear disk(runin::tribo::ArchardWear(k_d, hardness, form), track_radius);
    const double factor = k_d / (form == runin::tribo::ArchardForm::thesis ? 3.0 * hardness : hardness);
    EXPECT_EQ(disk.depth(), 0.0);
    // Uneven increments, as the CVODE output grid with its event times gives them.
    double s = 0.0;
    for (int i = 1; i <= 2000; ++i) {
      const double ds = 1e-3 * (1.0 + 0.5 * std::sin(0.37 * i));
      disk.slide(kLoad, ds, width * std::min(1.0, i / 500.0));
      s += ds;
      EXPECT_NEAR(disk.volume() / (factor * kLoad * s), 1.0, 1e-10) << i;
      // Track depth: one pass leaves (k_d/H_d) W / w on the swept length; n passes n times that.
      const double passes = s / circumference;
      const double expected = passes < 1.0 ? factor * kLoad / disk.track_width()
                                           : factor * kLoad * s / (circumference * disk.track_width());
      EXPECT_NEAR(disk.depth() / expected, 1.0, 1e-10) << i;
      EXPECT_NEAR(disk.passes(), passes, 1e-12);
    }
    EXPECT_GT(disk.passes(), 2.0);  // both regimes covered
    EXPECT_DOUBLE_EQ(disk.track_width(), width);
    EXPECT_DOUBLE_EQ(disk.worn_length(), circumference);
  }
  EXPECT_THROW(DiskTrackWear(runin::tribo::ArchardWear(1e-4, 1e9), 0.0), std::invalid_argument);
  DiskTrackWear disk(runin::tribo::ArchardWear(1e-4, 1e9), 0.1);
  EXPECT_THROW(disk.slide(kLoad, -1e-3, 1e-4), std::invalid_argument);
}

TEST(DiskTrackWear, PinPlusDiskIsTheSumOfBothArchardVolumes) {
  // Each body by its own k_i/H_i (Cu pin H = 0.87 GPa, Al disk H = 0.245 GPa, potentials/CuAl.runin), slid
  // together as the CLI does: the pair loses (k_p/H_p + k_d/H_d) W s, and with equal k the pin's part is
  // tribo::wear_share(H_p, H_d) (the softer disk takes 1/H more).
  constexpr double h_pin = 0.87e9, h_disk = 0.245e9;
  const auto hertz = hertz_sphere_on_flat(kTip, cu_al_modulus(), kLoad);
  for (double k_disk : {1e-4, 3e-5}) {
    const runin::tribo::ArchardWear pin_archard(1e-4, h_pin), disk_archard(k_disk, h_disk);
    PinWear pin_wear(pin(4.0 * hertz.contact_radius, 64), pin_archard, kLoad);
    DiskTrackWear disk(disk_archard, 0.102);
    double s = 0.0;
    for (int i = 1; i <= 20; ++i) {
      const double ds = 2.5e-4 * i;
      ASSERT_TRUE(pin_wear.advance(ds)) << pin_wear.message();
      disk.slide(kLoad, ds, 2.0 * pin_wear.contact().contact_radius);
      s += ds;
      const double total = (1e-4 / h_pin + k_disk / h_disk) * kLoad * s;
      EXPECT_NEAR((pin_wear.wear_volume() + disk.volume()) / total, 1.0, 1e-10) << i;
    }
    const double pin_part = pin_wear.wear_volume() / (pin_wear.wear_volume() + disk.volume());
    if (k_disk == 1e-4) EXPECT_NEAR(pin_part, runin::tribo::wear_share(h_pin, h_disk), 1e-10);
    else EXPECT_GT(pin_part, runin::tribo::wear_share(h_pin, h_disk) + 0.1);
    EXPECT_NEAR(disk.track_width(), 2.0 * pin_wear.contact().contact_radius, 1e-15);
  }
}
