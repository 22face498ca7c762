// Worn-asperity geometry (truncated sphere) and Sneddon's flat-punch + Hertz normal contact.
#include "tribo/asperity_geometry.h"
#include "tribo/contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace runin::tribo;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST(TruncatedSphere, CapVolumeAndFlatMatchClosedForm)
{
  const double R = 1.3e-6;
  const TruncatedSphere sphere(R);
  for (double x : {1e-6, 0.01, 0.3, 1.0, 1.7, 2.0}) {
    const double h = x * R;
    const double volume = kPi * h * h * (3.0 * R - h) / 3.0;
    EXPECT_NEAR(sphere.cap_volume(h), volume, 1e-15 * volume) << "h/R = " << x;
    EXPECT_NEAR(sphere.flat_radius(h), std::sqrt(2.0 * R * h - h * h), 1e-15 * R) << "h/R = " << x;
  }
  EXPECT_NEAR(sphere.cap_volume(R), 2.0 / 3.0 * kPi * R * R * R, 1e-15 * R * R * R);    // hemisphere
  EXPECT_NEAR(sphere.flat_radius(R), R, 1e-15 * R);
  EXPECT_NEAR(sphere.cap_volume(2.0 * R), sphere.sphere_volume(), 1e-15 * sphere.sphere_volume());
  EXPECT_EQ(sphere.cap_volume(0.0), 0.0);
  EXPECT_EQ(sphere.flat_radius(0.0), 0.0);
}

// V(h(V)) == V to round-off over 17 decades of worn volume, and h(V(h)) == h.
TEST(TruncatedSphere, InverseIsExactToRoundOff)
{
  const double R = 1.0e-6;
  const TruncatedSphere sphere(R);
  double worst = 0.0;
  for (double fraction = 1e-17; fraction < 1.0; fraction *= 1.37) {
    const double volume = fraction * sphere.sphere_volume();
    const double h = sphere.cap_height(volume);
    ASSERT_GE(h, 0.0);
    ASSERT_LE(h, 2.0 * R);
    worst = std::max(worst, std::fabs(sphere.cap_volume(h) - volume) / volume);
  }
  EXPECT_LT(worst, 1e-14);
  // h(V) has the condition number (3 - x) / (3 (2 - x)), x = h/R: it grows only near the full sphere
  for (double x : {1e-9, 1e-4, 0.5, 1.0, 1.5, 1.999}) {
    const double h = x * R;
    const double condition = (3.0 - x) / (3.0 * (2.0 - x));
    EXPECT_NEAR(sphere.cap_height(sphere.cap_volume(h)), h, 1e-14 * condition * h) << "h/R = " << x;
  }
}

TEST(TruncatedSphere, InverseLimits)
{
  const double R = 2.0e-6;
  const TruncatedSphere sphere(R);
  EXPECT_EQ(sphere.cap_height(0.0), 0.0);
  EXPECT_EQ(sphere.cap_height(-1e-20), 0.0);
  EXPECT_NEAR(sphere.cap_height(2.0 / 3.0 * kPi * R * R * R), R, 1e-15 * R);    // half the sphere
  EXPECT_EQ(sphere.cap_height(sphere.sphere_volume()), 2.0 * R);
  EXPECT_EQ(sphere.cap_height(10.0 * sphere.sphere_volume()), 2.0 * R);    // clamps
  // small caps: V = pi R h^2 (1 - h / 3R), so h = s (1 + s / 6R + O(s^2/R^2)) with s = sqrt(V / (pi R))
  const double volume = 1e-30;
  const double s = std::sqrt(volume / (kPi * R));
  EXPECT_NEAR(sphere.cap_height(volume), s * (1.0 + s / (6.0 * R)), 1e-12 * s);
  EXPECT_THROW(TruncatedSphere(0.0), InvalidCoefficient);
}

// Wear lowers the summit and widens the flat; deposited material refills the cap first.
TEST(WornAsperity, WearFlattensAndTransferRefills)
{
  const double R = 1.0e-6;
  const TruncatedSphere sphere(R);
  double previous_drop = 0.0, previous_flat = 0.0;
  for (double volume : {1e-22, 1e-21, 1e-20, 1e-19}) {
    const WornAsperity worn = worn_asperity(R, volume, 0.0);
    EXPECT_GT(worn.summit_drop, previous_drop);
    EXPECT_GT(worn.flat_radius, previous_flat);
    EXPECT_NEAR(sphere.cap_volume(worn.summit_drop), volume, 1e-14 * volume);
    previous_drop = worn.summit_drop;
    previous_flat = worn.flat_radius;
  }
  const WornAsperity refilled = worn_asperity(R, 3e-20, 1e-20);
  EXPECT_NEAR(refilled.summit_drop, sphere.cap_height(2e-20), 1e-15 * R);
  const WornAsperity grown = worn_asperity(R, 1e-20, 4e-20);
  EXPECT_NEAR(grown.summit_drop, -3e-20 / (kPi * R * R), 1e-15 * R);
  EXPECT_EQ(grown.flat_radius, 0.0);
}

