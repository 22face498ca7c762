// mindlin_spring against LAMMPS's pair granular 'tangential mindlin' (GRANULAR/pair_granular.cpp, compute(),
// LAMMPS 29Sep2021): frame update with length restore (Luding 2008 eq. 17) above LAMMPS's threshold, then
// advance, then the Coulomb rescale; RunIn's slip distance on top.
#include "tribo/contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace runin::tribo;

namespace {
double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const double *a) { return std::sqrt(dot3(a, a)); }

// The TANGENTIAL_MINDLIN branch of PairGranular::compute, transcribed (history = spring, k_tangential = kt,
// Fscrit = limit, damp_tangential = 0 as with a zero damping coefficient), for a step (historyupdate) or
// setup. Returns the force fs1..fs3.
void lammps_mindlin(double kt, double limit, const double n[3], const double vtr[3], double dt, double history[3],
                    bool historyupdate, double fs[3])
{
  const double EPSILON = 1e-10, damp_tangential = 0.0;
  if (historyupdate) {
    const double rsht = history[0] * n[0] + history[1] * n[1] + history[2] * n[2];
    if (std::fabs(rsht) * kt > EPSILON * limit) {
      const double shrmag = std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
      history[0] -= rsht * n[0];
      history[1] -= rsht * n[1];
      history[2] -= rsht * n[2];
      const double prjmag = std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
      const double scalefac = prjmag > 0 ? shrmag / prjmag : 0;
      history[0] *= scalefac;
      history[1] *= scalefac;
      history[2] *= scalefac;
    }
    history[0] += vtr[0] * dt;
    history[1] += vtr[1] * dt;
    history[2] += vtr[2] * dt;
  }
  fs[0] = -kt * history[0] - damp_tangential * vtr[0];
  fs[1] = -kt * history[1] - damp_tangential * vtr[1];
  fs[2] = -kt * history[2] - damp_tangential * vtr[2];
  const double f = std::sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
  if (f > limit) {
    const double shrmag = std::sqrt(history[0] * history[0] + history[1] * history[1] + history[2] * history[2]);
    if (shrmag != 0.0) {
      for (int k = 0; k < 3; ++k) history[k] = -1.0 / kt * (limit * fs[k] / f + damp_tangential * vtr[k]);
      for (int k = 0; k < 3; ++k) fs[k] *= limit / f;
    } else {
      fs[0] = fs[1] = fs[2] = 0.0;
    }
  }
}

// unit normal at angle theta in the x-z plane, tilted by phi out of it (a contact rolling over its partner)
void rotating_normal(double theta, double phi, double n[3])
{
  n[0] = std::sin(theta) * std::cos(phi);
  n[1] = std::sin(phi);
  n[2] = std::cos(theta) * std::cos(phi);
}
}    // namespace

// A stuck spring (limit far above k_t |xi|, no relative velocity) on a contact whose normal turns by 90
// degrees in 900 steps: it turns with the normal and keeps its length and stays in the tangent plane.
// Projection alone (the former kernel) would shrink it by cos(dtheta) per step.
TEST(MindlinLammps, RotatingNormalPreservesSpringLength)
{
  const double kt = 5e3, limit = 1.0, dt = 1e-10, zero[3] = {0.0, 0.0, 0.0};
  double spring[3] = {2e-9, 1e-9, 0.0}, slip = 0.0;    // tangent to n = (0, 0, 1)
  const double length = norm3(spring);
  const int steps = 900;
  double n[3];
  for (int step = 1; step <= steps; ++step) {
    rotating_normal(0.5 * M_PI * step / steps, 0.2 * std::sin(0.01 * step), n);
    const TangentialUpdate out = mindlin_spring(kt, limit, n, zero, dt, spring, slip, true);
    ASSERT_FALSE(out.slipping);
    ASSERT_NEAR(norm3(spring), length, 1e-14 * length) << step;
    ASSERT_NEAR(dot3(spring, n), 0.0, 1e-14 * length) << step;
    ASSERT_NEAR(out.force_magnitude, kt * length, 1e-14 * kt * length) << step;
  }
  EXPECT_EQ(slip, 0.0);
}

