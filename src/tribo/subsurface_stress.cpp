#include "tribo/subsurface_stress.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace runin::tribo {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string fmt(double v)
{
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void require_finite(double v, const std::string &name)
{
  if (!std::isfinite(v)) throw InvalidCoefficient("subsurface stress: " + name + " must be finite, got " + fmt(v));
}

void require_poisson(double nu)
{
  require_finite(nu, "Poisson ratio nu");
  if (!(nu > -1.0 && nu <= 0.5))
    throw InvalidCoefficient("subsurface stress: Poisson ratio nu must lie in (-1, 0.5], got " + fmt(nu));
}

void require_point(double x, double y, double z)
{
  require_finite(x, "x");
  require_finite(y, "y");
  require_finite(z, "depth z");
  if (z < 0.0) throw InvalidCoefficient("subsurface stress: depth z must be >= 0 (the body is z >= 0), got " + fmt(z));
}

void require_grid(const std::vector<double> &v, const std::string &name)
{
  if (v.empty()) throw InvalidCoefficient("subsurface stress: the " + name + " grid is empty");
  for (double a : v) require_finite(a, name + " grid value");
}

// ---- Hamilton (1983), lengths in units of a, stresses in units of p0 (normal) and mu p0 (tangential).

// On the axis r = 0.
void hamilton_axis(double z, double nu, StressTensor &normal, StressTensor &tangential)
{
  const double at = std::atan2(1.0, z);    // atan(1/z), pi/2 at z = 0
  normal = {};
  normal.xx = normal.yy = (1.0 + nu) * (z * at - 1.0) + 0.5 / (1.0 + z * z);
  normal.zz = -1.0 / (1.0 + z * z);
  tangential = {};
  tangential.xz = -1.0 + 1.5 * z * at - 0.5 * z * z / (1.0 + z * z);
}

// Off the axis (r > 0), Hamilton's explicit equations for P (normal) and Q (tangential, +x).
void hamilton_off_axis(double x, double y, double z, double nu, StressTensor &normal, StressTensor &tangential)
{
  const double x2 = x * x, y2 = y * y, z2 = z * z;
  const double r2 = x2 + y2, r4 = r2 * r2;
  const double A = r2 + z2 - 1.0;
  double S = std::sqrt(A * A + 4.0 * z2);
  if (!(S > 1e-300)) S = 1e-300;    // only at z = 0, r = a (the contact edge); every term there is finite
  const double M = std::sqrt(std::max(0.5 * (S + A), 0.0));
  const double N = std::sqrt(std::max(0.5 * (S - A), 0.0));
  const double phi = std::atan2(1.0, M);
  const double G = M * M - N * N + z * M - N;
  const double H = 2.0 * M * N + M + z * N;
  const double GH = G * G + H * H;
  const double c12 = 1.0 - 2.0 * nu;

  // Normal load.
  const double common = (1.0 - nu) * N * z2 - c12 / 3.0 * (N * S + 2.0 * A * N + 1.0) - nu * M * z;
  normal.xx = (1.0 + nu) * z * phi + ((y2 - x2) / r2 * common - N * (x2 + 2.0 * nu * y2) - M * x2 * z / S) / r2;
  normal.yy = (1.0 + nu) * z * phi + ((x2 - y2) / r2 * common - N * (y2 + 2.0 * nu * x2) - M * y2 * z / S) / r2;
  normal.zz = -N + z * M / S;
  normal.xy = x * y * c12 / r4 * (-N * r2 + 2.0 / 3.0 * N * (S + 2.0 * A) - z * (z * N + M) + 2.0 / 3.0) +
              x * y * z / r4 * (-M * r2 / S - z * N + M);
  normal.yz = -z * (y * N / S - y * z * H / GH);
  normal.xz = -z * (x * N / S - x * z * H / GH);

  // Tangential load.
  const double fx = 1.5 - 2.0 * x2 / r2;       // (3/2 - 2 x^2 / r^2)
  const double hx = 0.5 - 2.0 * x2 / r2;       // (1/2 - 2 x^2 / r^2)
  const double hy = 0.5 - 2.0 * y2 / r2;       // (1/2 - 2 y^2 / r^2)
  const double sa = S / 6.0 * c12 + A / 3.0 * c12;
  tangential.xx = -x * (nu / 4.0 + 1.0) * phi +
                  x * M / r4 *
                      (fx * (S * nu - 2.0 * A * nu + z2) + x2 * z2 / S + 7.0 * nu * r2 / 4.0 - 2.0 * nu * x2 + r2) +
                  x * z * N / r4 * (fx * (-sa - 0.5 * (z2 + 3.0)) + x2 / S - nu * r2 / 4.0 - 7.0 * r2 / 4.0) +
                  4.0 * x * z / (3.0 * r4) * fx * c12;
  tangential.yy = -0.75 * nu * x * phi +
                  x * M / r4 * (hy * (nu * (S - 2.0 * A + r2) + z2) + y2 * z2 / S + 0.75 * nu * r2) +
                  z * x * N / r4 * (hy * (-sa - 0.5 * z2 - 1.5) + y2 / S - 0.75 * nu * r2 - 0.25 * r2) +
                  4.0 / 3.0 * z * x / r4 * hy * c12;
  tangential.zz = z * x * N / (2.0 * r2) * (1.0 - (r2 + z2 + 1.0) / S);
  tangential.xy =
      0.5 * y * (0.5 * nu - 1.0) * phi +
      y * M / r4 * (x2 * z2 / S + nu * ((S - 2.0 * A) * hx - 2.0 * x2 + 0.25 * r2) + 0.5 * r2 + z2 * hx) +
      y * z * N / r4 * (hx * (-sa - 0.5 * z2 - 1.5 - 0.5 * r2) + 0.25 * r2 * nu + x2 / S - 0.5 * y2 - 1.5 * x2) +
      4.0 * y * z / (3.0 * r4) * hx * c12;
  tangential.yz = x * y * z / (2.0 * r4) *
                  (M * (0.5 + (0.5 * z2 - 1.5 - 0.5 * r2) / S) + 0.5 * z * N * (-3.0 + (5.0 + z2 + r2) / S));
  tangential.xz = 1.5 * z * phi + z * M / r2 * (1.0 + x2 / r2 - x2 / S) +
                  N / r2 * (-0.75 * (S + 2.0 * A) + z2 - 0.75 - 0.25 * r2 + 0.5 * z2 * hx);
}

StressTensor lerp(const StressTensor &a, const StressTensor &b, double t)
{
  StressTensor s = a.scaled(1.0 - t);
  s += b.scaled(t);
  return s;
}

// ---- Boussinesq / Cerruti corner functions (doc/subsurface_stress.md): the stress of a uniform unit traction
// on a rectangle is sum over its corners of +-K(X, Y, z) / (2 pi), X = x - xi_c, Y = y - eta_c.

struct CornerPair {
  StressTensor normal, shear;
};

// Y + rho without cancellation for Y < 0.
inline double plus_rho(double Y, double rho, double xz2) { return Y >= 0.0 ? Y + rho : xz2 / (rho - Y); }

inline CornerPair corner(double X, double Y, double z, double nu, bool with_shear)
{
  CornerPair k;
  const double X2 = X * X, Y2 = Y * Y, z2 = z * z;
  const double rho = std::sqrt(X2 + Y2 + z2);
  const double xz2 = X2 + z2, yz2 = Y2 + z2;
  const double ypr = plus_rho(Y, rho, xz2), xpr = plus_rho(X, rho, yz2);
  const double T = std::atan2(X * Y, z * rho);
  const double rmz = (X2 + Y2) / (rho + z);    // rho - z
  const double Ax = std::atan2(X * Y * rmz, X2 * rho + Y2 * z);
  const double Ay = std::atan2(X * Y * rmz, Y2 * rho + X2 * z);
  const double c12 = 1.0 - 2.0 * nu;
  const bool surface = !(z > 0.0);    // every z-multiplied term vanishes there
  const double zx = surface ? 0.0 : z * X / (rho * ypr);             // z X / (rho (Y + rho))
  const double zy = surface ? 0.0 : z * Y / (rho * xpr);             // z Y / (rho (X + rho))
  const double zzy = surface ? 0.0 : z2 / (rho * ypr);               // z^2 / (rho (Y + rho))
  const double zzx = surface ? 0.0 : z2 / (rho * xpr);               // z^2 / (rho (X + rho))
  const double zq = surface ? 0.0 : z * X * Y * (rho * rho + z2) / (rho * xz2 * yz2);
  k.normal.xx = -2.0 * nu * T - zx - c12 * Ax;
  k.normal.yy = -2.0 * nu * T - zy - c12 * Ay;
  k.normal.zz = -T - zq;
  k.normal.yz = -zzx;
  k.normal.xz = -zzy;
  k.normal.xy = -(c12 * std::log(rho + z) + (surface ? 0.0 : z / rho));
  if (with_shear) {
    const double LY = std::log(ypr), LX = std::log(xpr);
    const double zyr = surface ? 0.0 : z * Y / (rho * (rho + z));
    const double zxr = surface ? 0.0 : z * X / (rho * (rho + z));
    k.shear.xx = 2.0 * LY + zyr + zzy + 2.0 * nu * Y / (rho + z);
    k.shear.yy = 2.0 * nu * LY - zyr - 2.0 * nu * Y / (rho + z);
    k.shear.zz = -zzy;
    k.shear.yz = surface ? 0.0 : -z / rho;
    k.shear.xz = -T - zx;
    k.shear.xy = LX - zxr - 2.0 * nu * X / (rho + z);
  }
  return k;
}

inline void accumulate(StressTensor &s, const StressTensor &k, double w)
{
  s.xx += w * k.xx, s.yy += w * k.yy, s.zz += w * k.zz, s.yz += w * k.yz, s.xz += w * k.xz, s.xy += w * k.xy;
}

// Mixed second differences of the patch values at the (nx + 1) x (ny + 1) corners (zero outside the grid).
std::vector<double> corner_weights(const std::vector<double> &v, int nx, int ny)
{
  std::vector<double> w(static_cast<std::size_t>((nx + 1) * (ny + 1)), 0.0);
  if (v.empty()) return w;
  auto at = [&](int i, int j) { return (i < 0 || j < 0 || i >= nx || j >= ny) ? 0.0 : v[i + nx * j]; };
  double largest = 0.0;
  for (double a : v) largest = std::max(largest, std::abs(a));
  // Rounding leaves ~1e-16 weights on lines where the traction is smooth by symmetry (the axis of an
  // axisymmetric load); zero them, a corner function may be singular exactly there.
  const double tiny = 1e-12 * largest;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const double d = at(i, j) - at(i - 1, j) - at(i, j - 1) + at(i - 1, j - 1);
      w[i + (nx + 1) * j] = std::abs(d) > tiny ? d : 0.0;
    }
  return w;
}

