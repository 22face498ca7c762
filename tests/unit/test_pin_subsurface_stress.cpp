// The pin-on-disk subsurface stress report (continuum/pin_on_disk.h: hertz_contact_stress, ring_contact_stress;
// doc/subsurface_stress.md): the influence tier on the ring pressure that AxisymmetricContact solves for the
// unworn tip against Hamilton's closed form on the Hertz pressure, and the yield verdict.
#include "continuum/axisymmetric_contact.h"
#include "continuum/pin_on_disk.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <tuple>
#include <vector>

using namespace runin;

namespace {

struct ThesisPair {
  tribo::Material pin, disk;
  ThesisPair()
  {
    pin.youngs_modulus = 110e9, pin.poisson_ratio = 0.37, pin.hardness = 0.87e9, pin.yield_strength = 250e6;
    disk.youngs_modulus = 69e9, disk.poisson_ratio = 0.33, disk.hardness = 0.245e9, disk.yield_strength = 34e6;
  }
};

}  // namespace

// Thesis set-up (Cu pin R = 5 mm on Al disk, W = 0.981 N): the solved pressure of 256 rings through the
// influence tier gives the closed form's peak von Mises stress of both bodies within 1 % at mu = 0, 0.3 and the
// thesis's 0.95 (measured: 0.16 % or better; at 0.95 the peak is on the surface inside the contact).
TEST(PinSubsurfaceStress, RingPressureMatchesHertzClosedForm)
{
  const ThesisPair m;
  const double E = tribo::effective_modulus(m.pin, m.disk), R = 5e-3, W = 0.981;
  const auto h = continuum::hertz_sphere_on_flat(R, E, W);
  continuum::AxisymmetricContact contact(1.5 * h.contact_radius, 256, E);
  std::vector<double> gap(256);
  for (int i = 0; i < 256; ++i) gap[i] = std::pow(contact.ring_radius(i), 2) / (2.0 * R);
  const auto solution = contact.solve(gap, W);
  ASSERT_TRUE(solution.converged);
  for (double mu : {0.0, 0.3, 0.95}) {
    const auto closed = continuum::hertz_contact_stress(h.peak_pressure, h.contact_radius, mu, m.pin, m.disk);
    const auto ring = continuum::ring_contact_stress(solution.pressure, contact.ring_width(), mu, m.pin, m.disk);
    const double tolerance = 0.01;
    for (const auto &[a, b] : {std::make_pair(&closed.disk, &ring.disk), std::make_pair(&closed.pin, &ring.pin)}) {
      std::cout << "mu " << mu << ": closed " << a->peak.von_mises << " Pa at (" << a->peak.x << ", " << a->peak.z
                << "), ring " << b->peak.von_mises << " Pa at (" << b->peak.x << ", " << b->peak.z << ")\n";
      EXPECT_NEAR(b->peak.von_mises / a->peak.von_mises, 1.0, tolerance) << "mu " << mu;
    }
    // The pin carries the opposite shear: its field is the mirror image (x -> -x) with its own nu.
    if (mu > 0.0) EXPECT_LT(closed.disk.peak.x * closed.pin.peak.x, 0.0);
  }
}

// The reported peak (and so the yield verdict) is the closed form's maximum: for mu = 0.3-0.7 it is the cusp on the
// surface at the disk's trailing edge (x = -a, z = 0; the pin's is at x = +a), between the points of the 64 x 64
// grid that alone reported it up to 3.3 % low. Reference: Hamilton's surface stresses at the edge (derived in
// test_tribo_subsurface_stress.cpp) and a brute-force search of the closed form (0.01 a mesh, then 0.0002 a around
// its best point); within 1 %.
TEST(PinSubsurfaceStress, PeakIsTheClosedFormMaximum)
{
  const ThesisPair m;
  const double a = 4.243e-5, p0 = 2.602e8;
  for (double mu : {0.3, 0.5, 0.7}) {
    const auto closed = continuum::hertz_contact_stress(p0, a, mu, m.pin, m.disk);
    for (const auto &[body, nu, sign] : {std::make_tuple(&closed.disk, m.disk.poisson_ratio, 1.0),
                                         std::make_tuple(&closed.pin, m.pin.poisson_ratio, -1.0)}) {
      const tribo::SlidingHertzSphere c{p0, a, nu, sign * mu};
      const double sxx = (1.0 - 2.0 * nu) / 3.0 + (4.0 + nu) * 3.14159265358979323846 * mu / 8.0;
      const double syy = -(1.0 - 2.0 * nu) / 3.0 + 3.0 * nu * 3.14159265358979323846 * mu / 8.0;
      const double edge = p0 * std::sqrt(sxx * sxx + syy * syy - sxx * syy);
      auto vm = [&](double x, double z) { return tribo::hamilton_stress(c, a * x, 0.0, a * z).von_mises(); };
      double dense = 0.0, best_x = 0.0, best_z = 0.0;
      for (int i = 0; i <= 300; ++i)
        for (int k = 0; k <= 150; ++k)
          if (const double v = vm(-1.5 + 0.01 * i, 0.01 * k); v > dense) dense = v, best_x = -1.5 + 0.01 * i, best_z = 0.01 * k;
      const double cx = best_x, cz = best_z;
      for (int i = -100; i <= 100; ++i)
        for (int k = -100; k <= 100; ++k)
          if (cz + 0.0002 * k >= 0.0) dense = std::max(dense, vm(cx + 0.0002 * i, cz + 0.0002 * k));
      const double reference = std::max(edge, dense);
      const double grid = body->field.peak_von_mises().von_mises;
      std::cout << "mu " << mu << ", nu " << nu << ": reported " << body->peak.von_mises << " Pa at (" << body->peak.x / a
                << ", " << body->peak.z / a << ") a, closed-form maximum " << reference << " Pa ("
                << (body->peak.von_mises / reference - 1.0) * 100.0 << " %); the grid's " << grid << " Pa ("
                << (grid / reference - 1.0) * 100.0 << " %)\n";
      EXPECT_NEAR(body->peak.von_mises / reference, 1.0, 0.01) << "mu " << mu << " nu " << nu;
      if (edge >= dense) EXPECT_NEAR(body->peak.x, -sign * a, 1e-6 * a) << "mu " << mu << " nu " << nu;
    }
  }
}

TEST(PinSubsurfaceStress, YieldVerdict)
{
  const ThesisPair m;
  const auto hertz = continuum::hertz_sphere_on_flat(5e-3, tribo::effective_modulus(m.pin, m.disk), 0.981);
  // Frictionless: 0.6 p0 = 157 MPa > 34 MPa (Al) but < 250 MPa (Cu).
  const auto free = continuum::hertz_contact_stress(hertz.peak_pressure, hertz.contact_radius, 0.0, m.pin, m.disk);
  EXPECT_TRUE(free.disk.yields());
  EXPECT_FALSE(free.pin.yields());
  EXPECT_NEAR(free.disk.peak.z / hertz.contact_radius, 0.48, 0.03);
  tribo::Material unknown = m.disk;
  unknown.yield_strength = 0.0;
  EXPECT_FALSE(continuum::hertz_contact_stress(hertz.peak_pressure, hertz.contact_radius, 0.0, m.pin, unknown)
                   .disk.yields());
}