// Below LAMMPS's threshold |xi.n| k_t <= 1e-10 limit the frame is not updated: the spring is taken as is.
TEST(MindlinLammps, NegligibleNormalPartIsNotRotated)
{
  const double kt = 1e4, limit = 1e-4, n[3] = {0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
  double spring[3] = {3e-9, -4e-9, 0.5e-10 * limit / kt}, slip = 0.0;    // |xi.n| k_t = 0.5e-10 limit
  const double before[3] = {spring[0], spring[1], spring[2]};
  const TangentialUpdate out = mindlin_spring(kt, limit, n, zero, 1e-9, spring, slip, true);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(spring[k], before[k]);
    EXPECT_EQ(out.force[k], -kt * before[k]);
  }
  spring[2] = 2e-10 * limit / kt;    // above the threshold: rotated into the plane, length kept
  const double length = norm3(spring);
  mindlin_spring(kt, limit, n, zero, 1e-9, spring, slip, true);
  EXPECT_EQ(spring[2], 0.0);
  EXPECT_NEAR(norm3(spring), length, 1e-15 * length);
}

// Stick limit: a contact sticks (F_t = -k_t xi exactly) while k_t |xi| <= limit, i.e. up to the
// displacement limit / k_t; beyond, |F_t| is the limit and the spring is left at length limit / k_t.
TEST(MindlinLammps, SticksUpToKtDeltaThenHoldsTheLimit)
{
  const double kt = 2e5, limit = 1e-3, dt = 1e-9, n[3] = {0.0, 0.6, 0.8};
  const double vt[3] = {1.0, 0.8, -0.6};    // tangential: vt.n = 0
  double spring[3] = {0.0, 0.0, 0.0}, slip = 0.0;
  const double stick_distance = limit / kt;    // 5e-9 m
  int step = 0;
  for (;; ++step) {
    const double trial[3] = {spring[0] + vt[0] * dt, spring[1] + vt[1] * dt, spring[2] + vt[2] * dt};
    const TangentialUpdate out = mindlin_spring(kt, limit, n, vt, dt, spring, slip, true);
    if (out.slipping) {
      EXPECT_GT(kt * norm3(trial), limit);
      EXPECT_NEAR(out.force_magnitude, limit, 1e-15 * limit);
      EXPECT_NEAR(norm3(out.force), limit, 1e-15 * limit);
      EXPECT_NEAR(kt * norm3(spring), limit, 1e-15 * limit);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(out.force[k], -kt * spring[k], 1e-15 * limit);
      break;
    }
    ASSERT_LE(kt * norm3(trial), limit * (1.0 + 1e-15)) << step;
    for (int k = 0; k < 3; ++k) ASSERT_EQ(out.force[k], -kt * spring[k]) << step;
    ASSERT_EQ(slip, 0.0);
    ASSERT_LT(step, 1000);
  }
  // slips on the first step whose trial displacement exceeds limit / k_t (|vt| dt = 1.414e-9 m per step)
  const double per_step = norm3(vt) * dt;
  EXPECT_EQ(step + 1, static_cast<int>(std::ceil(stick_distance / per_step)));
  // exactly at the limit the spring still sticks (LAMMPS: slip only for |F_t| > F_scrit)
  double at_limit[3] = {stick_distance, 0.0, 0.0}, no_slip = 0.0;
  const double z[3] = {0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
  const TangentialUpdate held = mindlin_spring(kt, kt * stick_distance, z, zero, dt, at_limit, no_slip, true);
  EXPECT_FALSE(held.slipping);
  EXPECT_EQ(held.force[0], -kt * stick_distance);
}

// slip_increment is the length by which the spring was shortened at the limit, |xi + vt dt| - limit / k_t:
// at the first slip, on a rotating contact, and in steady sliding (where it is |vt| dt).
TEST(MindlinLammps, SlipIncrementIsTheShortening)
{
  const double kt = 7.6e3, limit = 1.2e-5, dt = 1e-10;
  std::mt19937_64 rng(2021);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double spring[3] = {0.0, 0.0, 0.0}, slip = 0.0, n[3], expected_slip = 0.0;
  int slipping = 0;
  for (int step = 0; step < 400; ++step) {
    rotating_normal(1e-3 * step, 0.0, n);
    // sliding along +y at 1 m/s with a small random wobble in the plane, then reversing
    const double speed = step < 300 ? 1.0 : -1.0, wobble = 0.1 * uniform(rng);
    const double vt[3] = {wobble * n[2], speed, -wobble * n[0]};    // tangent to n = (sin t, 0, cos t)
    // the trial spring: frame update (length kept) and advance
    const double rsht = dot3(spring, n);
    double trial[3] = {spring[0], spring[1], spring[2]};
    if (std::fabs(rsht) * kt > 1e-10 * limit) {
      const double length = norm3(trial);
      for (int k = 0; k < 3; ++k) trial[k] -= rsht * n[k];
      const double scale = length / norm3(trial);
      for (int k = 0; k < 3; ++k) trial[k] *= scale;
    }
    for (int k = 0; k < 3; ++k) trial[k] += vt[k] * dt;
    const TangentialUpdate out = mindlin_spring(kt, limit, n, vt, dt, spring, slip, true);
    if (out.slipping) {
      ++slipping;
      EXPECT_NEAR(out.slip_increment, norm3(trial) - limit / kt, 1e-14 * limit / kt) << step;
      EXPECT_NEAR(out.slip_increment, norm3(trial) - norm3(spring), 1e-14 * limit / kt) << step;
    } else {
      EXPECT_EQ(out.slip_increment, 0.0);
    }
    expected_slip += out.slip_increment;
    ASSERT_EQ(slip, expected_slip);
  }
  EXPECT_GT(slipping, 300);
  EXPECT_LT(slipping, 400);    // the reversal sticks for a while

  // steady sliding along a fixed direction: the slider slips by exactly |vt| dt per step
  const double z[3] = {0.0, 0.0, 1.0}, vt[3] = {0.6, -0.8, 0.0};
  double straight[3] = {0.0, 0.0, 0.0}, s = 0.0;
  for (int step = 0; step < 100; ++step) {
    const double before = s;
    const TangentialUpdate out = mindlin_spring(kt, limit, z, vt, dt, straight, s, true);
    if (step > 20) {
      ASSERT_TRUE(out.slipping);
      ASSERT_NEAR(s - before, dt, 1e-12 * dt) << step;
    }
  }
}

// Against the LAMMPS transcription over a random history: rotating and tilting normals, random tangential
// velocities (stick, slip, reversals), k_t and limit changing with the overlap, a limit that drops to zero
// (F_n clamped), and setup calls. Equal to rounding: RunIn restores the length with one square root of the
// squared ratio and rescales a slipping spring with two divisions where LAMMPS takes five (shorter chains
// of dependent operations in the force loop); the two histories, each carried on by its own code, stay
// within 1e-13 of each other over the 5000 steps.
TEST(MindlinLammps, AgreesWithPairGranularToRounding)
{
  std::mt19937_64 rng(29092021);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double spring[3] = {0.0, 0.0, 0.0}, history[3] = {0.0, 0.0, 0.0}, slip = 0.0;
  int slipping = 0, sticking = 0;
  for (int step = 0; step < 5000; ++step) {
    double n[3];
    rotating_normal(2e-3 * step + 0.01 * uniform(rng), 0.3 * std::sin(1e-3 * step), n);
    const double a = 1e-7 * (1.0 + 0.5 * std::sin(3e-3 * step));    // contact radius
    const double kt = 8.0 * 2.6e10 * a;
    const double limit = (step % 500 < 20) ? 0.0 : 0.5 * 4.0 / 3.0 * 3.8e10 * a * a * a / 1e-6;
    const double dir[3] = {uniform(rng), uniform(rng), uniform(rng)};
    const double along = dot3(dir, n);
    const double speed = (step / 250) % 2 ? 0.02 : 5.0;
    const double vt[3] = {speed * (dir[0] - along * n[0]), speed * (dir[1] - along * n[1]),
                          speed * (dir[2] - along * n[2])};
    const bool advance = step % 97 != 0;
    double fs[3];
    if (!advance) {
      // setup differs on purpose (SetupReadsButDoesNotStore): LAMMPS may rescale its history there and
      // takes the spring unrotated; RunIn stores nothing. Both continue from the stored spring.
      mindlin_spring(kt, limit, n, vt, 1e-10, spring, slip, false);
      continue;
    }
    lammps_mindlin(kt, limit, n, vt, 1e-10, history, true, fs);
    const TangentialUpdate out = mindlin_spring(kt, limit, n, vt, 1e-10, spring, slip, true);
    const double force_scale = norm3(fs), spring_scale = norm3(history);
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(out.force[k], fs[k], 1e-13 * force_scale) << step << " " << k;
      ASSERT_NEAR(spring[k], history[k], 1e-13 * spring_scale) << step << " " << k;
    }
    (out.slipping ? slipping : sticking)++;
  }
  EXPECT_GT(slipping, 500);
  EXPECT_GT(sticking, 500);
}

