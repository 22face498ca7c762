#include "tribo/summit_envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace runin::tribo {

SummitEnvelope::SummitEnvelope(double x0, double y0, double lx, double ly, std::size_t nx, std::size_t ny,
                               bool periodic_x, bool periodic_y) :
    x0_(x0), y0_(y0), lx_(lx), ly_(ly), nx_(nx), ny_(ny), px_(periodic_x), py_(periodic_y)
{
  if (!(lx > 0.0) || !(ly > 0.0) || !std::isfinite(lx) || !std::isfinite(ly))
    throw std::invalid_argument("summit envelope: the nominal area's sides must be > 0 and finite");
  if (nx == 0 || ny == 0) throw std::invalid_argument("summit envelope: the grid needs at least one point per side");
  dx_ = lx / static_cast<double>(nx);
  dy_ = ly / static_cast<double>(ny);
  z_.assign(nx * ny, -std::numeric_limits<double>::infinity());
}

double SummitEnvelope::footprint_above(const EnvelopeSummit &s, double floor)
{
  const double above = floor - s.centre;    // the cap is above the floor where sqrt(R^2 - r^2) > above
  if (!(above > 0.0)) return s.radius;
  if (above >= s.radius - s.drop) return 0.0;
  return std::sqrt((s.radius - above) * (s.radius + above));
}

void SummitEnvelope::add(const EnvelopeSummit &s, double footprint)
{
  // a summit cut past its equator (drop > R) keeps only the flat of radius sqrt(2 R drop - drop^2)
  const double past = s.drop > s.radius ? std::sqrt(std::max(s.drop * (2.0 * s.radius - s.drop), 0.0)) : s.radius;
  const double f = std::min({footprint, s.radius, past});
  if (!(f > 0.0)) return;
  const double r2max = f * f, R2 = s.radius * s.radius, flat = s.radius - std::max(s.drop, 0.0);
  // cell-centre indices (unwrapped) whose centre lies within f of the axis along each direction
  const long iy0 = static_cast<long>(std::ceil((s.y - f - y0_) / dy_ - 0.5));
  const long iy1 = static_cast<long>(std::floor((s.y + f - y0_) / dy_ - 0.5));
  const long nxl = static_cast<long>(nx_), nyl = static_cast<long>(ny_);
  for (long iy = iy0; iy <= iy1; ++iy) {
    long wy = iy;
    if (py_) wy = ((iy % nyl) + nyl) % nyl;
    else if (iy < 0 || iy >= nyl) continue;
    const double ddy = y0_ + (static_cast<double>(iy) + 0.5) * dy_ - s.y;
    const double rest = r2max - ddy * ddy;
    if (!(rest >= 0.0)) continue;
    const double half = std::sqrt(rest);
    const long ix0 = static_cast<long>(std::ceil((s.x - half - x0_) / dx_ - 0.5));
    const long ix1 = static_cast<long>(std::floor((s.x + half - x0_) / dx_ - 0.5));
    double *row = &z_[static_cast<std::size_t>(wy) * nx_];
    for (long ix = ix0; ix <= ix1; ++ix) {
      long wx = ix;
      if (px_) wx = ((ix % nxl) + nxl) % nxl;
      else if (ix < 0 || ix >= nxl) continue;
      const double ddx = x0_ + (static_cast<double>(ix) + 0.5) * dx_ - s.x;
      const double h = s.centre + std::min(std::sqrt(std::max(R2 - ddx * ddx - ddy * ddy, 0.0)), flat);
      row[wx] = std::max(row[wx], h);
    }
  }
}

EnvelopeStatistics envelope_statistics(const std::vector<double> &heights, double base)
{
  EnvelopeStatistics out;
  std::vector<double> z(heights);
  std::size_t covered = 0;
  for (double &v : z) {
    if (std::isfinite(v))
      ++covered;
    else
      v = base;
  }
  out.covered = z.empty() ? 0.0 : static_cast<double>(covered) / static_cast<double>(z.size());
  out.roughness = roughness(z);
  return out;
}

}    // namespace runin::tribo
