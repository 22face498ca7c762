#include "continuum/axisymmetric_contact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace runin::continuum {
namespace {
void require(bool ok, const std::string &what) {
  if (!ok) throw std::invalid_argument(what);
}

// Surface displacement at r under unit pressure on a disk of radius a, times pi E* / 4.
double disk_displacement(double a, double r) {
  if (a <= 0.0) return 0.0;
  if (r <= a) return a * std::comp_ellint_2(r / a);
  const double k = a / r;
  return r * (std::comp_ellint_2(k) - (1.0 - k * k) * std::comp_ellint_1(k));
}
}  // namespace

AxisymmetricContact::AxisymmetricContact(double grid_radius, int rings, double effective_modulus)
    : n_(rings), h_(grid_radius / rings), e_star_(effective_modulus) {
  require(std::isfinite(grid_radius) && grid_radius > 0.0, "contact grid radius must be positive");
  require(rings >= 2 && rings <= 8192, "contact rings must be in [2, 8192]");
  require(std::isfinite(effective_modulus) && effective_modulus > 0.0, "effective modulus must be positive");
  c_.resize(n_, n_);
  const double scale = 4.0 / (M_PI * e_star_);
  for (int i = 0; i < n_; ++i) {
    const double r = ring_radius(i);
    double inner = 0.0;
    for (int j = 0; j < n_; ++j) {
      const double outer = disk_displacement((j + 1) * h_, r);
      c_(i, j) = scale * (outer - inner);
      inner = outer;
    }
  }
}

double AxisymmetricContact::ring_area(int i) const { return M_PI * (2.0 * i + 1.0) * h_ * h_; }

const std::vector<int> &AxisymmetricContact::prepare(const std::vector<int> &active) {
  constexpr std::size_t max_extra = 32;  // beyond this a fresh LU is cheaper than the Schur block
  std::vector<bool> in_base(n_, false);
  for (int i : base_) in_base[i] = true;
  std::vector<int> extra;
  std::size_t covered = 0;
  for (int i : active) {
    if (in_base[i])
      ++covered;
    else
      extra.push_back(i);
  }
  if (base_.empty() || covered != base_.size() || extra.size() > max_extra) {
    base_ = active;
    const int m = static_cast<int>(base_.size());
    Eigen::MatrixXd block(m, m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) block(a, b) = c_(base_[a], base_[b]);
    lu_.compute(block);
    stiffness_ = -1.0;
    extra.clear();
  }
  if (extra != extra_ || extra.empty()) {
    extra_ = extra;
    const int m = static_cast<int>(base_.size()), e = static_cast<int>(extra_.size());
    if (e > 0) {
      Eigen::MatrixXd c_be(m, e), c_eb(e, m), c_ee(e, e);
      for (int k = 0; k < e; ++k) {
        for (int a = 0; a < m; ++a) {
          c_be(a, k) = c_(base_[a], extra_[k]);
          c_eb(k, a) = c_(extra_[k], base_[a]);
        }
        for (int l = 0; l < e; ++l) c_ee(k, l) = c_(extra_[k], extra_[l]);
      }
      z_ = lu_.solve(c_be);
      schur_lu_.compute(c_ee - c_eb * z_);
      c_eb_ = std::move(c_eb);
    }
  }
  order_ = base_;
  order_.insert(order_.end(), extra_.begin(), extra_.end());
  return order_;
}

Eigen::VectorXd AxisymmetricContact::solve_ordered(const Eigen::VectorXd &b) const {
  const int m = static_cast<int>(base_.size()), e = static_cast<int>(extra_.size());
  Eigen::VectorXd x(m + e);
  const Eigen::VectorXd xb = lu_.solve(b.head(m));
  if (e == 0) return xb;
  const Eigen::VectorXd xe = schur_lu_.solve(b.tail(e) - c_eb_ * xb);
  x.head(m) = xb - z_ * xe;
  x.tail(e) = xe;
  return x;
}

