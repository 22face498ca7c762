#include "continuum/ring_liner_wear.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

namespace runin::continuum {
namespace {
constexpr double kPi = 3.14159265358979323846;
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}
bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }
}  // namespace

void RingLinerWearSettings::validate() const {
  require(finite_positive(bore), "bore must be positive");
  require(finite_positive(ring_width), "ring_width must be positive");
  require(std::isfinite(crown_height) && crown_height >= 0.0, "crown_height must be >= 0");
  require(ring_cells >= 2 && ring_cells <= 100000, "ring_cells must lie in [2, 100000]");
  require(liner_cells >= 2 && liner_cells <= 10000000, "liner_cells must lie in [2, 1e7]");
  require(std::isfinite(liner_begin) && std::isfinite(liner_end) && liner_end > liner_begin,
          "liner_end must exceed liner_begin");
  if (contact == FaceContact::Winkler)
    require(finite_positive(foundation_modulus), "foundation_modulus must be positive");
  else
    require(finite_positive(contact_modulus), "contact_modulus must be positive");
  require(std::isfinite(ring_share) && ring_share >= 0.0 && ring_share <= 1.0, "ring_share must lie in [0, 1]");
  require(std::isfinite(step_safety) && step_safety > 0.0 && step_safety < 1.0, "step_safety must lie in (0, 1)");
  require(std::isfinite(fixed_step) && fixed_step >= 0.0, "fixed_step must be >= 0");
  require(std::isfinite(ring_thickness) && ring_thickness >= 0.0, "ring_thickness must be >= 0");
  require(std::isfinite(liner_wall) && liner_wall >= 0.0, "liner_wall must be >= 0");
}

const char *to_string(RingLinerWearStatus status) {
  switch (status) {
    case RingLinerWearStatus::Ok: return "ok";
    case RingLinerWearStatus::RingWornThrough: return "ring worn through";
    case RingLinerWearStatus::LinerWornThrough: return "liner worn through";
  }
  return "unknown";
}

RingLinerWear::RingLinerWear(RingLinerWearSettings settings, tribo::ArchardWear wear)
    : s_(settings), wear_(wear) {
  s_.validate();
  dz_ = s_.ring_width / s_.ring_cells;
  dx_ = (s_.liner_end - s_.liner_begin) / s_.liner_cells;
  ring_wear_.assign(s_.ring_cells, 0.0);
  liner_wear_ = std::make_shared<std::vector<double>>(s_.liner_cells, 0.0);
  if (s_.contact == FaceContact::Winkler) {
    stiffness_ = s_.foundation_modulus;
  } else {
    // Reference length w: the rigid-body constant of the half-plane only shifts the approach.
    compliance_ = symmetric_toeplitz(half_plane_influence_row(s_.ring_cells, dz_, s_.contact_modulus, s_.ring_width));
    const double lambda_min = smallest_eigenvalue_bound(compliance_);
    require(lambda_min > 0.0, "ring face: half-plane compliance not positive definite");
    stiffness_ = 1.0 / lambda_min;
  }
}

void RingLinerWear::share_liner(const RingLinerWear &other) {
  require(other.s_.liner_cells == s_.liner_cells && other.s_.liner_begin == s_.liner_begin &&
              other.s_.liner_end == s_.liner_end,
          "share_liner: the liner grids differ");
  liner_wear_ = other.liner_wear_;
}

double RingLinerWear::ring_cell_centre(int i) const { return -0.5 * s_.ring_width + (i + 0.5) * dz_; }
double RingLinerWear::liner_cell_centre(int j) const { return s_.liner_begin + (j + 0.5) * dx_; }

double RingLinerWear::step() const {
  if (s_.fixed_step > 0.0) return s_.fixed_step;
  if (law_) return law_factor_ > 0.0 ? s_.step_safety * 2.0 / (stiffness_ * law_factor_) : HUGE_VAL;
  return s_.step_safety * wear_.stable_slip_step(stiffness_);
}

void RingLinerWear::attach_state_law(std::shared_ptr<const coupling::StateLaw> law, coupling::OutOfRange policy,
                                     const std::optional<FilmSettings> &film) {
  const auto &w = law->table(coupling::StateField::WearRate).mean;
  law_factor_ = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i)
    for (double x : w[i]) law_factor_ = std::max(law_factor_, x / law->pressure()[i]);
  law_.emplace(std::move(law), policy, static_cast<std::size_t>(s_.ring_cells));
  if (film) law_->set_film(*film);
}

double RingLinerWear::mu_effective(double x_ring, double load) {
  const auto contact = pressure(x_ring, load);
  return law_->mu_effective(contact.pressure, std::vector<double>(contact.pressure.size(), dz_));
}