// The restore factor from a spring nearly in the new plane to one nearly along the normal (q = sin^2 of its
// angle to the plane): the rotated spring equals LAMMPS's to rounding and keeps its length.
TEST(MindlinLammps, RestoreAgreesWithLammpsAtEveryAngle)
{
  const double n[3] = {0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
  for (double q : {1e-10, 1e-6, 1e-3, 0.1, 0.9}) {
    const double s = std::sqrt(q), c = std::sqrt(1.0 - q);
    double spring[3] = {1e-9 * c * 0.6, 1e-9 * c * 0.8, 1e-9 * s}, history[3], slip = 0.0, fs[3];
    for (int k = 0; k < 3; ++k) history[k] = spring[k];
    const double length = norm3(spring);
    lammps_mindlin(1e6, 1.0, n, zero, 1e-9, history, true, fs);
    mindlin_spring(1e6, 1.0, n, zero, 1e-9, spring, slip, true);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(spring[k], history[k], 4e-16 * length) << "q = " << q << " " << k;
    EXPECT_NEAR(norm3(spring), length, 4e-16 * length) << "q = " << q;
    EXPECT_EQ(spring[2], 0.0) << "q = " << q;
  }
}

// A spring lying along the new normal but for a denormal remainder: the squared-ratio restore would
// overflow to inf (LAMMPS's two lengths would not); the spring is dropped instead and the force is finite.
TEST(MindlinLammps, SpringAlongTheNormalStaysFinite)
{
  const double n[3] = {0.0, 0.0, 1.0}, zero[3] = {0.0, 0.0, 0.0};
  double spring[3] = {1e-160, 0.0, 1.0}, slip = 0.0;
  const TangentialUpdate out = mindlin_spring(1.0, 1.0, n, zero, 1e-9, spring, slip, true);
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(std::isfinite(out.force[k])) << k;
    EXPECT_TRUE(std::isfinite(spring[k])) << k;
  }
  EXPECT_EQ(spring[2], 0.0);
}