// ---- Flamant strip corner functions: the stress of a unit traction on [xi, inf) is -(2/pi) K(x - xi, z).
struct LineCorner {
  double nxx, nzz, nxz, txx, tzz, txz;
};
inline LineCorner line_corner(double X, double z, double r2_floor, bool with_shear)
{
  const double r2 = std::max(X * X + z * z, r2_floor);
  const double th = std::atan2(X, z);
  const double xz = X * z / r2, zz = z * z / r2;
  const double log_r = with_shear ? 0.5 * std::log(r2) : 0.0;
  return {0.5 * (th - xz), 0.5 * (th + xz), -0.5 * zz, log_r + 0.5 * zz, -0.5 * zz, 0.5 * (th - xz)};
}

}  // namespace

// ---------------------------------------------------------------- StressTensor

double StressTensor::von_mises() const
{
  const double a = xx - yy, b = yy - zz, c = zz - xx;
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (xy * xy + yz * yz + xz * xz));
}

std::array<double, 3> StressTensor::principal() const
{
  Eigen::Matrix3d m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d e = solver.eigenvalues();    // ascending
  return {e[2], e[1], e[0]};
}

double StressTensor::tresca() const
{
  const auto p = principal();
  return p[0] - p[2];
}

// ---------------------------------------------------------------- closed forms