double RingLinerWear::peak_mu(double x_ring, double load) const {
  const auto contact = pressure(x_ring, load);
  return law_->peak_mu(contact.pressure, std::vector<double>(contact.pressure.size(), dz_));
}

template <typename Visit>
void RingLinerWear::for_each_overlap(double x_ring, Visit visit) const {
  const double left = x_ring - 0.5 * s_.ring_width;
  if (left < s_.liner_begin || left + s_.ring_width > s_.liner_end)
    throw std::out_of_range("ring at x = " + std::to_string(x_ring) + " m leaves the liner grid [" +
                            std::to_string(s_.liner_begin) + ", " + std::to_string(s_.liner_end) + "] m");
  for (int i = 0; i < s_.ring_cells; ++i) {
    const double a = left + i * dz_, b = a + dz_;
    int j = std::clamp(static_cast<int>(std::floor((a - s_.liner_begin) / dx_)), 0, s_.liner_cells - 1);
    for (; j < s_.liner_cells; ++j) {
      const double c = s_.liner_begin + j * dx_, d = c + dx_;
      if (c >= b) break;
      const double overlap = std::min(b, d) - std::max(a, c);
      if (overlap > 0.0) visit(i, j, overlap);
    }
  }
}

std::vector<double> RingLinerWear::gaps(double x_ring) const {
  std::vector<double> g(s_.ring_cells, 0.0);
  for_each_overlap(x_ring, [&](int i, int j, double overlap) { g[i] += (*liner_wear_)[j] * overlap / dz_; });
  for (int i = 0; i < s_.ring_cells; ++i) {
    const double z = 2.0 * ring_cell_centre(i) / s_.ring_width;
    g[i] += s_.crown_height * z * z + ring_wear_[i];
  }
  return g;
}

ContactPressure RingLinerWear::pressure(double x_ring, double load) const {
  const std::vector<double> g = gaps(x_ring);
  ContactPressure result;
  result.pressure.assign(g.size(), 0.0);
  const double line_load = std::abs(load) / (kPi * s_.bore);  // N/m of circumference
  if (line_load == 0.0) return result;
  if (s_.contact == FaceContact::HalfPlane) {
    const int n = s_.ring_cells;
    const Eigen::Map<const Eigen::VectorXd> gap0(g.data(), n);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(n);
    const double relief = gap0.maxCoeff() - gap0.minCoeff();
    const double tolerance = 1e-10 * std::max(relief, line_load * s_.ring_width / s_.contact_modulus);
    const LineContactResult r = solve_line_contact(compliance_, gap0, ones, dz_, line_load, tolerance, active_, &blocks_);
    if (!r.converged)
      throw std::runtime_error("ring-face contact: active set did not converge in " + std::to_string(r.iterations) +
                               " passes");
    double integral = 0.0;
    for (int i = 0; i < n; ++i) {
      const double p = r.pressure[i];
      result.pressure[i] = p;
      integral += p * dz_;
      result.peak = std::max(result.peak, p);
      if (p > 0.0) result.width += dz_;
    }
    result.mean = integral / result.width;
    return result;
  }
  // Water filling: with the m smallest gaps in contact, d = (q / (k_c dz) + sum g) / m.
  std::vector<double> sorted = g;
  std::sort(sorted.begin(), sorted.end());
  const double fill = line_load / (s_.foundation_modulus * dz_);
  double sum = 0.0, approach = 0.0;
  for (std::size_t m = 1; m <= sorted.size(); ++m) {
    sum += sorted[m - 1];
    approach = (fill + sum) / static_cast<double>(m);
    if (m == sorted.size() || approach <= sorted[m]) break;
  }
  double integral = 0.0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double p = s_.foundation_modulus * std::max(0.0, approach - g[i]);
    result.pressure[i] = p;
    integral += p * dz_;
    result.peak = std::max(result.peak, p);
    if (p > 0.0) result.width += dz_;
  }
  // Remove the round-off of the fill so that pi D sum p dz = W holds to the last bit it can.
  const double scale = line_load / integral;
  for (auto &p : result.pressure) p *= scale;
  result.peak *= scale;
  result.mean = line_load / result.width;
  return result;
}

std::vector<double> RingLinerWear::liner_pressure(double x_ring, double load) const {
  const ContactPressure contact = pressure(x_ring, load);
  std::vector<double> p(s_.liner_cells, 0.0);
  for_each_overlap(x_ring, [&](int i, int j, double overlap) { p[j] += contact.pressure[i] * overlap / dx_; });
  return p;
}

