// Isotropic Gaussian random surfaces on a periodic square grid: spectral synthesis (Eigen's FFT), the spectral
// moments and bandwidth parameter alpha of Nayak (1971), and the summits as 8-neighbour maxima.
// Nayak's large-alpha summit-height variance, sigma_s^2 = (1 - 0.8968 / alpha) m0, is checked against generated
// surfaces in tests/unit/test_tribo_gaussian_surface.cpp; doc/rve_cell.md ("Surface and summit roughness").
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace runin::tribo {

// Heights on an n x n periodic grid of side `length`, row-major: z[iy * n + ix] at ((ix + 1/2) h, (iy + 1/2) h),
// h = length / n.
struct HeightField {
  std::size_t n = 0;
  double length = 0.0;
  std::vector<double> z;
  double spacing() const { return length / static_cast<double>(n); }
};

// An isotropic power spectral density C(q) of the wavenumber q = |q| (rad per length unit); any scale (the
// generated field is rescaled to the requested RMS).
using IsotropicSpectrum = std::function<double(double q)>;

// Self-affine spectrum with a roll-off (Persson): C = 1 for 0 < q < q_roll, (q / q_roll)^(-2 (1 + H)) for
// q_roll <= q <= q_cut, 0 above q_cut and at q = 0 (the mean).
struct SelfAffineSpectrum {
  double q_roll, q_cut, hurst;
  double operator()(double q) const;
};

// A realisation: independent complex Gaussian amplitudes sqrt(C(q)) on the grid's wavevectors (|q_x|, |q_y| up to
// the Nyquist pi / h), inverse FFT, real part, mean removed, scaled to RMS `rms`. Deterministic for a seed.
// Throws std::invalid_argument for n < 4, length <= 0, rms < 0 or a spectrum that is zero on the whole grid.
HeightField gaussian_surface(std::size_t n, double length, const IsotropicSpectrum &spectrum, double rms,
                             std::uint64_t seed);

// Profile spectral moments of a field, averaged over directions (m2 = <(q.e)^2>, m4 = <(q.e)^4>: the isotropic
// averages q^2 / 2 and 3 q^4 / 8 of its discrete power spectrum), and Nayak's bandwidth alpha = m0 m4 / m2^2.
struct SpectralMoments {
  double m0 = 0.0, m2 = 0.0, m4 = 0.0;
  double alpha() const { return m2 > 0.0 ? m0 * m4 / (m2 * m2) : 0.0; }
};
SpectralMoments spectral_moments(const HeightField &field);

// Heights of the summits: grid points strictly above their 8 neighbours (periodic).
std::vector<double> summit_heights(const HeightField &field);

// Nayak (1971) for an isotropic Gaussian surface, large alpha: summit-height variance / m0 = 1 - 0.8968 / alpha,
// mean summit height / sqrt(m0) = 4 / sqrt(pi alpha).
inline double nayak_summit_variance_ratio(double alpha) { return 1.0 - 0.8968 / alpha; }
double nayak_mean_summit_height(double alpha);

}    // namespace runin::tribo