void SlidingHertzSphere::validate() const
{
  require_finite(peak_pressure, "peak pressure p0");
  require_finite(contact_radius, "contact radius a");
  require_finite(friction_coefficient, "friction coefficient mu");
  if (peak_pressure < 0.0)
    throw InvalidCoefficient("subsurface stress: peak pressure p0 must be >= 0, got " + fmt(peak_pressure));
  if (!(contact_radius > 0.0))
    throw InvalidCoefficient("subsurface stress: contact radius a must be > 0, got " + fmt(contact_radius));
  require_poisson(poisson_ratio);
}

StressTensor hamilton_stress(const SlidingHertzSphere &c, double x, double y, double z)
{
  c.validate();
  require_point(x, y, z);
  const double a = c.contact_radius;
  const double X = x / a, Y = y / a, Z = z / a, r = std::hypot(X, Y);
  constexpr double kAxis = 1e-2;    // below: interpolate (the 1/r^4 terms cancel to eps / r^4)
  StressTensor n, t;
  if (r >= kAxis) {
    hamilton_off_axis(X, Y, Z, c.poisson_ratio, n, t);
  } else {
    StressTensor n0, t0;
    hamilton_axis(Z, c.poisson_ratio, n0, t0);
    if (r > 0.0) {
      StressTensor n1, t1;
      hamilton_off_axis(X * kAxis / r, Y * kAxis / r, Z, c.poisson_ratio, n1, t1);
      n = lerp(n0, n1, r / kAxis);
      t = lerp(t0, t1, r / kAxis);
    } else {
      n = n0, t = t0;
    }
  }
  StressTensor s = n.scaled(c.peak_pressure);
  s += t.scaled(c.friction_coefficient * c.peak_pressure);
  return s;
}

