#include "continuum/node_state_law.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <sstream>

namespace runin::continuum {

using coupling::OutOfRange;
using coupling::StateField;

NodeStateLaw::NodeStateLaw(std::shared_ptr<const coupling::StateLaw> law, OutOfRange policy, std::size_t nodes)
    : law_(std::move(law)), policy_(policy), h_(nodes, 0.0), c_(nodes, 0.0) {
  if (!law_) throw std::invalid_argument("node state law: no law");
  // Accuracy bound from the wear-rate table's steepest slope along h (the stiffness L of dh/ds = w(h)): L ds <= 0.05
  // keeps RK4's relative error near 1e-8 per e-folding, far inside its stability limit (L ds < 2.78).
  const auto &depth = law_->worn_depth();
  const auto &w = law_->table(StateField::WearRate).mean;
  double slope = 0.0;
  for (const auto &row : w)
    for (std::size_t j = 0; j + 1 < row.size(); ++j)
      slope = std::max(slope, std::abs(row[j + 1] - row[j]) / (depth[j + 1] - depth[j]));
  substep_ = slope > 0.0 ? 0.05 / slope : std::numeric_limits<double>::infinity();
}

double NodeStateLaw::substep(double h, double w, double ds_left) const {
  const auto &depth = law_->worn_depth();
  // the grid cell that holds h (the last one at its upper edge)
  const auto upper = std::upper_bound(depth.begin(), depth.end(), h);
  const std::size_t j = upper == depth.begin() ? 0 : std::min<std::size_t>(upper - depth.begin() - 1, depth.size() - 2);
  double step = std::min(ds_left, substep_);
  if (w > 0.0) step = std::min(step, (depth[j + 1] - depth[j]) / w);
  return step;
}

void NodeStateLaw::reset_state(std::vector<double> h) {
  if (h.size() != h_.size()) throw std::invalid_argument("node state law: state size mismatch");
  h_ = std::move(h);
}

void NodeStateLaw::set_film(const FilmSettings &settings, double counterface_duty) {
  if (!(counterface_duty > 0.0 && counterface_duty <= 1.0))
    throw std::invalid_argument("film: the counterface duty must be in (0, 1]");
  if (!law_->has(StateField::ContactFraction))
    throw std::invalid_argument("film: the state law has no contact_fraction field (the fraction of summits in contact "
                                "that the film kinetics need): rebuild it with runin homogenise");
  film_.emplace(settings, h_.size());
  counterface_duty_ = counterface_duty;
}

double NodeStateLaw::mu_effective(const std::vector<double> &pressure, const std::vector<double> &area) {
  if (pressure.size() != h_.size() || area.size() != h_.size())
    throw std::invalid_argument("node state law: pressure/area size mismatch");
  double weighted = 0.0, load = 0.0;
  for (std::size_t i = 0; i < h_.size(); ++i) {
    if (!(pressure[i] > 0.0)) continue;
    const double f = pressure[i] * area[i];
    double mu = law_->value(StateField::MuBody, law_->slice(pressure[i], policy_), h_[i], &use_);
    if (film_) mu *= film_->friction_factor(i);
    weighted += mu * f;
    load += f;
  }
  return load > 0.0 ? weighted / load : 0.0;
}

std::vector<double> NodeStateLaw::node_mu(const std::vector<double> &pressure) const {
  if (pressure.size() != h_.size()) throw std::invalid_argument("node state law: pressure size mismatch");
  std::vector<double> mu(h_.size(), 0.0);
  for (std::size_t i = 0; i < h_.size(); ++i)
    if (pressure[i] > 0.0)
      mu[i] = law_->value(StateField::MuBody, law_->slice(pressure[i], OutOfRange::Clamp), h_[i]) *
              (film_ ? film_->friction_factor(i) : 1.0);
  return mu;
}

double NodeStateLaw::peak_mu(const std::vector<double> &pressure, const std::vector<double> &area) const {
  if (pressure.size() != h_.size() || area.size() != h_.size())
    throw std::invalid_argument("node state law: pressure/area size mismatch");
  double weighted = 0.0, load = 0.0;
  for (std::size_t i = 0; i < h_.size(); ++i) {
    if (!(pressure[i] > 0.0)) continue;
    const auto slice = law_->slice(pressure[i], policy_);  // the Error policy throws here too
    double peak = 0.0;
    for (double h : law_->worn_depth()) peak = std::max(peak, law_->value(StateField::MuBody, slice, h));
    if (film_) peak *= film_->friction_factor(i);  // the static limit at the film's present coverage
    weighted += peak * pressure[i] * area[i];
    load += pressure[i] * area[i];
  }
  return load > 0.0 ? weighted / load : 0.0;
}

NodeStateLaw::Increment NodeStateLaw::advance(const std::vector<double> &pressure, double ds, double dt) {
  if (pressure.size() != h_.size()) throw std::invalid_argument("node state law: pressure size mismatch");
  if (!(std::isfinite(ds) && ds >= 0.0)) throw std::invalid_argument("node state law: slid distance must be >= 0");
  if (!(std::isfinite(dt) && dt >= 0.0)) throw std::invalid_argument("node state law: time step must be >= 0");
  Increment inc;
  inc.body.assign(h_.size(), 0.0);
  inc.counterface.assign(h_.size(), 0.0);
  // the film moves at the contact fractions of the step's start (it does not change the wear); at rest it only regrows
  std::vector<double> phi(film_ ? h_.size() : 0, 0.0);
  if (ds > 0.0) wear_nodes(pressure, ds, inc, phi);
  if (film_) film_->advance(phi, ds, dt, counterface_duty_);
  return inc;
}

void NodeStateLaw::wear_nodes(const std::vector<double> &pressure, double ds, Increment &inc,
                              std::vector<double> &phi) {
  constexpr long max_substeps = 100000000;
  constexpr long kCreepCheck = 1000;   // a node's sub-steps in one call before its creep is checked
  const auto &depth = law_->worn_depth();
  const double last_depth = depth.back();
  inc.substeps = 0;
  for (std::size_t i = 0; i < h_.size(); ++i) {
    const double p = pressure[i];
    if (!(p > 0.0)) continue;
    const coupling::StateLaw::PressureSlice slice = law_->slice(p, policy_);  // p is held over the step
    if (!phi.empty()) phi[i] = law_->value(StateField::ContactFraction, slice, h_[i]);
    double h = h_[i], c = 0.0, left = ds;
    long taken = 0;
    while (left > 0.0) {
      double w1, c1, w2, c2, w3, c3, w4, c4;
      law_->wear_rates(slice, h, &use_, w1, c1);
      if (h >= last_depth) {
        // beyond the law's last worn depth its values are held: the rates are constant, one read is exact
        h += left * w1;
        c += left * c1;
        break;
      }
      if (!(w1 > 0.0)) {
        // rates are >= 0, so a zero rate is a fixed point: h stays, the counterface wears at its rate there (it
        // stepped through the whole slide at the law's stiffness bound before: 1e8 sub-steps for 1 km)
        c += left * c1;
        break;
      }
      if (taken >= kCreepCheck) {
        // a node creeping towards a depth where its rate vanishes: done once the rest of the slide can move h by
        // less than 1e-12 of the cell (or a few ulps of h): at most the gap to a zero-rate upper edge (which it
        // cannot pass), else the rest at the larger of its rate and the edge's
        const auto upper = std::upper_bound(depth.begin(), depth.end(), h);
        const std::size_t j = std::min<std::size_t>(upper - depth.begin(), depth.size() - 1);
        double w_edge, c_edge;
        law_->wear_rates(slice, depth[j], nullptr, w_edge, c_edge);
        const double reach = w_edge > 0.0 ? left * std::max(w1, w_edge) : std::min(left * w1, depth[j] - h);
        if (reach <= 1e-12 * (depth[j] - depth[j - 1]) + 4.0 * std::numeric_limits<double>::epsilon() * depth[j]) {
          h += w_edge > 0.0 ? left * w1 : reach;
          c += left * (w_edge > 0.0 ? c1 : c_edge);   // creeping: the node sits at the edge for the rest
          break;
        }
      }
      // Classic RK4 on dh/ds = w(p, h) over a sub-step inside the node's own h-cell; the counterface depth is the
      // same quadrature of its rate.
      double step = substep(h, w1, left);
      if (left - step <= 1e-12 * ds) step = left;   // no sliver left over by round-off
      law_->wear_rates(slice, h + 0.5 * step * w1, &use_, w2, c2);
      law_->wear_rates(slice, h + 0.5 * step * w2, &use_, w3, c3);
      law_->wear_rates(slice, h + step * w3, &use_, w4, c4);
      h += step / 6.0 * (w1 + 2.0 * w2 + 2.0 * w3 + w4);
      c += step / 6.0 * (c1 + 2.0 * c2 + 2.0 * c3 + c4);
      left -= step;
      if (++taken > max_substeps)
        throw std::runtime_error("node state law: " + std::to_string(ds) + " m needs more than 1e8 sub-steps");
    }
    inc.substeps = static_cast<int>(std::max<long>(inc.substeps, taken));
    inc.body[i] = std::max(h - h_[i], 0.0);  // rates are >= 0: never un-wears
    inc.counterface[i] = std::max(c, 0.0);
    h_[i] += inc.body[i];
    c_[i] += inc.counterface[i];
  }
}

double NodeStateLaw::stable_contact_step(const std::vector<double> &pressure, double stiffness, double safety) {
  if (pressure.size() != h_.size()) throw std::invalid_argument("node state law: pressure size mismatch");
  double factor = 0.0;  // max w/p, 1/Pa
  const double p_min = law_->pressure().front(), p_max = law_->pressure().back();
  for (std::size_t i = 0; i < h_.size(); ++i)
    if (pressure[i] > 0.0)  // a clamped node's rate does not follow p: its secant is taken at the grid edge
      factor = std::max(factor, law_->value(StateField::WearRate, law_->slice(pressure[i], policy_), h_[i]) /
                                    std::clamp(pressure[i], p_min, p_max));
  if (!(factor > 0.0) || !(stiffness > 0.0)) return std::numeric_limits<double>::infinity();
  return safety * 2.0 / (stiffness * factor);
}

std::string describe(const coupling::RangeUse &use, const coupling::StateLaw &law) {
  std::ostringstream out;
  out.precision(4);
  out << use.lookups << " lookups: " << use.below_pressure << " clamped below p = " << law.pressure().front()
      << " Pa, " << use.above_pressure << " above p = " << law.pressure().back() << " Pa, " << use.beyond_depth
      << " beyond the last worn depth " << law.worn_depth().back() << " m (held)";
  return out.str();
}

std::string out_of_range_warning(const coupling::RangeUse &use, const coupling::StateLaw &law,
                                 coupling::OutOfRange policy) {
  const long outside = use.below_pressure + use.above_pressure;
  if (outside == 0) return {};
  std::ostringstream out;
  out.precision(4);
  out << "WARNING: " << outside << " of " << use.lookups << " state-law lookups were outside the law's pressure range ("
      << use.below_pressure << " below " << law.pressure().front() << " Pa, " << use.above_pressure << " above "
      << law.pressure().back() << " Pa; friction.out_of_range = \"" << coupling::to_string(policy) << "\"): ";
  if (policy == coupling::OutOfRange::Archard)
    out << "friction and surface state taken at the nearest grid pressure, wear rates proportional to p";
  else
    out << "clamped to the nearest grid pressure, wear rates included, which breaks Archard's law there "
           "(\"archard\" keeps them proportional to p)";
  return out.str();
}

}  // namespace runin::continuum
