#include "coupling/homogenise_curves.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace runin::coupling {

namespace {

std::string g6(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

// Least-squares line of y over x on rows [a, b] (inclusive): the means and the slope (0 if x does not vary).
struct Line {
  double mean_x = 0.0, mean_y = 0.0, slope = 0.0;
  bool varies = false;
};
Line fit_line(const std::vector<double> &x, const std::vector<double> &y, std::size_t a, std::size_t b) {
  const double n = static_cast<double>(b - a + 1);
  Line line;
  for (std::size_t i = a; i <= b; ++i) line.mean_x += x[i], line.mean_y += y[i];
  line.mean_x /= n, line.mean_y /= n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = a; i <= b; ++i)
    sxy += (x[i] - line.mean_x) * (y[i] - line.mean_y), sxx += (x[i] - line.mean_x) * (x[i] - line.mean_x);
  line.varies = sxx > 0;
  line.slope = line.varies ? sxy / sxx : 0.0;
  return line;
}

double slope(const std::vector<double> &x, const std::vector<double> &y, std::size_t a, std::size_t b) {
  return fit_line(x, y, a, b).slope;
}

// Value at x0 of the least-squares line of y over x on rows [a, b]; false if there are fewer than 3 rows or x
// does not vary.
bool local_line(const std::vector<double> &x, const std::vector<double> &y, std::size_t a, std::size_t b, double x0,
                double &value) {
  if (b < a + 2) return false;
  const Line line = fit_line(x, y, a, b);
  if (!line.varies) return false;
  value = line.mean_y + line.slope * (x0 - line.mean_x);
  return true;
}

void running_max(std::vector<double> &v) {
  for (std::size_t i = 1; i < v.size(); ++i) v[i] = std::max(v[i], v[i - 1]);
}

}  // namespace

CellSeries cell_series(const coupling::AveTimeTable &table, double rough_summits) {
  CellSeries c;
  const std::array<std::pair<const char *, std::vector<double> *>, 7> columns = {{{"v_s", &c.s},
                                                                                  {"v_h", &c.h},
                                                                                  {"v_h_cf", &c.h_cf},
                                                                                  {"v_mu_body", &c.mu_body},
                                                                                  {"v_rq", &c.rq},
                                                                                  {"v_rsk", &c.rsk},
                                                                                  {"v_area_fraction", &c.area_fraction}}};
  const auto read = [&](const char *name, std::vector<double> &out) {
    out = table.column(name);  // InputFormatError (a runtime_error) naming the file and the columns it has
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!std::isfinite(out[i]))
        throw std::runtime_error(table.source() + ": " + name + " is not finite in data row " + std::to_string(i + 1));
  };
  for (const auto &[name, out] : columns) read(name, *out);
  if (rough_summits > 0.0 && table.has_column("v_contacts")) {
    read("v_contacts", c.contact_fraction);
    for (double &x : c.contact_fraction) x /= rough_summits;
  }
  return c;
}

std::vector<double> depth_grid(double depth, long points, double first) {
  std::vector<double> grid;
  if (first > 0.0 && points >= 3) {
    grid.push_back(0.0);
    const double n = static_cast<double>(points - 2);
    for (long j = 0; j < points - 1; ++j)
      grid.push_back(j == points - 2 ? depth : first * std::pow(depth / first, static_cast<double>(j) / n));
    return grid;
  }
  for (long j = 0; j < points; ++j)
    grid.push_back(j == points - 1 ? depth : depth * static_cast<double>(j) / static_cast<double>(points - 1));
  return grid;
}

