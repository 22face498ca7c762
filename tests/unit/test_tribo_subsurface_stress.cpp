// Subsurface stress kernels (src/tribo/subsurface_stress.h, doc/subsurface_stress.md).
// Tolerance tiers: identities of one closed form (axis limit, surface equilibrium, equilibrium in the volume):
// 1e-6 p0 or tighter; published maxima: 1 %; the influence-function tier against a closed form: 2 % of p0.
#include "tribo/subsurface_stress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using namespace runin::tribo;

namespace {

constexpr double kPi = 3.14159265358979323846;

double hertz_p(double r) { return r < 1.0 ? std::sqrt(1.0 - r * r) : 0.0; }

// Johnson (1985) eq. 3.45, coded again here: frictionless sphere, on the axis, p0 = a = 1.
double johnson_axis_von_mises(double z, double nu)
{
  const double sr = -(1.0 + nu) * (1.0 - z * std::atan(1.0 / z)) + 0.5 / (1.0 + z * z);
  const double sz = -1.0 / (1.0 + z * z);
  return std::abs(sr - sz);    // sigma_r = sigma_theta: von Mises = |sigma_r - sigma_z|
}

// Johnson (1985) eq. 4.50: frictionless line contact on its axis (x = 0), p0 = b = 1, plane strain.
StressTensor johnson_line_axis(double z, double nu)
{
  StressTensor s;
  const double w = std::sqrt(1.0 + z * z);
  s.xx = -((1.0 + 2.0 * z * z) / w - 2.0 * z);
  s.zz = -1.0 / w;
  s.yy = nu * (s.xx + s.zz);
  return s;
}

// Golden-section maximum of f on [lo, hi].
std::pair<double, double> maximise(const std::function<double(double)> &f, double lo, double hi)
{
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi, c = b - g * (b - a), d = a + g * (b - a);
  for (int i = 0; i < 200 && b - a > 1e-10; ++i) {
    if (f(c) > f(d)) b = d; else a = c;
    c = b - g * (b - a), d = a + g * (b - a);
  }
  const double x = 0.5 * (a + b);
  return {x, f(x)};
}

double max_component_difference(const StressTensor &a, const StressTensor &b)
{
  return std::max({std::abs(a.xx - b.xx), std::abs(a.yy - b.yy), std::abs(a.zz - b.zz), std::abs(a.yz - b.yz),
                   std::abs(a.xz - b.xz), std::abs(a.xy - b.xy)});
}

// Largest von Mises stress over the plane y = 0 (x in [-1.5, 1.5], z in [0, 1.5]) of the Hamilton field.
StressPeak hamilton_plane_peak(const SlidingHertzSphere &c, double step)
{
  StressPeak p;
  for (double x = -1.5; x <= 1.5 + 1e-12; x += step)
    for (double z = 0.0; z <= 1.5 + 1e-12; z += step) {
      const double v = hamilton_stress(c, x, 0.0, z).von_mises();
      if (v > p.von_mises) p = {v, x, z};
    }
  return p;
}

}  // namespace

