#include "tribo/gaussian_surface.h"

#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <random>
#include <stdexcept>
#include <string>

namespace runin::tribo {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Wavenumber of FFT index k on n points of spacing h: k 2 pi / L for k < n/2, (k - n) 2 pi / L above.
double wavenumber(std::size_t k, std::size_t n, double length)
{
  const double signed_k = k <= n / 2 ? static_cast<double>(k) : static_cast<double>(k) - static_cast<double>(n);
  return 2.0 * kPi * signed_k / length;
}

// In-place 2-D transform of an n x n row-major array: 1-D transforms of the rows, then of the columns.
void transform_2d(std::vector<std::complex<double>> &a, std::size_t n, bool inverse)
{
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> line(n), out(n);
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t c = 0; c < n; ++c) line[c] = a[r * n + c];
    if (inverse)
      fft.inv(out, line);
    else
      fft.fwd(out, line);
    for (std::size_t c = 0; c < n; ++c) a[r * n + c] = out[c];
  }
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t r = 0; r < n; ++r) line[r] = a[r * n + c];
    if (inverse)
      fft.inv(out, line);
    else
      fft.fwd(out, line);
    for (std::size_t r = 0; r < n; ++r) a[r * n + c] = out[r];
  }
}

}    // namespace

double SelfAffineSpectrum::operator()(double q) const
{
  if (!(q > 0.0) || q > q_cut) return 0.0;
  if (q < q_roll) return 1.0;
  return std::pow(q / q_roll, -2.0 * (1.0 + hurst));
}

HeightField gaussian_surface(std::size_t n, double length, const IsotropicSpectrum &spectrum, double rms,
                             std::uint64_t seed)
{
  if (n < 4) throw std::invalid_argument("gaussian_surface: n must be >= 4, got " + std::to_string(n));
  if (!(length > 0.0) || !std::isfinite(length))
    throw std::invalid_argument("gaussian_surface: length must be > 0 and finite");
  if (!(rms >= 0.0) || !std::isfinite(rms)) throw std::invalid_argument("gaussian_surface: rms must be >= 0 and finite");
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<std::complex<double>> a(n * n);
  bool any = false;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) {
      const double qx = wavenumber(c, n, length), qy = wavenumber(r, n, length);
      const double power = spectrum(std::sqrt(qx * qx + qy * qy));
      if (!(power >= 0.0) || !std::isfinite(power))
        throw std::invalid_argument("gaussian_surface: the spectrum must be >= 0 and finite");
      const double amplitude = std::sqrt(power);
      // both draws always taken: the field of a seed does not depend on where the spectrum is zero
      const double re = normal(engine), im = normal(engine);
      a[r * n + c] = amplitude * std::complex<double>(re, im);
      any = any || amplitude > 0.0;
    }
  if (!any) throw std::invalid_argument("gaussian_surface: the spectrum is zero at every wavevector of the grid");
  transform_2d(a, n, true);
  HeightField field;
  field.n = n;
  field.length = length;
  field.z.resize(n * n);
  double mean = 0.0;
  for (std::size_t k = 0; k < n * n; ++k) mean += a[k].real();
  mean /= static_cast<double>(n * n);
  double sum2 = 0.0;
  for (std::size_t k = 0; k < n * n; ++k) {
    field.z[k] = a[k].real() - mean;
    sum2 += field.z[k] * field.z[k];
  }
  const double scale = sum2 > 0.0 ? rms / std::sqrt(sum2 / static_cast<double>(n * n)) : 0.0;
  for (double &z : field.z) z *= scale;
  return field;
}

SpectralMoments spectral_moments(const HeightField &field)
{
  const std::size_t n = field.n;
  std::vector<std::complex<double>> a(field.z.begin(), field.z.end());
  transform_2d(a, n, false);
  SpectralMoments m;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) {
      if (r == 0 && c == 0) continue;
      const double qx = wavenumber(c, n, field.length), qy = wavenumber(r, n, field.length);
      const double q2 = qx * qx + qy * qy, power = std::norm(a[r * n + c]);
      m.m0 += power;
      m.m2 += 0.5 * q2 * power;
      m.m4 += 0.375 * q2 * q2 * power;
    }
  // Parseval: sum |Z|^2 = n^2 sum z^2, so m0 is the mean square height
  const double norm = 1.0 / (static_cast<double>(n) * static_cast<double>(n) * static_cast<double>(n * n));
  m.m0 *= norm;
  m.m2 *= norm;
  m.m4 *= norm;
  return m;
}

std::vector<double> summit_heights(const HeightField &field)
{
  const std::size_t n = field.n;
  std::vector<double> out;
  const auto &z = field.z;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) {
      const double centre = z[r * n + c];
      bool summit = true;
      for (int dr = -1; dr <= 1 && summit; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          if (dr == 0 && dc == 0) continue;
          const std::size_t rr = (r + n + dr) % n, cc = (c + n + dc) % n;
          if (!(centre > z[rr * n + cc])) {
            summit = false;
            break;
          }
        }
      if (summit) out.push_back(centre);
    }
  return out;
}

double nayak_mean_summit_height(double alpha)
{
  return 4.0 / std::sqrt(kPi * alpha);
}

}    // namespace runin::tribo
