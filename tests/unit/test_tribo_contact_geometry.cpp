// The kinematics of a contact shared by the hosts (sphere_sphere_geometry, sphere_flat_geometry) against the
// closed forms: unit normal towards i, R* = r_i r_j / (r_i + r_j), m* = m_i m_j / (m_i + m_j), and the velocity of
// i at the contact point relative to the counter-body, v_r - (v_r . n) n + n x (r_i w_i + r_j w_j).
#include "tribo/contact_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

TEST(ContactGeometry, SphereSphereMatchesClosedForms)
{
  const double del[3] = {0.3e-6, -0.4e-6, 1.2e-6};    // x_i - x_j, |del| = 1.3 um
  const double r = 1.3e-6, ri = 1.0e-6, rj = 0.8e-6, mi = 3.0e-14, mj = 5.0e-14;
  const double vi[3] = {1.0, 0.2, -0.5}, vj[3] = {-0.3, 0.1, 0.4}, wi[3] = {1e5, -2e5, 3e4}, wj[3] = {-4e4, 5e4, 1e5};
  const ContactGeometry g = sphere_sphere_geometry(ri + rj - r, 1.0 / r, del, 0.1e-6, ri, rj, mi, mj, vi, vj, wi, wj);
  const double n[3] = {del[0] / r, del[1] / r, del[2] / r};
  for (int k = 0; k < 3; k++) EXPECT_NEAR(g.normal[k], n[k], 1e-15);
  EXPECT_NEAR(g.effective_radius, ri * rj / (ri + rj), 1e-15 * ri);
  EXPECT_NEAR(g.effective_mass, mi * mj / (mi + mj), 1e-15 * mi);
  EXPECT_EQ(g.overlap, ri + rj - r);
  EXPECT_EQ(g.flat_radius, 0.1e-6);
  const double vr[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
  const double vn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
  EXPECT_NEAR(g.normal_velocity, vn, 1e-15);
  const double s[3] = {ri * wi[0] + rj * wj[0], ri * wi[1] + rj * wj[1], ri * wi[2] + rj * wj[2]};
  const double roll[3] = {n[1] * s[2] - n[2] * s[1], n[2] * s[0] - n[0] * s[2], n[0] * s[1] - n[1] * s[0]};
  for (int k = 0; k < 3; k++) EXPECT_NEAR(g.tangential_velocity[k], vr[k] - vn * n[k] + roll[k], 1e-14) << k;
  // the rolling part is tangential: v_t . n = 0
  double vt_n = 0.0;
  for (int k = 0; k < 3; k++) vt_n += g.tangential_velocity[k] * n[k];
  EXPECT_NEAR(vt_n, 0.0, 1e-14);
}

TEST(ContactGeometry, SphereFlatIsTheSphereOnAnInfiniteCounterBody)
{
  const double n[3] = {0.0, 0.0, 1.0}, v[3] = {0.5, -0.2, -0.1}, wall[3] = {1.0, 0.0, 0.0}, w[3] = {2e5, 1e5, -3e5};
  const double r = 1.5e-6, m = 4.0e-14;
  const ContactGeometry g = sphere_flat_geometry(2e-8, n, 0.0, r, m, v, wall, w);
  EXPECT_EQ(g.effective_radius, r);
  EXPECT_EQ(g.effective_mass, m);
  EXPECT_EQ(g.normal_velocity, -0.1);
  // v_r = (-0.5, -0.2, -0.1); n x (r w) = (-r w_y, r w_x, 0)
  EXPECT_NEAR(g.tangential_velocity[0], -0.5 - r * w[1], 1e-15);
  EXPECT_NEAR(g.tangential_velocity[1], -0.2 + r * w[0], 1e-15);
  EXPECT_EQ(g.tangential_velocity[2], 0.0);
  // the limit of two spheres with r_j -> infinity and m_j -> infinity (a heavy, large counter-body, not spinning)
  const double del[3] = {0.0, 0.0, 1.0e3}, no_spin[3] = {0.0, 0.0, 0.0};
  const ContactGeometry s =
      sphere_sphere_geometry(2e-8, 1.0e-3, del, 0.0, r, 1.0e3 - r + 2e-8, m, 1.0e10, v, wall, w, no_spin);
  EXPECT_NEAR(s.effective_radius, r, 1e-8 * r);
  EXPECT_NEAR(s.effective_mass, m, 1e-8 * m);
  for (int k = 0; k < 3; k++) EXPECT_NEAR(s.tangential_velocity[k], g.tangential_velocity[k], 1e-12) << k;
}