AxisStress hertz_axis_stress(double p0, double a, double nu, double z)
{
  SlidingHertzSphere{p0, a, nu, 0.0}.validate();
  require_point(0.0, 0.0, z);
  // Johnson (1985) eq. 3.45: sigma_r = sigma_theta = -p0 (1 + nu) (1 - (z/a) atan(a/z)) + p0 / (2 (1 + z^2/a^2)),
  // sigma_z = -p0 (1 + z^2/a^2)^-1.
  const double q = z / a;
  const double radial = -p0 * (1.0 + nu) * (1.0 - q * std::atan2(1.0, q)) + 0.5 * p0 / (1.0 + q * q);
  return {radial, -p0 / (1.0 + q * q)};
}

void SlidingHertzLine::validate() const
{
  require_finite(peak_pressure, "peak pressure p0");
  require_finite(half_width, "half-width b");
  require_finite(friction_coefficient, "friction coefficient mu");
  if (peak_pressure < 0.0)
    throw InvalidCoefficient("subsurface stress: peak pressure p0 must be >= 0, got " + fmt(peak_pressure));
  if (!(half_width > 0.0)) throw InvalidCoefficient("subsurface stress: half-width b must be > 0, got " + fmt(half_width));
  require_poisson(poisson_ratio);
}

StressTensor mcewen_stress(const SlidingHertzLine &c, double x, double z)
{
  c.validate();
  require_point(x, 0.0, z);
  const double X = x / c.half_width, Z = z / c.half_width;
  const double k = 1.0 - X * X + Z * Z;
  double D = std::sqrt(k * k + 4.0 * X * X * Z * Z);    // m^2 + n^2
  if (!(D > 1e-300)) D = 1e-300;                        // z = 0, |x| = b
  const double m = std::sqrt(std::max(0.5 * (D + k), 0.0));
  const double n = std::copysign(std::sqrt(std::max(0.5 * (D - k), 0.0)), X);
  const double Z2 = Z * Z, n2 = n * n, m2 = m * m;
  StressTensor s;
  const double p0 = c.peak_pressure, q0 = c.friction_coefficient * c.peak_pressure;
  // McEwen (1949) as in Johnson (1985) §4.2 (normal) and §7.1 (tangential), n with the sign of x. The sign of
  // the normal tau_xz is that of the Flamant integration (tau_xz < 0 for x > 0, Johnson eq. 2.15).
  s.xx = -p0 * (m * (1.0 + (Z2 + n2) / D) - 2.0 * Z) + q0 * (n * (2.0 - (Z2 - m2) / D) - 2.0 * X);
  s.zz = -p0 * m * (1.0 - (Z2 + n2) / D) - q0 * n * (m2 - Z2) / D;
  s.xz = -p0 * n * (m2 - Z2) / D - q0 * (m * (1.0 + (Z2 + n2) / D) - 2.0 * Z);
  s.yy = c.poisson_ratio * (s.xx + s.zz);
  return s;
}

// ---------------------------------------------------------------- tier 2

void LineTraction::validate() const
{
  const std::size_t n = pressure.size();
  if (n == 0) throw InvalidCoefficient("subsurface stress: the line traction has no strips");
  if (edges.size() != n + 1)
    throw InvalidCoefficient("subsurface stress: a line traction of " + std::to_string(n) + " strips needs " +
                             std::to_string(n + 1) + " edges, got " + std::to_string(edges.size()));
  if (!shear.empty() && shear.size() != n)
    throw InvalidCoefficient("subsurface stress: line traction shear has " + std::to_string(shear.size()) +
                             " values for " + std::to_string(n) + " strips");
  for (std::size_t j = 0; j <= n; ++j) {
    require_finite(edges[j], "strip edge");
    if (j > 0 && !(edges[j] > edges[j - 1]))
      throw InvalidCoefficient("subsurface stress: strip edges must increase strictly (edge " + std::to_string(j) + ")");
  }
  for (double p : pressure) require_finite(p, "pressure");
  for (double q : shear) require_finite(q, "shear");
}