// The part of a summit's drop that plastic flattening left: all of it for a summit that was only flattened
// (the drop recovered from the flattened volume), the volume share for a summit also worn, none without
// flattening or drop.
TEST(WornAsperity, FlattenedPartOfTheDrop)
{
  const double R = 2e-5, pi = 3.14159265358979323846;
  const TruncatedSphere sphere(R);
  for (double h : {1e-10, 3e-8, 1e-6, 0.5 * R}) {
    const double flattened = pi * h * h * (3.0 * R - h) / 3.0;
    const double drop = sphere.cap_height(flattened);
    EXPECT_NEAR(flattened_part_of_drop(R, drop, flattened), drop, 1e-14 * drop) << h;
    // worn by as much again: the flattened share of the total cap
    const double total = sphere.cap_height(2.0 * flattened);
    EXPECT_NEAR(flattened_part_of_drop(R, total, flattened), 0.5 * total, 1e-12 * total) << h;
  }
  EXPECT_EQ(flattened_part_of_drop(R, 0.0, 1e-20), 0.0);
  EXPECT_EQ(flattened_part_of_drop(R, 1e-8, 0.0), 0.0);
  EXPECT_EQ(flattened_part_of_drop(R, -1e-9, 1e-20), 0.0);
}

TEST(FlatHertzNormal, ZeroFlatIsHertz)
{
  const double E = 4.8e10, R = 5e-7;
  const FlatHertzNormal worn(E, R, 0.0);
  const HertzNormal hertz(E, R);
  for (double delta : {1e-12, 1e-10, 3e-9, 1e-8}) {
    EXPECT_NEAR(worn.force(delta), 4.0 / 3.0 * E * std::sqrt(R) * std::pow(delta, 1.5),
                1e-14 * hertz.force(delta));
    EXPECT_NEAR(worn.contact_radius(delta), std::sqrt(R * delta), 1e-15 * std::sqrt(R * delta));
    EXPECT_NEAR(worn.stiffness(delta), hertz.stiffness(delta), 1e-14 * hertz.stiffness(delta));
    EXPECT_NEAR(worn.elastic_energy(delta), hertz.elastic_energy(delta), 1e-14 * hertz.elastic_energy(delta));
  }
  EXPECT_EQ(worn.force(0.0), 0.0);
  EXPECT_EQ(worn.force(-1e-9), 0.0);
}

TEST(FlatHertzNormal, MatchesSneddonClosedForm)
{
  const double E = 4.8e10, R = 5e-7, b = 4e-8;
  const FlatHertzNormal worn(E, R, b);
  for (double delta : {1e-11, 1e-10, 1e-9, 1e-8}) {
    const double a2 = (b * b + std::sqrt(std::pow(b, 4) + 4.0 * R * R * delta * delta)) / 2.0;
    const double c = std::sqrt(a2 - b * b);
    const double force = 2.0 * E / (3.0 * R) * c * (2.0 * a2 + b * b);
    EXPECT_NEAR(worn.force(delta), force, 1e-12 * force) << delta;
    EXPECT_NEAR(worn.contact_radius(delta), std::sqrt(a2), 1e-14 * std::sqrt(a2));
    EXPECT_NEAR(worn.stiffness(delta), 2.0 * E * std::sqrt(a2), 1e-14 * E * std::sqrt(a2));
  }
}

// Small overlap: a rigid flat punch of radius b, F = 2 E* b delta.
TEST(FlatHertzNormal, SmallOverlapIsFlatPunch)
{
  const double E = 7e10, R = 1e-6, b = 1e-7;
  const FlatHertzNormal worn(E, R, b);
  const double delta = 1e-16;    // R delta / b^2 = 1e-8: the curved ring is negligible
  EXPECT_NEAR(worn.force(delta), 2.0 * E * b * delta, 1e-7 * 2.0 * E * b * delta);
  EXPECT_NEAR(worn.contact_radius(delta), b, 1e-15 * b);
}

// The stiffness is the derivative of the force and the force the derivative of the energy.
TEST(FlatHertzNormal, StiffnessAndEnergyAreConsistent)
{
  const FlatHertzNormal worn(4.8e10, 5e-7, 3e-8);
  for (double delta : {1e-10, 2e-9, 8e-9}) {
    const double step = 1e-4 * delta;
    const double dforce = (worn.force(delta + step) - worn.force(delta - step)) / (2.0 * step);
    EXPECT_NEAR(dforce, worn.stiffness(delta), 1e-7 * worn.stiffness(delta));
    const double denergy = (worn.elastic_energy(delta + step) - worn.elastic_energy(delta - step)) / (2.0 * step);
    EXPECT_NEAR(denergy, worn.force(delta), 1e-7 * worn.force(delta));
  }
  EXPECT_THROW(FlatHertzNormal(4.8e10, 5e-7, -1e-9), InvalidCoefficient);
  EXPECT_EQ(combined_flat_radius(2e-8, 5e-8), 2e-8);
}

