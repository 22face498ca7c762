#include "tribo/surface_statistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace runin::tribo {

void HeightRange::add(double z)
{
  count += 1.0;
  sum += z;
  min = std::min(min, z);
  max = std::max(max, z);
}

void HeightRange::merge(const HeightRange &other)
{
  count += other.count;
  sum += other.sum;
  min = std::min(min, other.min);
  max = std::max(max, other.max);
}

double HeightRange::mean() const
{
  return count > 0.0 ? sum / count : 0.0;
}

HeightMoments::HeightMoments(double reference, double top, std::vector<double> depths) :
    reference_(reference), top_(top), depths_(std::move(depths)), sums_(NFIXED + depths_.size(), 0.0)
{
  for (double depth : depths_)
    if (!(depth >= 0.0) || !std::isfinite(depth))
      throw std::invalid_argument("bearing depth must be a finite number >= 0, got " + std::to_string(depth));
}

void HeightMoments::add(double z)
{
  const double d = z - reference_, d2 = d * d;
  sums_[N] += 1.0;
  sums_[S1] += d;
  sums_[SABS] += std::fabs(d);
  sums_[S2] += d2;
  sums_[S3] += d2 * d;
  sums_[S4] += d2 * d2;
  for (std::size_t k = 0; k < depths_.size(); ++k)
    if (z >= top_ - depths_[k]) sums_[NFIXED + k] += 1.0;
}

void HeightMoments::merge(const HeightMoments &other)
{
  if (other.reference_ != reference_ || other.top_ != top_ || other.depths_ != depths_)
    throw std::invalid_argument("HeightMoments::merge: reference, top and depths must match");
  for (std::size_t k = 0; k < sums_.size(); ++k) sums_[k] += other.sums_[k];
}

RoughnessStatistics roughness(const HeightRange &range, const HeightMoments &moments)
{
  RoughnessStatistics out;
  const auto &s = moments.sums();
  out.bearing.assign(moments.depths().size(), 0.0);
  const double n = s[HeightMoments::N];
  if (!(n > 0.0)) return out;

  // Raw moments about the reference, then central moments about the mean = reference + delta.
  const double m1 = s[HeightMoments::S1] / n, m2 = s[HeightMoments::S2] / n;
  const double m3 = s[HeightMoments::S3] / n, m4 = s[HeightMoments::S4] / n;
  const double delta = m1, delta2 = delta * delta;
  const double mu2 = std::max(0.0, m2 - delta2);
  const double mu3 = m3 - 3.0 * delta * m2 + 2.0 * delta2 * delta;
  const double mu4 = m4 - 4.0 * delta * m3 + 6.0 * delta2 * m2 - 3.0 * delta2 * delta2;

  out.count = n;
  out.mean = moments.reference() + delta;
  out.Ra = s[HeightMoments::SABS] / n;
  out.Rq = std::sqrt(mu2);
  if (mu2 > 0.0) {
    out.Rsk = mu3 / (mu2 * out.Rq);
    out.Rku = mu4 / (mu2 * mu2);
  }
  // Extremes relative to the mean, through the reference so that no large absolute height is
  // subtracted from a nearby one twice.
  if (!range.empty()) {
    out.Rp = (range.max - moments.reference()) - delta;
    out.Rv = delta - (range.min - moments.reference());
  }
  out.Rz = out.Rp + out.Rv;
  for (std::size_t k = 0; k < out.bearing.size(); ++k) out.bearing[k] = s[HeightMoments::NFIXED + k] / n;
  return out;
}

RoughnessStatistics roughness(const std::vector<double> &heights, const std::vector<double> &depths)
{
  HeightRange range;
  for (double z : heights) range.add(z);
  HeightMoments moments(range.mean(), range.max, depths);
  for (double z : heights) moments.add(z);
  return roughness(range, moments);
}

}    // namespace runin::tribo