LineTraction LineTraction::from_nodes(const std::vector<double> &x, const std::vector<double> &pressure,
                                      const std::vector<double> &shear)
{
  if (x.size() < 2 || pressure.size() != x.size())
    throw InvalidCoefficient("subsurface stress: from_nodes needs >= 2 nodes and one pressure per node");
  LineTraction t;
  t.pressure = pressure;
  t.shear = shear;
  t.edges.resize(x.size() + 1);
  t.edges.front() = x.front() - 0.5 * (x[1] - x[0]);
  for (std::size_t j = 1; j < x.size(); ++j) t.edges[j] = 0.5 * (x[j - 1] + x[j]);
  t.edges.back() = x.back() + 0.5 * (x.back() - x[x.size() - 2]);
  t.validate();
  return t;
}

StressTensor line_traction_stress(const LineTraction &t, double nu, double x, double z)
{
  return line_traction_field(t, nu, {x}, {z}).stress.front();
}

StressField line_traction_field(const LineTraction &t, double nu, const std::vector<double> &x,
                                 const std::vector<double> &z)
{
  t.validate();
  require_poisson(nu);
  require_grid(x, "x");
  require_grid(z, "depth");
  for (double d : z) require_point(0.0, 0.0, d);
  const std::size_t n = t.pressure.size();
  // Jumps at the edges: strip e lies to the right of edge e.
  std::vector<double> dp(n + 1), dq(n + 1);
  for (std::size_t e = 0; e <= n; ++e) {
    dp[e] = (e < n ? t.pressure[e] : 0.0) - (e > 0 ? t.pressure[e - 1] : 0.0);
    dq[e] = t.shear.empty() ? 0.0 : (e < n ? t.shear[e] : 0.0) - (e > 0 ? t.shear[e - 1] : 0.0);
  }
  const double span = t.edges.back() - t.edges.front();
  const double r2_floor = 1e-24 * span * span;    // a surface point on an edge: finite, not NaN
  StressField f;
  f.x = x, f.z = z;
  f.stress.assign(x.size() * z.size(), StressTensor{});
  const double scale = -2.0 / kPi;
  for (std::size_t k = 0; k < z.size(); ++k) {
    StressTensor *row = &f.stress[x.size() * k];
    for (std::size_t e = 0; e <= n; ++e) {
      const double wp = dp[e], wq = dq[e];
      if (wp == 0.0 && wq == 0.0) continue;
      const double xi = t.edges[e];
      for (std::size_t i = 0; i < x.size(); ++i) {
        const LineCorner c = line_corner(x[i] - xi, z[k], r2_floor, wq != 0.0);
        row[i].xx += wp * c.nxx + wq * c.txx;
        row[i].zz += wp * c.nzz + wq * c.tzz;
        row[i].xz += wp * c.nxz + wq * c.txz;
      }
    }
    for (std::size_t i = 0; i < x.size(); ++i) {
      StressTensor &s = row[i];
      s.xx *= scale, s.zz *= scale, s.xz *= scale;
      s.yy = nu * (s.xx + s.zz);
    }
  }
  return f;
}

void PatchTraction::validate() const
{
  require_finite(x0, "patch grid x0");
  require_finite(y0, "patch grid y0");
  require_finite(dx, "patch size dx");
  require_finite(dy, "patch size dy");
  if (!(dx > 0.0) || !(dy > 0.0)) throw InvalidCoefficient("subsurface stress: patch sizes dx, dy must be > 0");
  if (nx < 1 || ny < 1) throw InvalidCoefficient("subsurface stress: the patch grid needs nx, ny >= 1");
  const auto count = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  if (pressure.size() != count)
    throw InvalidCoefficient("subsurface stress: " + std::to_string(pressure.size()) + " patch pressures for a " +
                             std::to_string(nx) + " x " + std::to_string(ny) + " grid");
  if (!shear_x.empty() && shear_x.size() != count)
    throw InvalidCoefficient("subsurface stress: " + std::to_string(shear_x.size()) + " patch shears for a " +
                             std::to_string(nx) + " x " + std::to_string(ny) + " grid");
  for (double p : pressure) require_finite(p, "patch pressure");
  for (double q : shear_x) require_finite(q, "patch shear");
}

StressTensor patch_traction_stress(const PatchTraction &t, double nu, double x, double y, double z)
{
  return patch_traction_field(t, nu, {x}, {z}, y).stress.front();
}