// --- Fast paths of the force loops: they must agree with the validated kernels to round-off ---

// evaluate() (one pass, a Hertz branch for b = 0) against the member functions, from the flat punch
// (R delta << b^2) through b ~ sqrt(R delta) to Hertz-like contacts (R delta >> b^2).
TEST(FlatHertzNormal, EvaluateAgreesWithMembersToRoundOff)
{
  const double E = 4.817e10, R = 5e-7;
  double worst = 0.0;
  for (double b : {0.0, 1e-10, 3e-9, 4e-8, 2e-7}) {
    const FlatHertzNormal worn(E, R, b);
    for (double delta = 1e-16; delta < 1e-7; delta *= 3.1) {
      const FlatHertzContact fast = worn.evaluate(delta);
      const double expected[4] = {worn.contact_radius(delta), worn.curved_radius(delta), worn.force(delta),
                                  worn.stiffness(delta)};
      const double got[4] = {fast.contact_radius, fast.curved_radius, fast.force, fast.stiffness};
      for (int k = 0; k < 4; ++k) {
        ASSERT_GT(expected[k], 0.0);
        worst = std::max(worst, std::fabs(got[k] - expected[k]) / expected[k]);
        EXPECT_NEAR(got[k], expected[k], 4e-15 * expected[k]) << "b " << b << " delta " << delta << " k " << k;
      }
    }
    const FlatHertzContact none = worn.evaluate(0.0), apart = worn.evaluate(-1e-9);
    EXPECT_EQ(none.force, 0.0);
    EXPECT_EQ(none.stiffness, 0.0);
    EXPECT_EQ(apart.contact_radius, 0.0);
  }
  EXPECT_LT(worst, 4e-15);
}

// cap_height(V, h_near), the per-step path (fifth-order steps from the previous height), returns the closed-form root
// to round-off: from heights a part per million to a few percent off, and from unusable starts (fallback).
TEST(TruncatedSphere, CapHeightFromNearbyHeightMatchesClosedForm)
{
  const double R = 1.0e-6;
  const TruncatedSphere sphere(R);
  for (double fraction = 1e-15; fraction < 1.0; fraction *= 2.9) {
    const double volume = fraction * sphere.sphere_volume();
    const double exact = sphere.cap_height(volume);
    const double x = exact / R;
    const double tolerance = 4e-16 * (3.0 - x) / (3.0 * (2.0 - x)) * 3.0 * exact;    // condition of h(V)
    for (double previous_fraction : {1.0 - 1e-6, 1.0 - 1e-3, 0.97, 1.0 + 1e-6}) {
      const double near = sphere.cap_height(previous_fraction * volume);
      EXPECT_NEAR(sphere.cap_height(volume, near), exact, tolerance) << fraction << " " << previous_fraction;
    }
    for (double unusable : {0.0, -1e-9, 2.0 * R, 5.0 * R})
      EXPECT_NEAR(sphere.cap_height(volume, unusable), exact, tolerance) << fraction << " " << unusable;
    EXPECT_NEAR(sphere.cap_height(volume, 1.4 * R), exact, tolerance) << fraction;    // far: several steps or fallback
  }
  EXPECT_EQ(sphere.cap_height(0.0, 1e-7), 0.0);
  EXPECT_EQ(sphere.cap_height(2.0 * sphere.sphere_volume(), 1e-7), 2.0 * R);
}

// worn_asperity from the previous summit drop gives the geometry of the closed form, also across the switch
// between a net loss and a net gain.
TEST(WornAsperity, PreviousDropGivesTheSameGeometry)
{
  const double R = 1e-6;
  for (double lost : {0.0, 1e-24, 3e-21, 1e-19}) {
    for (double gained : {0.0, 2e-24, 1e-21}) {
      const WornAsperity exact = worn_asperity(R, lost, gained);
      for (double previous : {0.0, -1e-12, exact.summit_drop * (1.0 - 1e-6), 1e-9}) {
        const WornAsperity fast = worn_asperity(R, lost, gained, previous);
        EXPECT_NEAR(fast.summit_drop, exact.summit_drop, 1e-15 * std::fabs(exact.summit_drop)) << lost << " " << gained;
        EXPECT_NEAR(fast.flat_radius, exact.flat_radius, 1e-15 * exact.flat_radius) << lost << " " << gained;
      }
    }
  }
}

// A stored height of an unchanged volume is kept bit for bit (the state survives write/read_restart, whose
// setup refreshes every atom), up to h = 1.5 R where h(V) is well conditioned.
TEST(TruncatedSphere, CapHeightOfAnUnchangedVolumeIsKept)
{
  const double R = 1.0e-6;
  const TruncatedSphere sphere(R);
  for (double fraction = 1e-15; fraction < 0.84; fraction *= 1.9) {
    const double volume = fraction * sphere.sphere_volume();
    const double stored = sphere.cap_height(volume, sphere.cap_height((1.0 - 1e-6) * volume));
    EXPECT_EQ(sphere.cap_height(volume, stored), stored) << fraction;
  }
}
