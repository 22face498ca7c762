// Gaussian random surfaces (spectral synthesis), their summits, Nayak's bandwidth relation between the surface
// Rq and the summit-height RMS, and the summit-envelope height field of compute runin/roughness.
#include "tribo/gaussian_surface.h"
#include "tribo/summit_envelope.h"
#include "tribo/surface_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace runin::tribo;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Pooled over a few realisations: the surface's mean square height, the summits' variance and mean, and alpha.
struct Pooled {
  double m0 = 0.0, alpha = 0.0, summit_variance = 0.0, summit_mean = 0.0;
  double summits = 0.0;
};

// Self-affine (H = 0.8) with the cut-off at a fraction of the Nyquist wavenumber and the roll-off `band` times
// lower; realisations with seeds 20260, 20261, ...
Pooled pooled(std::size_t n, double cut_fraction_of_nyquist, double band, int realisations)
{
  const double length = 1.0, nyquist = kPi * static_cast<double>(n) / length;
  const SelfAffineSpectrum spectrum{cut_fraction_of_nyquist * nyquist / band, cut_fraction_of_nyquist * nyquist, 0.8};
  Pooled p;
  double sum = 0.0, sum2 = 0.0, m0 = 0.0, alpha = 0.0;
  for (int k = 0; k < realisations; ++k) {
    const HeightField field = gaussian_surface(n, length, spectrum, 1.0, 20260 + k);
    const RoughnessStatistics surface = roughness(field.z);    // the routine of compute runin/roughness
    m0 += surface.Rq * surface.Rq;
    alpha += spectral_moments(field).alpha();
    for (double z : summit_heights(field)) {
      sum += z - surface.mean;
      sum2 += (z - surface.mean) * (z - surface.mean);
      p.summits += 1.0;
    }
  }
  p.m0 = m0 / realisations;
  p.alpha = alpha / realisations;
  p.summit_mean = sum / p.summits;
  p.summit_variance = sum2 / p.summits - p.summit_mean * p.summit_mean;
  return p;
}

}    // namespace

TEST(GaussianSurface, HasTheRequestedRmsZeroMeanAndGaussianMoments)
{
  // roll-off at 16 wavelengths per side, cut-off at 64: thousands of independent modes
  const double L = 1e-3;
  const HeightField field =
      gaussian_surface(256, L, SelfAffineSpectrum{2.0 * kPi * 16.0 / L, 2.0 * kPi * 64.0 / L, 0.8}, 2e-7, 7);
  const RoughnessStatistics s = roughness(field.z);
  EXPECT_NEAR(s.mean, 0.0, 1e-20);
  EXPECT_NEAR(s.Rq, 2e-7, 1e-20);
  EXPECT_NEAR(s.Rsk, 0.0, 0.1);
  EXPECT_NEAR(s.Rku, 3.0, 0.2);
  EXPECT_NEAR(s.Ra / s.Rq, std::sqrt(2.0 / kPi), 0.03);    // Gaussian: Ra = sqrt(2/pi) Rq
  // the spectral m0 is the mean square height (Parseval)
  EXPECT_NEAR(spectral_moments(field).m0, s.Rq * s.Rq, 1e-12 * s.Rq * s.Rq);
  // deterministic per seed
  EXPECT_EQ(gaussian_surface(32, 1.0, SelfAffineSpectrum{10.0, 60.0, 0.8}, 1.0, 3).z,
            gaussian_surface(32, 1.0, SelfAffineSpectrum{10.0, 60.0, 0.8}, 1.0, 3).z);
}

TEST(GaussianSurface, AlphaOfARingSpectrumIsThreeHalves)
{
  // all power at one |q|: m2 = m0 q^2 / 2, m4 = 3 m0 q^4 / 8, so alpha = 3/2 (the isotropic minimum)
  const double q0 = 2.0 * kPi * 20.0;
  const HeightField field =
      gaussian_surface(128, 1.0, [&](double q) { return std::fabs(q - q0) < 1e-9 * q0 ? 1.0 : 0.0; }, 1.0, 1);
  EXPECT_NEAR(spectral_moments(field).alpha(), 1.5, 1e-12);
}