StressField patch_traction_field(const PatchTraction &t, double nu, const std::vector<double> &x,
                                 const std::vector<double> &z, double y)
{
  t.validate();
  require_poisson(nu);
  require_grid(x, "x");
  require_grid(z, "depth");
  require_finite(y, "section y");
  for (double d : z) require_point(0.0, 0.0, d);
  const int cx = t.nx + 1, cy = t.ny + 1;
  const std::vector<double> wp = corner_weights(t.pressure, t.nx, t.ny);
  const std::vector<double> wq = corner_weights(t.shear_x, t.nx, t.ny);
  const bool shear = !t.shear_x.empty();
  auto weight_q = [&](int c) { return shear ? wq[c] : 0.0; };
  std::vector<char> row_used(cy, 0);
  for (int j = 0; j < cy; ++j)
    for (int i = 0; i < cx; ++i)
      if (wp[i + cx * j] != 0.0 || weight_q(i + cx * j) != 0.0) row_used[j] = 1;

  // Toeplitz path: x = the patch centres, so X = (i - c + 1/2) dx depends on i - c only.
  bool centres = static_cast<int>(x.size()) == t.nx;
  for (int i = 0; centres && i < t.nx; ++i)
    centres = std::abs(x[i] - (t.x0 + (i + 0.5) * t.dx)) <= 1e-9 * t.dx;

  StressField f;
  f.x = x, f.z = z;
  f.stress.assign(x.size() * z.size(), StressTensor{});
  const double scale = 1.0 / (2.0 * kPi);
  std::vector<double> table_soa, acc;
  for (std::size_t k = 0; k < z.size(); ++k) {
    StressTensor *row = &f.stress[x.size() * k];
    if (centres) acc.assign(6 * static_cast<std::size_t>(t.nx), 0.0);
    for (int j = 0; j < cy; ++j) {
      if (!row_used[j]) continue;
      const double Y = y - (t.y0 + j * t.dy);
      if (centres) {
        // d = i - c in [-nx, nx - 1], stored at d + nx; components in separate arrays (structure of arrays) so
        // the sum over i below is a plain vectorisable multiply-add.
        const std::size_t m = 2 * static_cast<std::size_t>(t.nx);
        table_soa.assign(12 * m, 0.0);
        for (int d = -t.nx; d < t.nx; ++d) {
          const CornerPair kp = corner((d + 0.5) * t.dx, Y, z[k], nu, shear);
          const double v[12] = {kp.normal.xx, kp.normal.yy, kp.normal.zz, kp.normal.yz, kp.normal.xz, kp.normal.xy,
                                kp.shear.xx,  kp.shear.yy,  kp.shear.zz,  kp.shear.yz,  kp.shear.xz,  kp.shear.xy};
          for (int q = 0; q < 12; ++q) table_soa[q * m + d + t.nx] = v[q];
        }
        for (int c = 0; c < cx; ++c) {
          const double a = wp[c + cx * j], b = weight_q(c + cx * j);
          if (a == 0.0 && b == 0.0) continue;
          const std::size_t offset = static_cast<std::size_t>(t.nx - c);    // d + nx at i = 0
          for (int q = 0; q < 6; ++q) {
            double *out = &acc[q * static_cast<std::size_t>(t.nx)];
            const double *tn = &table_soa[q * m + offset];
            const double *ts = &table_soa[(q + 6) * m + offset];
            if (b != 0.0)
              for (int i = 0; i < t.nx; ++i) out[i] += a * tn[i] + b * ts[i];
            else
              for (int i = 0; i < t.nx; ++i) out[i] += a * tn[i];
          }
        }
      } else {
        for (int c = 0; c < cx; ++c) {
          const double a = wp[c + cx * j], b = weight_q(c + cx * j);
          if (a == 0.0 && b == 0.0) continue;
          const double xi = t.x0 + c * t.dx;
          for (std::size_t i = 0; i < x.size(); ++i) {
            const CornerPair kp = corner(x[i] - xi, Y, z[k], nu, b != 0.0);
            accumulate(row[i], kp.normal, a);
            if (b != 0.0) accumulate(row[i], kp.shear, b);
          }
        }
      }
    }
    if (centres)
      for (int i = 0; i < t.nx; ++i) {
        const std::size_t n = static_cast<std::size_t>(t.nx);
        row[i] = {acc[i], acc[n + i], acc[2 * n + i], acc[3 * n + i], acc[4 * n + i], acc[5 * n + i]};
      }
    for (std::size_t i = 0; i < x.size(); ++i) row[i] = row[i].scaled(scale);
  }
  return f;
}