DepthCurves resample_on_depth_grid(const CellSeries &cell, const std::vector<double> &grid, double acceleration) {
  // rows once sliding has begun (the loading phase has s = 0 and no friction yet)
  CellSeries c;
  for (std::size_t i = 0; i < cell.s.size(); ++i)
    if (cell.s[i] > 0.0) {
      c.s.push_back(cell.s[i]);
      c.h.push_back(cell.h[i]);
      c.h_cf.push_back(cell.h_cf[i]);
      c.mu_body.push_back(cell.mu_body[i]);
      c.rq.push_back(cell.rq[i]);
      c.rsk.push_back(cell.rsk[i]);
      c.area_fraction.push_back(cell.area_fraction[i]);
      if (!cell.contact_fraction.empty()) c.contact_fraction.push_back(cell.contact_fraction[i]);
    }
  if (c.s.size() < 2) throw std::runtime_error("fewer than 2 output rows with sliding (s > 0)");
  // wear only grows: the running maximum removes round-off dips, so h is non-decreasing
  running_max(c.h);
  running_max(c.h_cf);
  const std::vector<double> &H = c.h;
  const double depth = grid.back();
  if (!(H.back() >= depth))
    throw std::runtime_error("reached h = " + g6(H.back()) + " m of depth " + g6(depth) +
                             " m within nslide (raise grid.nslide or grid.acceleration)");
  const double dh = grid.size() > 1 ? grid[1] - grid[0] : depth;
  // the windows below and above a depth: half a step of the grid on each side (the first step on an even grid, so
  // that its windows do not move with the round-off of grid[j] - grid[j - 1])
  bool even = true;
  for (std::size_t j = 1; j < grid.size(); ++j) even = even && std::fabs(grid[j] - grid[j - 1] - dh) <= 1e-9 * dh;
  const auto step_below = [&](std::size_t j) { return even || j == 0 ? dh : grid[j] - grid[j - 1]; };
  const auto step_above = [&](std::size_t j) {
    return even ? dh : (j + 1 < grid.size() ? grid[j + 1] - grid[j] : grid[j] - grid[j - 1]);
  };
  DepthCurves out;
  for (std::size_t f = 0; f < state_field_count; ++f)
    if (!optional_field(static_cast<StateField>(f)) || !c.contact_fraction.empty()) out.field[f].resize(grid.size());
  using F = coupling::StateField;
  auto field = [&](F f) -> std::vector<double> & { return out.field[static_cast<std::size_t>(f)]; };
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const double hj = grid[j];
    // the first row at or above hj, and the last one below it: the bracket crosses a flat stretch at its end
    const std::size_t i = static_cast<std::size_t>(std::lower_bound(H.begin(), H.end(), hj) - H.begin());
    std::size_t lo = i, hi = i;
    double w = 1.0;
    if (i > 0 && H[i] > hj) {
      lo = i - 1;
      w = (hj - H[lo]) / (H[hi] - H[lo]);  // H[hi] > hj > H[lo]
    }
    auto at = [&](const std::vector<double> &v) { return v[lo] + w * (v[hi] - v[lo]); };
    // friction and real area come from the few contacts of the moment: past h = 0, the least-squares line over
    // the rows within half a grid step of hj, at hj, kept within those rows' range (one-sided at the last depth);
    // exact for a linear trend, and it averages the contact noise of the rows instead of taking the two that
    // bracket hj (fewer than 3 rows: those two). h = 0 stays the state when sliding begins (the first row).
    const std::size_t wa = static_cast<std::size_t>(std::lower_bound(H.begin(), H.end(), hj - 0.5 * step_below(j)) - H.begin());
    const std::size_t wb_end = static_cast<std::size_t>(std::upper_bound(H.begin(), H.end(), hj + 0.5 * step_above(j)) - H.begin());
    auto smoothed = [&](const std::vector<double> &v) {
      double value;
      if (j == 0 || wb_end <= wa || !local_line(H, v, wa, wb_end - 1, hj, value)) return at(v);
      const auto [low, high] = std::minmax_element(v.begin() + static_cast<std::ptrdiff_t>(wa),
                                                   v.begin() + static_cast<std::ptrdiff_t>(wb_end));
      return std::clamp(value, *low, *high);
    };
    field(F::MuBody)[j] = smoothed(c.mu_body);
    field(F::Rq)[j] = at(c.rq);
    field(F::Rsk)[j] = at(c.rsk);
    field(F::AreaFraction)[j] = smoothed(c.area_fraction);
    if (!c.contact_fraction.empty()) field(F::ContactFraction)[j] = smoothed(c.contact_fraction);
    // below the first sliding row the distance runs from the end of loading, (s, h) = (0, 0): the h = 0
    // column is s = 0, where the continuum starts too (the other fields hold the first sliding row there)
    field(F::SlidingDistance)[j] =
        (i == 0 && H[0] > hj ? c.s[0] * (H[0] > 0.0 ? hj / H[0] : 0.0) : at(c.s)) * acceleration;
    // wear rates: least-squares slope over the rows with h within one grid step of hj (at least 3 rows)
    std::size_t a = static_cast<std::size_t>(std::lower_bound(H.begin(), H.end(), hj - step_below(j)) - H.begin());
    std::size_t b = static_cast<std::size_t>(std::upper_bound(H.begin(), H.end(), hj + step_above(j)) - H.begin());
    a = std::min(a, H.size() - 1);
    b = b == 0 ? 0 : b - 1;
    if (b < a) b = a;
    while (b - a + 1 < 3 && (a > 0 || b + 1 < H.size())) {
      if (a > 0) --a;
      if (b - a + 1 < 3 && b + 1 < H.size()) ++b;
    }
    field(F::WearRate)[j] = std::max(0.0, slope(c.s, H, a, b)) / acceleration;
    field(F::CounterfaceWearRate)[j] = std::max(0.0, slope(c.s, c.h_cf, a, b)) / acceleration;
  }
  return out;
}

}  // namespace runin::coupling