ContactSolution AxisymmetricContact::solve(const std::vector<double> &gap0, double load) {
  require(static_cast<int>(gap0.size()) == n_, "gap0 must have one value per ring");
  require(std::isfinite(load) && load > 0.0, "contact load must be positive");
  ContactSolution s;
  s.pressure.assign(n_, 0.0);
  const double g_scale = *std::max_element(gap0.begin(), gap0.end()) - *std::min_element(gap0.begin(), gap0.end());
  std::vector<int> active = active_;
  if (active.empty()) active = {static_cast<int>(std::min_element(gap0.begin(), gap0.end()) - gap0.begin())};

  const int max_iterations = 4 * n_ + 20;
  for (s.iterations = 1; s.iterations <= max_iterations; ++s.iterations) {
    active = prepare(active);
    const int m = static_cast<int>(active.size());
    Eigen::VectorXd ones = Eigen::VectorXd::Ones(m), rhs(m), area(m);
    for (int a = 0; a < m; ++a) {
      rhs[a] = -gap0[active[a]];
      area[a] = ring_area(active[a]);
    }
    const Eigen::VectorXd x = solve_ordered(ones), y = solve_ordered(rhs);
    const double delta = (load - area.dot(y)) / area.dot(x);
    const Eigen::VectorXd p = y + delta * x;

    std::vector<int> kept;
    for (int a = 0; a < m; ++a)
      if (p[a] >= 0.0) kept.push_back(active[a]);
    if (kept.empty()) kept.push_back(active[std::max_element(p.data(), p.data() + m) - p.data()]);
    if (static_cast<int>(kept.size()) < m) {  // tension somewhere: release it
      active = kept;
      continue;
    }
    // Penetration outside the active set?
    std::vector<bool> in(n_, false);
    for (int i : active) in[i] = true;
    const double tolerance = 1e-10 * (g_scale + std::abs(delta));
    std::vector<int> grown = active;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n_);
    for (int a = 0; a < m; ++a) u += c_.col(active[a]) * p[a];  // column access: contiguous
    for (int i = 0; i < n_; ++i)
      if (!in[i] && gap0[i] - delta + u[i] < -tolerance) grown.push_back(i);
    if (grown.size() > active.size()) {
      std::sort(grown.begin(), grown.end());
      active = grown;
      continue;
    }
    active_ = active;
    for (int a = 0; a < m; ++a) s.pressure[active[a]] = p[a];
    s.approach = delta;
    s.converged = true;
    break;
  }
  if (!s.converged) {
    s.message = "active-set iteration did not converge in " + std::to_string(max_iterations) + " iterations";
    active_.clear();
    return s;
  }
  int outermost = 0;
  for (int i = 0; i < n_; ++i)
    if (s.pressure[i] > 0.0) outermost = i;
  s.contact_radius = (outermost + 1) * h_;
  s.peak_pressure = *std::max_element(s.pressure.begin(), s.pressure.end());
  s.mean_pressure = load / (M_PI * s.contact_radius * s.contact_radius);
  if (outermost == n_ - 1) {
    s.converged = false;
    s.message = "contact reaches the edge of the grid (radius " + std::to_string(grid_radius()) + " m)";
  }
  return s;
}

double AxisymmetricContact::active_stiffness() {
  require(!base_.empty(), "active_stiffness needs a solved contact");
  if (stiffness_ > 0.0) return stiffness_;
  // Power iteration on the inverse base block (the active set less its last few added rings:
  // adding rings raises the value by a little, well inside the step safety factor). The
  // dominant mode alternates ring by ring; the previous mode is the warm start.
  const int m = static_cast<int>(base_.size());
  Eigen::VectorXd v(m);
  for (int a = 0; a < m; ++a) v[a] = a < mode_.size() ? mode_[a] : ((a % 2 == 0) ? 1.0 : -1.0);
  v.normalize();
  double lambda = 0.0;
  for (int k = 0; k < 100; ++k) {
    Eigen::VectorXd w = lu_.solve(v);
    const double next = w.norm();
    v = w / next;
    if (std::abs(next - lambda) <= 1e-6 * next) {
      lambda = next;
      break;
    }
    lambda = next;
  }
  stiffness_ = lambda;
  mode_ = v;
  return stiffness_;
}

double HertzSolution::pressure(double r) const {
  return r < contact_radius ? peak_pressure * std::sqrt(1.0 - (r / contact_radius) * (r / contact_radius)) : 0.0;
}

HertzSolution hertz_sphere_on_flat(double sphere_radius, double effective_modulus, double load) {
  HertzSolution h;
  h.contact_radius = std::cbrt(3.0 * load * sphere_radius / (4.0 * effective_modulus));
  h.peak_pressure = 3.0 * load / (2.0 * M_PI * h.contact_radius * h.contact_radius);
  h.approach = h.contact_radius * h.contact_radius / sphere_radius;
  return h;
}

double suggested_grid_radius(double tip_radius, double effective_modulus, double load,
                             const tribo::ArchardWear *wear, double sliding_distance) {
  const double hertz = hertz_sphere_on_flat(tip_radius, effective_modulus, load).contact_radius;
  const double volume = wear ? wear->volume(load, sliding_distance) : 0.0;
  const double worn = std::pow(4.0 * tip_radius * volume / M_PI, 0.25);
  return 1.5 * std::max(hertz, worn);
}