// Setup (advance = false): nothing is stored, and the force is that of the stored spring after the frame
// update (equal to LAMMPS's when the spring is in the tangent plane, as in a continued run).
TEST(MindlinLammps, SetupReadsButDoesNotStore)
{
  const double kt = 1e4, limit = 2e-5, n[3] = {0.0, 0.0, 1.0}, vt[3] = {3.0, 0.0, 0.0};
  double spring[3] = {1e-9, 1e-9, 1e-9}, slip = 0.5e-9;
  const TangentialUpdate out = mindlin_spring(kt, limit, n, vt, 1e-9, spring, slip, false);
  EXPECT_EQ(spring[0], 1e-9);
  EXPECT_EQ(spring[2], 1e-9);
  EXPECT_EQ(slip, 0.5e-9);
  EXPECT_NEAR(out.force[0], -kt * 1e-9 * std::sqrt(1.5), 1e-15 * limit);    // rotated, length kept
  EXPECT_EQ(out.force[2], 0.0);
  EXPECT_FALSE(out.slipping);
  // in the tangent plane the setup force is LAMMPS's, also at the limit
  double in_plane[3] = {3e-9, -1e-9, 0.0}, history[3] = {3e-9, -1e-9, 0.0}, fs[3];
  lammps_mindlin(kt, limit, n, vt, 1e-9, history, false, fs);
  const TangentialUpdate capped = mindlin_spring(kt, limit, n, vt, 1e-9, in_plane, slip, false);
  EXPECT_TRUE(capped.slipping);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(capped.force[k], fs[k]);
  EXPECT_EQ(in_plane[0], 3e-9);    // LAMMPS would have rescaled its history here; RunIn keeps it
  EXPECT_EQ(slip, 0.5e-9);
}