void RingLinerWear::update(double x_ring, double load, double ds, double dt) {
  const ContactPressure contact = pressure(x_ring, load);
  double ring_share = s_.ring_share, liner_share = 1.0 - s_.ring_share;
  std::vector<double> depth(contact.pressure.size()), liner_depth(contact.pressure.size());
  if (law_) {  // ring face by the law's wear rate, liner by its counterface rate
    auto inc = law_->advance(contact.pressure, ds, dt);
    depth = std::move(inc.body);
    liner_depth = std::move(inc.counterface);
    ring_share = liner_share = 1.0;
  } else {
    for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = wear_.depth_rate(contact.pressure[i]) * ds;
    liner_depth = depth;
  }
  double ring_deepest = 0.0, liner_deepest = 0.0;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    ring_wear_[i] += ring_share * depth[i];
    ring_deepest = std::max(ring_deepest, ring_wear_[i]);
  }
  for_each_overlap(x_ring, [&](int i, int j, double overlap) {
    auto &liner = *liner_wear_;
    liner[j] += liner_share * liner_depth[i] * overlap / dx_;
    liner_deepest = std::max(liner_deepest, liner[j]);
  });
  double added = 0.0;
  for (std::size_t i = 0; i < depth.size(); ++i) added += liner_depth[i];
  liner_volume_ += kPi * s_.bore * dz_ * liner_share * added;
  if (!law_) archard_volume_ += wear_.volume(load, ds);
  ++updates_;
  char buffer[200];
  if (s_.ring_thickness > 0.0 && ring_deepest > s_.ring_thickness) {
    status_ = RingLinerWearStatus::RingWornThrough;
    std::snprintf(buffer, sizeof buffer, "wear depth %.4g mm exceeds the ring's radial thickness %.4g mm",
                  1e3 * ring_deepest, 1e3 * s_.ring_thickness);
    message_ = buffer;
  } else if (s_.liner_wall > 0.0 && liner_deepest > s_.liner_wall) {
    status_ = RingLinerWearStatus::LinerWornThrough;
    std::snprintf(buffer, sizeof buffer, "wear depth %.4g mm exceeds the liner wall %.4g mm (ring at x = %.6g m)",
                  1e3 * liner_deepest, 1e3 * s_.liner_wall, x_ring);
    message_ = buffer;
  }
}

bool RingLinerWear::slide(double x_from, double x_to, double load_from, double load_to, double dt) {
  if (!ok()) return false;
  const double distance = std::abs(x_to - x_from);
  if (!(distance > 0.0)) return true;
  const double h = step();
  const double steps = std::ceil(distance / h);
  if (steps > 1e8)
    throw std::runtime_error("wear: " + std::to_string(steps) + " updates for one slide of " +
                             std::to_string(distance) + " m (stable wear step " + std::to_string(h) + " m)");
  const long n = std::max(1L, static_cast<long>(steps));
  const double ds = distance / static_cast<double>(n);
  for (long k = 0; k < n; ++k) {
    const double f = (k + 0.5) / static_cast<double>(n);  // midpoint of the sub-step
    update(x_from + f * (x_to - x_from), load_from + f * (load_to - load_from), ds, dt / static_cast<double>(n));
    if (!ok()) return false;
  }
  return true;
}

double RingLinerWear::ring_volume() const {
  return kPi * s_.bore * dz_ * std::accumulate(ring_wear_.begin(), ring_wear_.end(), 0.0);
}

double RingLinerWear::liner_volume() const { return liner_volume_; }

double RingLinerWear::shared_liner_volume() const {
  return kPi * s_.bore * dx_ * std::accumulate(liner_wear_->begin(), liner_wear_->end(), 0.0);
}

LineContactStress ring_face_stress(const RingLinerWear &wear, const std::vector<double> &pressure, double mu,
                                   const tribo::Material &liner, const tribo::Material &ring, int points) {
  std::vector<double> x(static_cast<std::size_t>(wear.settings().ring_cells));
  for (int i = 0; i < wear.settings().ring_cells; ++i) x[i] = wear.ring_cell_centre(i);
  return line_contact_stress(x, pressure, mu, liner, ring, points);
}

std::optional<LineContactStress> ring_face_hertz_stress(const RingLinerWearSettings &s, double load, double mu,
                                                        const tribo::Material &liner, const tribo::Material &ring,
                                                        int points) {
  if (!(s.crown_height > 0.0) || !(s.contact_modulus > 0.0) || !(load > 0.0)) return std::nullopt;
  const double radius = s.ring_width * s.ring_width / (8.0 * s.crown_height);
  const double per_length = load / (M_PI * s.bore);
  const double b = std::sqrt(4.0 * per_length * radius / (M_PI * s.contact_modulus));
  if (!(b < 0.5 * s.ring_width)) return std::nullopt;
  return hertz_line_contact_stress(2.0 * per_length / (M_PI * b), b, mu, liner, ring, 0.0, points);
}

}  // namespace runin::continuum