TEST(GaussianSurface, SummitsAreStrictEightNeighbourMaxima)
{
  HeightField field;
  field.n = 4;
  field.length = 4.0;
  field.z.assign(16, 0.0);
  field.z[1 * 4 + 1] = 2.0;    // a summit
  field.z[3 * 4 + 3] = 1.0;    // a summit across the periodic corner from (0, 0)
  field.z[0] = 1.0;            // its diagonal neighbour of equal height: neither is strict
  EXPECT_EQ(summit_heights(field), std::vector<double>{2.0});
}

TEST(GaussianSurface, RejectsBadArguments)
{
  const SelfAffineSpectrum spectrum{10.0, 60.0, 0.8};
  EXPECT_THROW(gaussian_surface(2, 1.0, spectrum, 1.0, 1), std::invalid_argument);
  EXPECT_THROW(gaussian_surface(16, 0.0, spectrum, 1.0, 1), std::invalid_argument);
  EXPECT_THROW(gaussian_surface(16, 1.0, spectrum, -1.0, 1), std::invalid_argument);
  EXPECT_THROW(gaussian_surface(16, 1.0, [](double) { return 0.0; }, 1.0, 1), std::invalid_argument);
}

// Nayak (1971): for an isotropic Gaussian surface the summits' height variance is (1 - 0.8968 / alpha) m0 and
// their mean height 4 sqrt(m0 / (pi alpha)), alpha = m0 m4 / m2^2. Surfaces resolved at 6 points per shortest
// wavelength (cut-off at a third of the Nyquist wavenumber), realisations of 1024^2 pooled (three at alpha ~ 4:
// 25 000 summits; two at alpha ~ 19: 13 000): the summit variance over the surface's Rq^2 within 5 % of Nayak's, at alpha ~ 4 (a narrow band, where
// the summits' RMS is 12 % below the surface Rq) and alpha ~ 19.
TEST(GaussianSurface, SummitVarianceFollowsNayaksBandwidthRelation)
{
  for (double band : {4.0, 16.0}) {
    const Pooled p = pooled(1024, 1.0 / 3.0, band, band == 4.0 ? 3 : 2);
    SCOPED_TRACE("band " + std::to_string(band) + ", alpha " + std::to_string(p.alpha) + ", summits " +
                 std::to_string(p.summits));
    EXPECT_GT(p.summits, 10000.0);
    const double nayak = nayak_summit_variance_ratio(p.alpha);
    // the numbers doc/compute_runin_roughness.rst quotes
    std::printf("Nayak: alpha %.2f, %.0f summits: summit variance / Rq^2 %.4f (Nayak %.4f), summit RMS / Rq %.4f, "
                "mean summit height / Rq %.4f (Nayak %.4f)\n",
                p.alpha, p.summits, p.summit_variance / p.m0, nayak, std::sqrt(p.summit_variance / p.m0),
                p.summit_mean / std::sqrt(p.m0), nayak_mean_summit_height(p.alpha));
    EXPECT_NEAR(p.summit_variance / p.m0, nayak, 0.05 * nayak);
    if (band == 4.0) {
      EXPECT_NEAR(p.alpha, 4.0, 0.5);
      // the summit RMS is not the surface Rq: it is well below it at this bandwidth
      EXPECT_LT(std::sqrt(p.summit_variance / p.m0), 0.92);
      EXPECT_NEAR(p.summit_mean / std::sqrt(p.m0), nayak_mean_summit_height(p.alpha),
                  0.05 * nayak_mean_summit_height(p.alpha));
    }
  }
}