PatchTraction axisymmetric_patches(const std::function<double(double)> &p_of_r, double radius, double mu,
                                   double half_size, int n)
{
  require_finite(radius, "contact radius");
  require_finite(mu, "friction coefficient mu");
  require_finite(half_size, "half size");
  if (!(radius > 0.0)) throw InvalidCoefficient("subsurface stress: contact radius must be > 0, got " + fmt(radius));
  if (!(half_size >= radius))
    throw InvalidCoefficient("subsurface stress: the patch grid half size " + fmt(half_size) +
                             " must cover the contact radius " + fmt(radius));
  if (n < 2) throw InvalidCoefficient("subsurface stress: the patch grid needs n >= 2 per side");
  PatchTraction t;
  t.nx = t.ny = n;
  t.x0 = t.y0 = -half_size;
  t.dx = t.dy = 2.0 * half_size / n;
  t.pressure.assign(static_cast<std::size_t>(n) * n, 0.0);
  constexpr int sub = 4;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double sum = 0.0;
      for (int b = 0; b < sub; ++b)
        for (int a = 0; a < sub; ++a) {
          const double px = t.x0 + (i + (a + 0.5) / sub) * t.dx, py = t.y0 + (j + (b + 0.5) / sub) * t.dy;
          const double r = std::hypot(px, py);
          if (r < radius) sum += p_of_r(r);
        }
      t.pressure[i + n * j] = sum / (sub * sub);
    }
  if (mu != 0.0) {
    t.shear_x = t.pressure;
    for (double &q : t.shear_x) q *= mu;
  }
  t.validate();
  return t;
}

PatchTraction axisymmetric_patches(const std::vector<double> &ring_pressure, double ring_width, double mu,
                                   double half_size, int n)
{
  if (ring_pressure.empty()) throw InvalidCoefficient("subsurface stress: no ring pressures");
  require_finite(ring_width, "ring width");
  if (!(ring_width > 0.0)) throw InvalidCoefficient("subsurface stress: ring width must be > 0");
  for (double p : ring_pressure) require_finite(p, "ring pressure");
  // Outer edge of the outermost loaded ring.
  std::size_t last = 0;
  for (std::size_t i = 0; i < ring_pressure.size(); ++i)
    if (ring_pressure[i] != 0.0) last = i + 1;
  if (last == 0) last = 1;
  const double radius = last * ring_width;
  return axisymmetric_patches(
      [&](double r) {
        const auto i = static_cast<std::size_t>(r / ring_width);
        return i < ring_pressure.size() ? ring_pressure[i] : 0.0;
      },
      radius, mu, std::max(half_size, radius), n);
}

// ---------------------------------------------------------------- fields

std::vector<double> StressField::von_mises() const
{
  std::vector<double> v(stress.size());
  for (std::size_t i = 0; i < stress.size(); ++i) v[i] = stress[i].von_mises();
  return v;
}

std::vector<double> StressField::tresca() const
{
  std::vector<double> v(stress.size());
  for (std::size_t i = 0; i < stress.size(); ++i) v[i] = stress[i].tresca();
  return v;
}

StressPeak StressField::peak_von_mises() const
{
  StressPeak p;
  for (std::size_t k = 0; k < z.size(); ++k)
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double v = stress[i + x.size() * k].von_mises();
      if (v > p.von_mises) p = {v, x[i], z[k]};
    }
  return p;
}

StressPeak StressField::peak_von_mises_on_axis() const
{
  std::size_t axis = 0;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (std::abs(x[i]) < std::abs(x[axis])) axis = i;
  StressPeak p;
  for (std::size_t k = 0; k < z.size(); ++k) {
    const double v = stress[axis + x.size() * k].von_mises();
    if (v > p.von_mises) p = {v, x[axis], z[k]};
  }
  return p;
}

std::vector<double> uniform_points(double lo, double hi, int n)
{
  if (n < 2 || !(hi > lo)) throw InvalidCoefficient("subsurface stress: uniform_points needs n >= 2 and hi > lo");
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = lo + (hi - lo) * i / (n - 1);
  return v;
}

std::vector<double> cell_centres(double lo, double hi, int n)
{
  if (n < 1 || !(hi > lo)) throw InvalidCoefficient("subsurface stress: cell_centres needs n >= 1 and hi > lo");
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = lo + (hi - lo) * (i + 0.5) / n;
  return v;
}