TEST(SubsurfaceStress, EquivalentStressesOfSimpleStates)
{
  const StressTensor uniaxial{-3.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_NEAR(uniaxial.von_mises(), 3.0, 1e-12);
  EXPECT_NEAR(uniaxial.tresca(), 3.0, 1e-12);
  const StressTensor shear{0.0, 0.0, 0.0, 0.0, 2.0, 0.0};
  EXPECT_NEAR(shear.von_mises(), std::sqrt(3.0) * 2.0, 1e-12);
  EXPECT_NEAR(shear.tresca(), 4.0, 1e-12);
  const StressTensor hydrostatic{-5.0, -5.0, -5.0, 0.0, 0.0, 0.0};
  EXPECT_NEAR(hydrostatic.von_mises(), 0.0, 1e-12);
  const auto p = StressTensor{1.0, 2.0, 3.0, 0.5, 0.0, 0.0}.principal();
  EXPECT_GE(p[0], p[1]);
  EXPECT_GE(p[1], p[2]);
  EXPECT_NEAR(p[0] + p[1] + p[2], 6.0, 1e-12);
}

// Hamilton's normal part on the axis is Johnson's eq. 3.45, and the off-axis equations join it continuously.
TEST(SubsurfaceStress, HamiltonFrictionlessAxisIsJohnson345)
{
  for (double nu : {0.0, 0.25, 0.3, 0.5})
    for (double z : {0.0, 0.1, 0.48, 1.0, 3.0}) {
      const SlidingHertzSphere c{2.0e8, 1.0e-4, nu, 0.0};
      const StressTensor s = hamilton_stress(c, 0.0, 0.0, z * 1.0e-4);
      const AxisStress ax = hertz_axis_stress(2.0e8, 1.0e-4, nu, z * 1.0e-4);
      EXPECT_NEAR(s.xx, ax.radial, 1e-9 * 2.0e8);
      EXPECT_NEAR(s.yy, ax.radial, 1e-9 * 2.0e8);
      EXPECT_NEAR(s.zz, ax.axial, 1e-9 * 2.0e8);
      if (z > 0.0) EXPECT_NEAR(s.von_mises() / 2.0e8, johnson_axis_von_mises(z, nu), 1e-9);
      // Just outside the interpolation zone (r = 0.011 a) the off-axis equations are within O(r^2) of the
      // axis for the normal stresses (even in r); the shears are odd in r.
      const StressTensor off = hamilton_stress(c, 1.1e-6, 0.0, z * 1.0e-4);
      EXPECT_NEAR(off.xx / 2.0e8, s.xx / 2.0e8, 1e-3) << "nu " << nu << " z " << z;
      EXPECT_NEAR(off.yy / 2.0e8, s.yy / 2.0e8, 1e-3) << "nu " << nu << " z " << z;
      EXPECT_NEAR(off.zz / 2.0e8, s.zz / 2.0e8, 1e-3) << "nu " << nu << " z " << z;
    }
}

// Verification item 1: frictionless, nu = 0.3: max von Mises 0.62 p0 at 0.48 a (Johnson 1985 §3.4, Fig. 3.9;
// Hamilton 1983), within 1 %, maximum found numerically on the axis.
TEST(SubsurfaceStress, HamiltonFrictionlessMaximumIs062At048)
{
  const SlidingHertzSphere c{1.0, 1.0, 0.3, 0.0};
  const auto [z, vm] = maximise([&](double d) { return hamilton_stress(c, 0.0, 0.0, d).von_mises(); }, 0.05, 2.0);
  std::cout << "Hamilton mu = 0, nu = 0.3: max von Mises " << vm << " p0 at z = " << z << " a\n";
  EXPECT_NEAR(vm, 0.62, 0.01 * 0.62);
  EXPECT_NEAR(z, 0.48, 0.01 * 0.48);
  // The axis holds the maximum of the whole y = 0 section.
  const StressPeak plane = hamilton_plane_peak(c, 0.01);
  EXPECT_NEAR(plane.von_mises, vm, 1e-3);
  EXPECT_NEAR(plane.x, 0.0, 0.011);
}

// Equilibrium of the surface element: sigma_zz = -p, sigma_xz = -q = -mu p, sigma_yz = 0 at z = 0.
TEST(SubsurfaceStress, HamiltonSurfaceTractions)
{
  for (double mu : {0.0, 0.3, -0.5}) {
    const SlidingHertzSphere c{1.0, 1.0, 0.3, mu};
    for (double x : {-1.3, -0.9, -0.4, 0.05, 0.6, 0.95, 1.2})
      for (double y : {0.0, 0.2, -0.3}) {
        const double p = hertz_p(std::hypot(x, y));
        const StressTensor s = hamilton_stress(c, x, y, 0.0);
        EXPECT_NEAR(s.zz, -p, 1e-9) << x << " " << y;
        EXPECT_NEAR(s.xz, -mu * p, 1e-9) << x << " " << y;
        EXPECT_NEAR(s.yz, 0.0, 1e-9) << x << " " << y;
      }
  }
}

// div sigma = 0 inside the body (central differences), for the normal and the tangential equations.
TEST(SubsurfaceStress, HamiltonIsInEquilibrium)
{
  const SlidingHertzSphere c{1.0, 1.0, 0.3, 0.4};
  const double h = 1e-4;
  for (const auto &pt : std::vector<std::array<double, 3>>{{0.3, 0.2, 0.4}, {-0.7, 0.5, 0.2}, {1.4, -0.3, 0.6},
                                                          {0.1, 0.9, 1.2}, {-0.2, -0.1, 0.05}}) {
    auto s = [&](double dx, double dy, double dz) { return hamilton_stress(c, pt[0] + dx, pt[1] + dy, pt[2] + dz); };
    const StressTensor xp = s(h, 0, 0), xm = s(-h, 0, 0), yp = s(0, h, 0), ym = s(0, -h, 0), zp = s(0, 0, h),
                       zm = s(0, 0, -h);
    const double fx = (xp.xx - xm.xx + yp.xy - ym.xy + zp.xz - zm.xz) / (2 * h);
    const double fy = (xp.xy - xm.xy + yp.yy - ym.yy + zp.yz - zm.yz) / (2 * h);
    const double fz = (xp.xz - xm.xz + yp.yz - ym.yz + zp.zz - zm.zz) / (2 * h);
    EXPECT_NEAR(fx, 0.0, 1e-5) << pt[0] << " " << pt[1] << " " << pt[2];
    EXPECT_NEAR(fy, 0.0, 1e-5) << pt[0] << " " << pt[1] << " " << pt[2];
    EXPECT_NEAR(fz, 0.0, 1e-5) << pt[0] << " " << pt[1] << " " << pt[2];
  }
}

// Verification item 2, mu = 0.3, nu = 0.3. Published statements compared against:
//  (a) the tensile stress at the trailing edge (x = -a, z = 0) is p0 [(1 - 2 nu)/3 + (4 + nu) pi mu / 8]
//      (Hamilton & Goodman 1966; Hamilton 1983; Johnson 1985 §7.2): 0.6399 p0 here, checked to 1e-6;
//  (b) friction moves the maximum von Mises stress forward (x > 0) and up from (0, 0.48 a), and the maximum
//      reaches the surface at the trailing edge when mu exceeds about 0.3 (Hamilton 1983; Johnson 1985 §7.2):
//      at mu = 0.3 the surface and subsurface maxima are within 2 % of each other (measured 0.651 vs 0.660 p0,
//      the subsurface one at x = 0.32 a, z = 0.43 a), at mu = 0.35 the surface one is larger, at 0.25 smaller.
TEST(SubsurfaceStress, HamiltonSlidingMaximumMovesToTheTrailingEdge)
{
  const double nu = 0.3;
  {
    const double mu = 0.3;
    const SlidingHertzSphere c{1.0, 1.0, nu, mu};
    const StressTensor edge = hamilton_stress(c, -1.0, 0.0, 0.0);
    EXPECT_NEAR(edge.xx, (1.0 - 2.0 * nu) / 3.0 + (4.0 + nu) * kPi * mu / 8.0, 1e-6);
  }
  auto surface_max = [&](double mu) {
    const SlidingHertzSphere c{1.0, 1.0, nu, mu};
    double v = 0.0;
    for (double x = -1.2; x <= 1.2; x += 0.002) v = std::max(v, hamilton_stress(c, x, 0.0, 0.0).von_mises());
    return v;
  };
  auto subsurface_max = [&](double mu) {
    const SlidingHertzSphere c{1.0, 1.0, nu, mu};
    StressPeak p;
    for (double x = -1.0; x <= 1.0; x += 0.01)
      for (double z = 0.05; z <= 1.0; z += 0.01) {
        const double v = hamilton_stress(c, x, 0.0, z).von_mises();
        if (v > p.von_mises) p = {v, x, z};
      }
    return p;
  };
  const StressPeak sub = subsurface_max(0.3);
  const double surf = surface_max(0.3);
  std::cout << "Hamilton mu = 0.3, nu = 0.3: subsurface max " << sub.von_mises << " p0 at x = " << sub.x
            << " a, z = " << sub.z << " a; surface max " << surf << " p0\n";
  EXPECT_GT(sub.x, 0.2);
  EXPECT_LT(sub.z, 0.46);
  EXPECT_GT(sub.von_mises, 0.62);
  EXPECT_NEAR(surf / sub.von_mises, 1.0, 0.02);
  EXPECT_GT(surface_max(0.35), subsurface_max(0.35).von_mises);
  EXPECT_LT(surface_max(0.25), subsurface_max(0.25).von_mises);
}

// Brute-force maximum of vm(x, z) on the section [-1.5, 1.5] x [0, 1.5] (units of a or b): a 0.01 mesh, then a
// 0.0002 mesh over +-0.02 around its best point.
StressPeak dense_maximum(const std::function<double(double, double)> &vm)
{
  StressPeak best;
  for (int i = 0; i <= 300; ++i)
    for (int k = 0; k <= 150; ++k) {
      const double x = -1.5 + 0.01 * i, z = 0.01 * k, v = vm(x, z);
      if (v > best.von_mises) best = {v, x, z};
    }
  const StressPeak coarse = best;
  for (int i = -100; i <= 100; ++i)
    for (int k = -100; k <= 100; ++k) {
      const double x = coarse.x + 0.0002 * i, z = coarse.z + 0.0002 * k;
      if (z < 0.0) continue;
      const double v = vm(x, z);
      if (v > best.von_mises) best = {v, x, z};
    }
  return best;
}

// The reported peak is the closed form's maximum, not the grid's: for mu = 0.3-0.7 the von Mises maximum is a
// cusp on the surface at the trailing edge (x = -a, z = 0), between the points of the pin's 64 x 64 grid. There
// the surface stresses are finite and follow from Hamilton's equations at r = a, z = 0 (S = A = 0, M = N = 0,
// phi = pi/2; Hamilton & Goodman 1966 for s_xx): s_xx = p0 [(1 - 2nu)/3 + (4 + nu) pi mu / 8],
// s_yy = p0 [-(1 - 2nu)/3 + 3 nu pi mu / 8], the rest zero. Reference: the larger of that closed form and a
// brute-force search of the closed form (0.01 a mesh, then 0.0002 a around its best point); the peak must be
// within 1e-4 of it (1 % was asked), and never below the grid's. At nu = 0.3 the edge holds the maximum for
// mu = 0.5 and 0.7 (the grid alone: 3.5 % and 0.75 % low); at 0.3 it lies below the surface, at 0.9 on the
// surface inside the contact (x = -0.34 a).
TEST(SubsurfaceStress, HamiltonPeakIncludesTheTrailingEdgeCusp)
{
  const double nu = 0.3;
  const std::vector<double> x = cell_centres(-1.5, 1.5, 64), z = uniform_points(0.0, 1.5, 64);
  for (double mu : {0.0, 0.3, 0.5, 0.7, 0.9}) {
    const SlidingHertzSphere c{1.0, 1.0, nu, mu};
    const double sxx = (1.0 - 2.0 * nu) / 3.0 + (4.0 + nu) * kPi * mu / 8.0;
    const double syy = -(1.0 - 2.0 * nu) / 3.0 + 3.0 * nu * kPi * mu / 8.0;
    const double edge = std::sqrt(sxx * sxx + syy * syy - sxx * syy);
    EXPECT_NEAR(hamilton_stress(c, -1.0, 0.0, 0.0).von_mises(), edge, 1e-6) << "mu " << mu;
    const double dense =
        dense_maximum([&](double px, double pz) { return hamilton_stress(c, px, 0.0, pz).von_mises(); }).von_mises;
    const double reference = std::max(edge, dense);
    const StressField field = hamilton_field(c, x, z);
    const StressPeak grid = field.peak_von_mises(), peak = hamilton_peak_von_mises(c, field);
    std::cout << "Hamilton nu = 0.3, mu = " << mu << ": trailing edge " << edge << " p0, dense search " << dense
              << " p0; grid peak " << grid.von_mises << " p0 (" << (grid.von_mises / reference - 1.0) * 100.0
              << " %), refined " << peak.von_mises << " p0 at (" << peak.x << ", " << peak.z << ") a ("
              << (peak.von_mises / reference - 1.0) * 100.0 << " %)\n";
    EXPECT_NEAR(peak.von_mises / reference, 1.0, 1e-4) << "mu " << mu;
    EXPECT_GE(peak.von_mises, grid.von_mises);
    if (mu == 0.5 || mu == 0.7) {    // the trailing-edge cusp
      EXPECT_GE(edge, dense);
      EXPECT_NEAR(peak.x, -1.0, 1e-6) << "mu " << mu;
      EXPECT_NEAR(peak.z, 0.0, 1e-12) << "mu " << mu;
    }
  }
}

// The same for McEwen's line contact: the refined peak against a brute-force search of the closed form.
TEST(SubsurfaceStress, McEwenPeakIsTheClosedFormMaximum)
{
  const double nu = 0.3;
  const std::vector<double> x = cell_centres(-1.5, 1.5, 48), z = uniform_points(0.0, 1.5, 48);
  for (double mu : {0.0, 0.3, 0.5, 0.7, 0.9}) {
    const SlidingHertzLine c{1.0, 1.0, nu, mu};
    const double dense = dense_maximum([&](double px, double pz) { return mcewen_stress(c, px, pz).von_mises(); }).von_mises;
    const StressField field = mcewen_field(c, x, z);
    const StressPeak grid = field.peak_von_mises(), peak = mcewen_peak_von_mises(c, field);
    std::cout << "McEwen nu = 0.3, mu = " << mu << ": dense search " << dense << " p0; grid peak " << grid.von_mises
              << " p0 (" << (grid.von_mises / dense - 1.0) * 100.0 << " %), refined " << peak.von_mises << " p0 at ("
              << peak.x << ", " << peak.z << ") b (" << (peak.von_mises / dense - 1.0) * 100.0 << " %)\n";
    EXPECT_NEAR(peak.von_mises / dense, 1.0, 1e-4) << "mu " << mu;
    EXPECT_GE(peak.von_mises, grid.von_mises);
  }
}

// Verification item 3: the influence-function tier on the Hertz pressure against Hamilton, within 2 % of p0,
// for every component on a section through the contact and for the peak von Mises stress and its place. The
// exception is the surface within one patch of the contact edge, where the 64 piecewise-constant patches cannot
// follow the square-root edge of the Hertz pressure (up to 5 % of p0 there; doc/subsurface_stress.md).
TEST(SubsurfaceStress, PatchIntegrationMatchesHamilton)
{
  for (double mu : {0.0, 0.3}) {
    const double nu = 0.3;
    const SlidingHertzSphere c{1.0, 1.0, nu, mu};
    const PatchTraction t = axisymmetric_patches(hertz_p, 1.0, mu, 1.5, 64);
    const std::vector<double> x = cell_centres(-1.5, 1.5, 64), z = uniform_points(0.0, 1.5, 32);
    const StressField f = patch_traction_field(t, nu, x, z);
    double worst = 0.0;
    for (std::size_t k = 0; k < z.size(); ++k)
      for (std::size_t i = 0; i < x.size(); ++i) {
        if (z[k] == 0.0 && std::abs(std::abs(x[i]) - 1.0) < 0.1) continue;
        worst = std::max(worst, max_component_difference(f.stress[i + x.size() * k], hamilton_stress(c, x[i], 0.0, z[k])));
      }
    EXPECT_LT(worst, 0.02) << "mu " << mu;
    const StressPeak pi = f.peak_von_mises(), ph = hamilton_field(c, x, z).peak_von_mises();
    std::cout << "3-D tier, 64 x 64 patches, mu = " << mu << ": largest component error " << worst
              << " p0; peak von Mises " << pi.von_mises << " p0 at (" << pi.x << ", " << pi.z << ") vs Hamilton "
              << ph.von_mises << " p0 at (" << ph.x << ", " << ph.z << ")\n";
    EXPECT_NEAR(pi.von_mises, ph.von_mises, 0.02 * ph.von_mises) << "mu " << mu;
    EXPECT_NEAR(pi.z, ph.z, 0.05) << "mu " << mu;
    // Off the section and at arbitrary points (generic, non-Toeplitz path).
    for (const auto &pt : std::vector<std::array<double, 3>>{{0.31, 0.27, 0.3}, {-0.77, 0.13, 0.07}, {1.3, 0.4, 0.2}})
      EXPECT_LT(max_component_difference(patch_traction_stress(t, nu, pt[0], pt[1], pt[2]),
                                         hamilton_stress(c, pt[0], pt[1], pt[2])),
                0.02);
  }
}

// Grid convergence of the 3-D tier: the error of the peak von Mises stress falls with the patch count.
TEST(SubsurfaceStress, PatchIntegrationConverges)
{
  const SlidingHertzSphere c{1.0, 1.0, 0.3, 0.0};
  const std::vector<double> z = uniform_points(0.3, 0.7, 41);
  std::vector<double> error;
  for (int n : {9, 17, 33, 65}) {
    const PatchTraction t = axisymmetric_patches(hertz_p, 1.0, 0.0, 1.0, n);
    const StressField f = patch_traction_field(t, 0.3, {0.0}, z);
    const StressField h = hamilton_field(c, {0.0}, z);
    error.push_back(std::abs(f.peak_von_mises().von_mises - h.peak_von_mises().von_mises));
  }
  std::cout << "3-D tier, peak von Mises error on the axis for n = 9, 17, 33, 65 patches:";
  for (double e : error) std::cout << " " << e;
  std::cout << " p0\n";
  for (std::size_t i = 1; i < error.size(); ++i) EXPECT_LT(error[i], error[i - 1]);
  EXPECT_LT(error.back(), 0.005 * 0.62);
}

// Surface equilibrium of the influence tiers: at a patch / strip centre sigma_zz = -p and sigma_xz = -q exactly
// (piecewise-constant traction).
TEST(SubsurfaceStress, InfluenceTiersCarryTheSurfaceTraction)
{
  const PatchTraction t = axisymmetric_patches(hertz_p, 1.0, 0.4, 1.2, 24);
  const std::vector<double> x = cell_centres(-1.2, 1.2, 24);
  const StressField f = patch_traction_field(t, 0.3, x, {0.0});
  for (int i = 0; i < 24; ++i) {
    const double p = t.pressure[i + 24 * 12];    // the row y in [0, dy]: centre y = dy / 2
    const StressTensor s = patch_traction_stress(t, 0.3, x[i], 0.05, 0.0);
    EXPECT_NEAR(s.zz, -p, 1e-9) << i;
    EXPECT_NEAR(s.xz, -0.4 * p, 1e-9) << i;
    EXPECT_TRUE(std::isfinite(f.stress[i].von_mises())) << i;
  }
  std::vector<double> nodes, p, q;
  for (int j = 0; j < 40; ++j) {
    nodes.push_back(-1.0 + (j + 0.5) / 20.0);
    p.push_back(hertz_p(nodes.back()));
    q.push_back(-0.2 * p.back());
  }
  const LineTraction lt = LineTraction::from_nodes(nodes, p, q);
  const StressField lf = line_traction_field(lt, 0.3, nodes, {0.0});
  for (int j = 0; j < 40; ++j) {
    EXPECT_NEAR(lf.stress[j].zz, -p[j], 1e-9);
    EXPECT_NEAR(lf.stress[j].xz, -q[j], 1e-9);
  }
}

// Line contact. Johnson (1985) §4.2 (eq. 4.50 on the axis): frictionless, nu = 0.3, the largest shear stress is
// tau_1 = 0.30 p0 at z = 0.78 b and the largest von Mises stress 0.557 p0 at z = 0.70 b (from eq. 4.50, coded
// above). McEwen and the Flamant strip integration (512 nodes) are checked against them, and against each other
// at mu = 0 and 0.3 (2 % of p0).
TEST(SubsurfaceStress, LineContactMatchesJohnsonAndMcEwen)
{
  const double nu = 0.3;
  const auto [zt, tau] = maximise([&](double z) { return 0.5 * johnson_line_axis(z, nu).tresca(); }, 0.1, 2.0);
  std::cout << "Johnson 4.50, nu = 0.3: tau_1 max " << tau << " p0 at z = " << zt << " b\n";
  EXPECT_NEAR(tau, 0.30, 0.01 * 0.30);
  EXPECT_NEAR(zt, 0.78, 0.01 * 0.78);
  const auto [zv, vm] = maximise([&](double z) { return johnson_line_axis(z, nu).von_mises(); }, 0.1, 2.0);
  std::cout << "Johnson 4.50, nu = 0.3: von Mises max " << vm << " p0 at z = " << zv << " b\n";
  EXPECT_NEAR(vm, 0.557, 0.01 * 0.557);
  EXPECT_NEAR(zv, 0.70, 0.01 * 0.70);

  std::vector<double> nodes;
  for (int j = 0; j < 512; ++j) nodes.push_back(-1.0 + (j + 0.5) / 256.0);
  for (double mu : {0.0, 0.3}) {
    std::vector<double> p, q;
    for (double x : nodes) p.push_back(hertz_p(std::abs(x))), q.push_back(mu * p.back());
    const LineTraction lt = LineTraction::from_nodes(nodes, p, q);
    const SlidingHertzLine c{1.0, 1.0, nu, mu};
    for (double z : {0.1, 0.5, 0.7, 1.5}) {
      if (mu == 0.0) EXPECT_LT(max_component_difference(mcewen_stress(c, 0.0, z), johnson_line_axis(z, nu)), 1e-9);
      for (double x : {-1.4, -0.77, -0.2, 0.33, 0.9, 2.0})
        EXPECT_LT(max_component_difference(line_traction_stress(lt, nu, x, z), mcewen_stress(c, x, z)), 0.02)
            << "mu " << mu << " x " << x << " z " << z;
    }
    const std::vector<double> x = cell_centres(-2.0, 2.0, 64), z = uniform_points(0.0, 2.0, 64);
    const StressPeak pi = line_traction_field(lt, nu, x, z).peak_von_mises();
    const StressPeak pm = mcewen_field(c, x, z).peak_von_mises();
    std::cout << "2-D tier, 512 strips, mu = " << mu << ": peak von Mises " << pi.von_mises << " p0 at (" << pi.x
              << ", " << pi.z << ") vs McEwen " << pm.von_mises << " p0 at (" << pm.x << ", " << pm.z << ")\n";
    EXPECT_NEAR(pi.von_mises, pm.von_mises, 0.02 * pm.von_mises) << "mu " << mu;
    if (mu == 0.0) EXPECT_NEAR(pm.von_mises, vm, 0.01 * vm);
  }
}

TEST(SubsurfaceStress, LineIntegrationConverges)
{
  const SlidingHertzLine c{1.0, 1.0, 0.3, 0.0};
  std::vector<double> error;
  for (int n : {16, 64, 256}) {
    std::vector<double> nodes, p;
    for (int j = 0; j < n; ++j) nodes.push_back(-1.0 + (j + 0.5) * 2.0 / n), p.push_back(hertz_p(std::abs(nodes.back())));
    const LineTraction lt = LineTraction::from_nodes(nodes, p);
    error.push_back(max_component_difference(line_traction_stress(lt, 0.3, 0.1, 0.7), mcewen_stress(c, 0.1, 0.7)));
  }
  EXPECT_LT(error[1], error[0]);
  EXPECT_LT(error[2], error[1]);
}

TEST(SubsurfaceStress, BadInputThrowsWithTheFieldNamed)
{
  auto throws_with = [](const std::function<void()> &f, const std::string &text) {
    try {
      f();
    } catch (const InvalidCoefficient &e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "no InvalidCoefficient for " << text;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  throws_with([] { hamilton_stress({1.0, -1.0, 0.3, 0.0}, 0, 0, 1); }, "contact radius a");
  throws_with([] { hamilton_stress({1.0, 1.0, 0.6, 0.0}, 0, 0, 1); }, "Poisson ratio");
  throws_with([] { hamilton_stress({1.0, 1.0, -1.0, 0.0}, 0, 0, 1); }, "Poisson ratio");
  throws_with([nan] { hamilton_stress({nan, 1.0, 0.3, 0.0}, 0, 0, 1); }, "peak pressure");
  throws_with([nan] { hamilton_stress({1.0, 1.0, 0.3, nan}, 0, 0, 1); }, "friction coefficient");
  throws_with([] { hamilton_stress({1.0, 1.0, 0.3, 0.0}, 0, 0, -1); }, "depth z");
  throws_with([] { mcewen_stress({1.0, 0.0, 0.3, 0.0}, 0, 1); }, "half-width");
  throws_with([] { hertz_axis_stress(1.0, 1.0, 0.7, 1.0); }, "Poisson ratio");
  throws_with([] { line_traction_stress({{0.0, 1.0}, {1.0, 2.0}, {}}, 0.3, 0, 1); }, "edges");
  throws_with([] { line_traction_stress({{0.0, 1.0, 0.5}, {1.0, 2.0}, {}}, 0.3, 0, 1); }, "increase");
  throws_with([] { patch_traction_stress({0, 0, 1, 1, 2, 2, {1, 2, 3}, {}}, 0.3, 0, 0, 1); }, "patch pressures");
  throws_with([nan] { patch_traction_stress({0, 0, 1, 1, 1, 1, {nan}, {}}, 0.3, 0, 0, 1); }, "patch pressure");
  throws_with([] { axisymmetric_patches(hertz_p, 1.0, 0.0, 0.5, 16); }, "cover the contact radius");
  // nu = 0.5 is allowed (incompressible).
  EXPECT_NO_THROW(hamilton_stress({1.0, 1.0, 0.5, 0.3}, 0.2, 0.1, 0.3));
}