PinWear::PinWear(const PinWearParameters &parameters, tribo::ArchardWear wear, double load)
    : p_(parameters), wear_(wear), load_(load),
      contact_(parameters.grid_radius, parameters.rings, parameters.effective_modulus) {
  require(std::isfinite(p_.tip_radius) && p_.tip_radius > 0.0, "pin tip radius must be positive");
  require(std::isfinite(p_.step_safety) && p_.step_safety > 0.0 && p_.step_safety <= 1.0,
          "wear step safety must be in (0, 1]");
  require(std::isfinite(load) && load > 0.0, "normal load must be positive");
  depth_.assign(p_.rings, 0.0);
  if (!resolve()) throw std::invalid_argument("pin contact: " + message_);
}

double PinWear::profile_height(int i) const {
  const double r = contact_.ring_radius(i);
  return r * r / (2.0 * p_.tip_radius) + depth_[i];
}

bool PinWear::resolve() {
  std::vector<double> gap0(p_.rings);
  for (int i = 0; i < p_.rings; ++i) gap0[i] = profile_height(i);
  solution_ = contact_.solve(gap0, load_);
  if (!solution_.converged) message_ = solution_.message;
  return solution_.converged;
}

bool PinWear::step(double distance) {
  require(std::isfinite(distance) && distance >= 0.0, "wear step must be >= 0");
  for (int i = 0; i < p_.rings; ++i) depth_[i] += wear_.depth_rate(solution_.pressure[i]) * distance;
  slid_ += distance;
  ++steps_;
  return resolve();
}

bool PinWear::apply(const std::vector<double> &increment, double distance) {
  require(increment.size() == depth_.size(), "wear increment size must equal the ring count");
  require(std::isfinite(distance) && distance >= 0.0, "wear step must be >= 0");
  for (int i = 0; i < p_.rings; ++i) depth_[i] += increment[i];
  slid_ += distance;
  ++steps_;
  return resolve();
}

double PinWear::stable_step() {
  return p_.step_safety * wear_.stable_slip_step(contact_.active_stiffness());
}

bool PinWear::advance(double distance) {
  require(std::isfinite(distance) && distance >= 0.0, "slid distance must be >= 0");
  double remaining = distance;
  while (remaining > 0.0) {
    if (steps_ >= p_.max_steps) {
      message_ = "more than " + std::to_string(p_.max_steps) + " wear updates (stable step " +
                 std::to_string(stable_step()) + " m); lower wear.k or contact.rings, or raise wear.max_steps";
      return false;
    }
    const double ds = std::min(remaining, stable_step());
    // The last sub-step may be a sliver; merge it instead of spending a solve on it.
    const double take = remaining - ds < 1e-9 * distance ? remaining : ds;
    if (!step(take)) return false;
    remaining -= take;
  }
  return true;
}

double PinWear::wear_volume() const {
  double v = 0.0;
  for (int i = 0; i < p_.rings; ++i) v += contact_.ring_area(i) * depth_[i];
  return v;
}

DiskTrackWear::DiskTrackWear(tribo::ArchardWear wear, double track_radius)
    : wear_(wear), circumference_(2.0 * M_PI * track_radius) {
  require(std::isfinite(track_radius) && track_radius > 0.0, "disk track radius must be positive");
}

void DiskTrackWear::slide(double load, double distance, double contact_width) {
  require(std::isfinite(distance) && distance >= 0.0, "disk slide distance must be >= 0");
  require(std::isfinite(contact_width) && contact_width >= 0.0, "disk contact width must be >= 0");
  volume_ += wear_.volume(load, distance);
  slid_ += distance;
  width_ = std::max(width_, contact_width);
}

void DiskTrackWear::slide_volume(double volume, double distance, double contact_width) {
  require(std::isfinite(volume) && volume >= 0.0, "disk worn volume must be >= 0");
  require(std::isfinite(distance) && distance >= 0.0, "disk slide distance must be >= 0");
  require(std::isfinite(contact_width) && contact_width >= 0.0, "disk contact width must be >= 0");
  volume_ += volume;
  slid_ += distance;
  width_ = std::max(width_, contact_width);
}

double DiskTrackWear::worn_length() const { return std::min(slid_, circumference_); }

double DiskTrackWear::depth() const {
  const double area = worn_length() * width_;
  return area > 0.0 ? volume_ / area : 0.0;
}

double DiskTrackWear::passes() const { return slid_ / circumference_; }

}  // namespace runin::continuum