StressField hamilton_field(const SlidingHertzSphere &c, const std::vector<double> &x, const std::vector<double> &z,
                           double y)
{
  c.validate();
  require_grid(x, "x");
  require_grid(z, "depth");
  StressField f;
  f.x = x, f.z = z;
  f.stress.reserve(x.size() * z.size());
  for (double d : z)
    for (double a : x) f.stress.push_back(hamilton_stress(c, a, y, d));
  return f;
}

StressField mcewen_field(const SlidingHertzLine &c, const std::vector<double> &x, const std::vector<double> &z)
{
  c.validate();
  require_grid(x, "x");
  require_grid(z, "depth");
  StressField f;
  f.x = x, f.z = z;
  f.stress.reserve(x.size() * z.size());
  for (double d : z)
    for (double a : x) f.stress.push_back(mcewen_stress(c, a, d));
  return f;
}

namespace {

// Compass search for the largest von Mises stress of vm(x, z) from each start (x, z), z >= 0 and x in
// [x_lo, x_hi], steps from `step` down to `tolerance`: a cusp (the contact edge) or a smooth maximum alike.
template <class F>
StressPeak compass_peak(const F &vm, const std::vector<StressPeak> &starts, double x_lo, double x_hi, double step,
                        double tolerance)
{
  StressPeak best;
  for (StressPeak p : starts) {
    p.von_mises = vm(p.x, p.z);
    double h = step;
    while (h > tolerance) {
      bool moved = false;
      const double trial[4][2] = {{p.x + h, p.z}, {p.x - h, p.z}, {p.x, p.z + h}, {p.x, std::max(p.z - h, 0.0)}};
      for (const auto &t : trial) {
        if (t[0] < x_lo || t[0] > x_hi || (t[0] == p.x && t[1] == p.z)) continue;
        const double v = vm(t[0], t[1]);
        if (v > p.von_mises) p = {v, t[0], t[1]}, moved = true;
      }
      if (!moved) h *= 0.5;
    }
    if (p.von_mises > best.von_mises) best = p;
  }
  return best;
}

// The starts of the peak search on a grid: its largest point, its largest surface point, the contact edges.
std::vector<StressPeak> peak_starts(const StressField &grid, double half_width)
{
  std::vector<StressPeak> starts{grid.peak_von_mises(), {0.0, -half_width, 0.0}, {0.0, half_width, 0.0}};
  std::size_t surface = 0;
  for (std::size_t k = 1; k < grid.z.size(); ++k)
    if (grid.z[k] < grid.z[surface]) surface = k;
  StressPeak top;
  for (std::size_t i = 0; i < grid.x.size(); ++i) {
    const double v = grid.stress[i + grid.x.size() * surface].von_mises();
    if (v > top.von_mises) top = {v, grid.x[i], grid.z[surface]};
  }
  starts.push_back(top);
  return starts;
}

template <class F> StressPeak refined_peak(const F &vm, const StressField &grid, double half_width)
{
  const auto [lo, hi] = std::minmax_element(grid.x.begin(), grid.x.end());
  double step = half_width;
  if (grid.x.size() > 1) step = (*hi - *lo) / static_cast<double>(grid.x.size() - 1);
  const StressPeak found = compass_peak(vm, peak_starts(grid, half_width), std::min(*lo, -half_width),
                                        std::max(*hi, half_width), step, 1e-9 * half_width);
  const StressPeak on_grid = grid.peak_von_mises();
  return found.von_mises > on_grid.von_mises ? found : on_grid;
}

}  // namespace

StressPeak hamilton_peak_von_mises(const SlidingHertzSphere &c, const StressField &grid, double y)
{
  c.validate();
  require_grid(grid.x, "x");
  require_grid(grid.z, "depth");
  return refined_peak([&](double x, double z) { return hamilton_stress(c, x, y, z).von_mises(); }, grid,
                      c.contact_radius);
}

StressPeak mcewen_peak_von_mises(const SlidingHertzLine &c, const StressField &grid)
{
  c.validate();
  require_grid(grid.x, "x");
  require_grid(grid.z, "depth");
  return refined_peak([&](double x, double z) { return mcewen_stress(c, x, z).von_mises(); }, grid, c.half_width);
}

StressField axisymmetric_section(const std::vector<double> &ring_pressure, double ring_width, double mu, double nu,
                                 double half_size, int n, const std::vector<double> &z)
{
  const PatchTraction t = axisymmetric_patches(ring_pressure, ring_width, mu, half_size, n);
  return patch_traction_field(t, nu, cell_centres(t.x0, t.x0 + t.nx * t.dx, t.nx), z, 0.0);
}

}  // namespace runin::tribo