// One sphere of radius R centred on a periodic cell of side L < 2R: the envelope z = sqrt(R^2 - r^2), whose mean
// over the cell is known in closed form (for L <= sqrt(2) R the whole square lies under the cap): the integral of
// sqrt(R^2 - x^2 - y^2) over the square [-L/2, L/2]^2, by the midpoint rule on a fine 1-D quadrature here.
TEST(SummitEnvelope, MeanOfOneCapConvergesToTheIntegral)
{
  const double R = 1.0, L = 1.2;
  // reference: integral over x of the exact y-integral int sqrt(a^2 - y^2) dy = (y s + a^2 asin(y / a)) / 2
  double exact = 0.0;
  const int m = 200000;
  for (int k = 0; k < m; ++k) {
    const double x = -L / 2 + (k + 0.5) * L / m, a2 = R * R - x * x, a = std::sqrt(a2), y = L / 2;
    exact += (y * std::sqrt(a2 - y * y) + a2 * std::asin(y / a)) * (L / m);
  }
  exact /= L * L;
  double previous_error = 1.0;
  for (std::size_t n : {8, 32, 128}) {
    SummitEnvelope envelope(0.0, 0.0, L, L, n, n, true, true);
    envelope.add({L / 2, L / 2, 0.0, R, 0.0}, R);
    const EnvelopeStatistics s = envelope_statistics(envelope.heights(), -1.0);
    EXPECT_EQ(s.covered, 1.0);
    const double error = std::fabs(s.roughness.mean - exact);
    EXPECT_LT(error, previous_error / 8.0) << n;    // midpoint rule: second order
    previous_error = error;
  }
  EXPECT_LT(previous_error, 2e-5);
}

// A flat cut at drop h removes the cap volume pi h^2 (3R - h) / 3 from the envelope of a lone summit; the caps of
// a periodic image wrap; a floor above the centre shrinks the footprint to where the cap is above it.
TEST(SummitEnvelope, FlatRemovesTheCapVolumeAndFootprintsAreExact)
{
  const double R = 1.0, L = 1.2, h = 0.05;
  SummitEnvelope whole(0.0, 0.0, L, L, 600, 600, true, true), cut(0.0, 0.0, L, L, 600, 600, true, true);
  // axis near a corner: the cap wraps over all four periodic images
  whole.add({0.05, 1.1, 0.0, R, 0.0}, R);
  cut.add({0.05, 1.1, 0.0, R, h}, R);
  const double removed = (envelope_statistics(whole.heights(), 0.0).roughness.mean -
                          envelope_statistics(cut.heights(), 0.0).roughness.mean) * L * L;
  EXPECT_NEAR(removed, kPi * h * h * (3.0 * R - h) / 3.0, 2e-3 * kPi * h * h * (3.0 * R - h) / 3.0);
  // sample (60, 0) at (0.121, 0.001); the nearest image of the axis is at (0.05, -0.1)
  EXPECT_NEAR(whole.heights()[0 * 600 + 60], std::sqrt(R * R - std::pow(0.121 - 0.05, 2) - std::pow(0.101, 2)),
              1e-12);

  const EnvelopeSummit s{0.0, 0.0, 0.5, R, h};
  EXPECT_EQ(SummitEnvelope::footprint_above(s, 0.4), R);                  // floor below the centre
  EXPECT_EQ(SummitEnvelope::footprint_above(s, 0.5 + R - h), 0.0);        // floor at the flat
  EXPECT_NEAR(SummitEnvelope::footprint_above(s, 1.3), std::sqrt(R * R - 0.8 * 0.8), 1e-15);

  // no periodicity and a cap off the grid: the holes take the base level and count as uncovered
  SummitEnvelope open(0.0, 0.0, 1.0, 1.0, 10, 10, false, false);
  open.add({-0.8, 0.5, 0.0, 1.0, 0.0}, 1.0);
  const EnvelopeStatistics o = envelope_statistics(open.heights(), -2.0);
  EXPECT_GT(o.covered, 0.0);
  EXPECT_LT(o.covered, 1.0);
  EXPECT_THROW(SummitEnvelope(0.0, 0.0, 0.0, 1.0, 4, 4, true, true), std::invalid_argument);
  EXPECT_THROW(SummitEnvelope(0.0, 0.0, 1.0, 1.0, 0, 4, true, true), std::invalid_argument);
}
