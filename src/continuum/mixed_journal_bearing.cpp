#include "continuum/mixed_journal_bearing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "tribo/contact.h"   // InvalidCoefficient
#include "tribo/flow_factors.h"
#include "tribo/greenwood_tripp.h"

namespace runin::continuum {

using tribo::InvalidCoefficient;
using tribo::require_positive_finite;

namespace {

const double kPi = std::acos(-1.0);


}    // namespace

// ---------------------------------------------------------------------------------------------------
double MixedJournalBearingParameters::speed_at(double t) const
{
  if (speed_time.empty()) return speed;
  if (t <= speed_time.front()) return speed_value.front();
  if (t >= speed_time.back()) return speed_value.back();
  const auto it = std::upper_bound(speed_time.begin(), speed_time.end(), t);
  const std::size_t k = static_cast<std::size_t>(it - speed_time.begin());
  const double w = (t - speed_time[k - 1]) / (speed_time[k] - speed_time[k - 1]);
  return (1.0 - w) * speed_value[k - 1] + w * speed_value[k];
}

void MixedJournalBearingParameters::validate() const
{
  require_positive_finite(radius, "radius");
  require_positive_finite(length, "length");
  require_positive_finite(clearance, "clearance");
  require_positive_finite(load, "load");
  require_positive_finite(viscosity, "viscosity");
  if (!(supply_pressure >= 0.0) || !std::isfinite(supply_pressure))
    throw InvalidCoefficient("supply_pressure must be >= 0 and finite, got " + std::to_string(supply_pressure));
  if (!std::isfinite(groove_angle)) throw InvalidCoefficient("groove_angle must be finite");
  if (speed_time.empty()) {
    require_positive_finite(speed, "speed");
  } else {
    if (speed_time.size() != speed_value.size() || speed_time.size() < 2)
      throw InvalidCoefficient("speed_time, speed_value: a table of >= 2 points of equal length");
    for (std::size_t k = 0; k < speed_time.size(); ++k) {
      if (!std::isfinite(speed_time[k]) || (k > 0 && !(speed_time[k] > speed_time[k - 1])))
        throw InvalidCoefficient("speed_time must be finite and increase strictly");
      require_positive_finite(speed_value[k], "speed_value");
    }
  }
  if (n_theta < 8) throw InvalidCoefficient("n_theta: at least 8 circumferential nodes needed");
  if (n_axial < 3) throw InvalidCoefficient("n_axial: at least 3 axial nodes needed (both ends included)");
  require_positive_finite(summit_density, "summit_density");
  require_positive_finite(summit_radius, "summit_radius");
  require_positive_finite(effective_modulus, "effective_modulus");
  if (!law) throw InvalidCoefficient("law: the state law is required");
  if (!(sigma_override >= 0.0) || !std::isfinite(sigma_override))
    throw InvalidCoefficient("sigma_override must be >= 0 and finite");
  if (flow_factors) tribo::pressure_flow_factor_x(1.0, gamma);   // range check of gamma
}

void asperity_statistics_from_law(const coupling::StateLaw &law, double &summit_density, double &summit_radius)
{
  const auto &m = law.metadata();
  const auto surface = m.find("surface");
  const auto number = [&](const char *key) {
    if (surface == m.end() || !surface->is_object() || !surface->contains(key) || !(*surface)[key].is_number())
      throw std::invalid_argument(std::string("a law without the statistics mixed lubrication needs: metadata "
                                              "surface.") + key + " is missing (surface.R: summit radius, "
                                              "surface.spacing: summit spacing, as runin homogenise writes them)");
    const double v = (*surface)[key].get<double>();
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("a law without the statistics mixed lubrication needs: metadata "
                                              "surface.") + key + " must be positive");
    return v;
  };
  summit_radius = number("R");
  const double spacing = number("spacing");
  summit_density = 1.0 / (spacing * spacing);
}

const char *to_string(MixedStatus status)
{
  switch (status) {
  case MixedStatus::Converged: return "converged";
  case MixedStatus::GapCloses: return "the gap closes";
  case MixedStatus::FilmFailed: return "film solve failed";
  case MixedStatus::NotConverged: return "not converged";
  }
  return "?";
}

const char *to_string(MixedRunStatus status)
{
  switch (status) {
  case MixedRunStatus::Finished: return "finished";
  case MixedRunStatus::EquilibriumFailed: return "equilibrium failed";
  case MixedRunStatus::TooManySteps: return "too many steps";
  case MixedRunStatus::LawOutOfRange: return "state law out of range";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------------
MixedJournalBearingSystem::MixedJournalBearingSystem(MixedJournalBearingParameters parameters)
    : p_(std::move(parameters))
{
  p_.validate();
}

double MixedJournalBearingSystem::node_area() const { return p_.radius * (2.0 * kPi / p_.n_theta) * p_.length; }

double MixedJournalBearingSystem::bore_angle(int i) const { return i * 2.0 * kPi / p_.n_theta; }

MixedWearState MixedJournalBearingSystem::initial_state() const
{
  MixedWearState s;
  s.bore.assign(static_cast<std::size_t>(p_.n_theta), 0.0);
  s.asperity_pressure.assign(static_cast<std::size_t>(p_.n_theta), 0.0);
  return s;
}

std::vector<double> MixedJournalBearingSystem::node_sigma(const MixedWearState &state, coupling::RangeUse *use) const
{
  const int n = p_.n_theta;
  std::vector<double> sigma(static_cast<std::size_t>(n));
  if (p_.sigma_override > 0.0) {
    std::fill(sigma.begin(), sigma.end(), p_.sigma_override);
    return sigma;
  }
  const auto &law = *p_.law;
  for (int i = 0; i < n; ++i) {
    // the law's rq at the node's last asperity pressure (no contact yet: the law's lowest pressure, which is
    // where a clamped or Archard lookup of a light contact takes its surface state anyway)
    const double pa = state.asperity_pressure.empty() ? 0.0 : state.asperity_pressure[i];
    const double p = pa > 0.0 ? pa : law.pressure().front();
    // cut summits keep the unworn spread below the cut: the law's rq at h = 0
    const bool unworn = p_.worn_surface == WornSurface::TruncatedSummits;
    const double body =
        law.value(coupling::StateField::Rq, p, unworn ? 0.0 : state.bore[i], coupling::Band::Mean, p_.policy, use);
    const double journal =
        p_.counterface_rough
            ? law.value(coupling::StateField::Rq, p, unworn ? 0.0 : state.shaft, coupling::Band::Mean, p_.policy, use)
            : 0.0;
    sigma[i] = std::hypot(body, journal);
  }
  return sigma;
}

std::vector<double> MixedJournalBearingSystem::node_top(const MixedWearState &state,
                                                        const std::vector<double> &sigma) const
{
  std::vector<double> top(sigma.size(), HUGE_VAL);
  if (p_.worn_surface != WornSurface::TruncatedSummits) return top;
  for (std::size_t i = 0; i < sigma.size(); ++i)
    if (sigma[i] > 0.0)
      top[i] = tribo::GreenwoodTripp(p_.summit_density, p_.summit_radius, sigma[i], p_.effective_modulus)
                   .top_after_wear(state.bore[i] + state.shaft);
  return top;
}

std::vector<double> MixedJournalBearingSystem::node_rms(const std::vector<double> &sigma,
                                                        const std::vector<double> &top) const
{
  std::vector<double> rms(sigma.size());
  for (std::size_t i = 0; i < sigma.size(); ++i)
    rms[i] = top[i] == HUGE_VAL || !(sigma[i] > 0.0) ? sigma[i] : sigma[i] * tribo::truncated_rms_ratio(top[i] / sigma[i]);
  return rms;
}

HydroJournalBearing MixedJournalBearingSystem::film_bearing(const MixedWearState &state, const std::vector<double> &sigma,
                                                            double speed, double eccentricity, double attitude) const
{
  HydroJournalBearing b;
  b.radius = p_.radius;
  b.length = p_.length;
  b.clearance = p_.clearance;
  b.viscosity = p_.viscosity;
  b.omega = speed / p_.radius;
  b.eccentricity_ratio = eccentricity;
  b.groove_angle = p_.groove_angle;
  b.supply_pressure = p_.supply_pressure;
  b.n_theta = p_.n_theta;
  b.n_axial = p_.n_axial;
  b.line_of_centres = attitude + kPi;   // the largest gap is opposite the approach
  b.gap_addition.resize(state.bore.size());
  for (std::size_t i = 0; i < state.bore.size(); ++i) b.gap_addition[i] = state.bore[i] + state.shaft;
  // The surfaces' split (V_r of the shear terms): the journal moves, the bore is at rest; the size per node.
  b.roughness.sigma_moving = p_.counterface_rough ? 1.0 : 0.0;
  b.roughness.sigma_fixed = 1.0;
  b.roughness.gamma = p_.gamma;
  b.roughness.flow_factors = p_.flow_factors;
  if (p_.flow_factors) b.node_sigma = sigma;
  return b;
}

MixedJournalBearingSystem::NodeSurface MixedJournalBearingSystem::node_surface(const MixedWearState &state) const
{
  NodeSurface s;
  s.sigma = node_sigma(state);
  s.top = node_top(state, s.sigma);
  s.rms = node_rms(s.sigma, s.top);
  return s;
}

MixedEquilibrium MixedJournalBearingSystem::evaluate(const MixedWearState &state, double speed, double eccentricity,
                                                     double attitude, const std::vector<double> *initial) const
{
  return evaluate(state, node_surface(state), speed, eccentricity, attitude, initial);
}

MixedEquilibrium MixedJournalBearingSystem::evaluate(const MixedWearState &state, const NodeSurface &surface,
                                                     double speed, double eccentricity, double attitude,
                                                     const std::vector<double> *initial) const
{
  const int n = p_.n_theta;
  MixedEquilibrium e;
  e.eccentricity = eccentricity;
  e.attitude = attitude;
  const std::vector<double> &sigma = surface.sigma;
  e.top = surface.top;
  e.sigma = surface.rms;
  const HydroJournalBearing b = film_bearing(state, e.sigma, speed, eccentricity, attitude);
  e.film = solve_journal_bearing(b, nullptr, ReynoldsSolver(), initial);
  e.film_solves = 1;
  if (!e.film.film.ok()) {
    e.status = MixedStatus::FilmFailed;
    e.message = std::string("Reynolds solve: ") + to_string(e.film.film.status);
    return e;
  }
  const auto &pressure = e.film.film.pressure;
  const int ny = p_.n_axial;
  const double dth = 2.0 * kPi / n, dx = p_.radius * dth, dy = p_.length / (ny - 1);
  // S = sum p r(alpha) A: the pressure resultant, which must equal W along the load line (alpha = 0)
  double fx = 0.0, fy = 0.0, ax = 0.0, ay = 0.0;
  e.gap.resize(static_cast<std::size_t>(n));
  e.asperity_pressure.assign(static_cast<std::size_t>(n), 0.0);
  e.mu_body.assign(static_cast<std::size_t>(n), 0.0);
  const double area = node_area();
  e.h_min = HUGE_VAL;
  int i_min = 0;
  for (int i = 0; i < n; ++i) {
    const double a = bore_angle(i), ca = std::cos(a), sa = std::sin(a);
    double column = 0.0;
    for (int j = 0; j < ny; ++j) column += ((j == 0 || j == ny - 1) ? 0.5 : 1.0) * pressure[i + n * j];
    fx += column * ca * dx * dy;
    fy += column * sa * dx * dy;
    const double g = b.clearance * (1.0 + eccentricity * std::cos(a - b.line_of_centres)) + b.gap_addition[i];
    e.gap[i] = g;
    if (g < e.h_min) e.h_min = g, i_min = i;
    double pa = 0.0;
    if (sigma[i] > 0.0) {
      const tribo::GreenwoodTripp summits(p_.summit_density, p_.summit_radius, sigma[i], p_.effective_modulus);
      // cut summits stand on the unworn mean plane, which the worn volume has not moved
      pa = e.top[i] == HUGE_VAL ? summits.pressure(g) : summits.pressure(g - b.gap_addition[i], e.top[i]);
    }
    e.asperity_pressure[i] = pa;
    if (pa > 0.0) {
      ax += pa * ca * area;
      ay += pa * sa * area;
      e.mu_body[i] = p_.law->value(coupling::StateField::MuBody, pa, state.bore[i], coupling::Band::Mean, p_.policy);
      e.boundary_friction += e.mu_body[i] * pa * area;
      e.peak_asperity_pressure = std::max(e.peak_asperity_pressure, pa);
    }
  }
  e.film_load = fx;
  e.asperity_load = ax;
  e.perpendicular_load = fy + ay;
  e.lambda = e.sigma[i_min] > 0.0 ? e.h_min / e.sigma[i_min] : HUGE_VAL;
  double wa = 0.0, ws = 0.0;
  for (int i = 0; i < n; ++i) {
    wa += e.asperity_pressure[i];
    ws += e.asperity_pressure[i] * e.sigma[i];
  }
  e.sigma_contact = wa > 0.0 ? ws / wa : e.sigma[i_min];
  e.viscous_friction = e.film.friction_force;
  e.peak_film_pressure = e.film.peak_pressure;
  e.cavitated_fraction = e.film.cavitated_fraction;
  e.status = MixedStatus::Converged;
  return e;
}

namespace {

// Fills the load-referred numbers of a balanced state.
void finish(MixedEquilibrium &e, const MixedJournalBearingParameters &p, double speed)
{
  const double W = p.load;
  e.asperity_share = e.asperity_load / W;
  e.mu_viscous = e.viscous_friction / W;
  e.mu_boundary = e.boundary_friction / W;
  e.mu = e.mu_viscous + e.mu_boundary;
  const double n_rev = speed / p.radius / (2.0 * kPi);
  e.hersey = p.viscosity * n_rev / p.mean_pressure();
  e.sommerfeld = (p.radius / p.clearance) * (p.radius / p.clearance) * e.hersey;
}

std::vector<double> pattern(const MixedEquilibrium &e)
{
  const auto &sol = e.film.film;
  std::vector<double> u(sol.pressure.size());
  for (std::size_t k = 0; k < u.size(); ++k) u[k] = sol.pressure[k] - (1.0 - sol.fill[k]);
  return u;
}

}    // namespace


double MixedJournalBearingSystem::closing_eccentricity(const MixedWearState &state, double attitude) const
{
  double eps_close = HUGE_VAL;
  for (int i = 0; i < p_.n_theta; ++i) {
    const double ca = std::cos(bore_angle(i) - attitude);
    if (ca > 0.0) eps_close = std::min(eps_close, (p_.clearance + state.bore[i] + state.shaft) / (p_.clearance * ca));
  }
  return eps_close;
}

namespace {

// The balance solve's film evaluations at (eps, attitude): each warm-started from the last good film pattern,
// counted; the first failure is kept (the solve stops with it).
struct BalanceEvaluations {
  BalanceEvaluations(const MixedJournalBearingSystem &s, const MixedWearState &w, double u, std::vector<double> guess)
      : sys(s), state(w), surface(s.node_surface(w)), speed(u), initial(std::move(guess)) {}
  const MixedJournalBearingSystem &sys;
  const MixedWearState &state;
  const MixedJournalBearingSystem::NodeSurface surface;   // one state: its roughness and cut once
  double speed;
  std::vector<double> initial;
  int solves = 0;
  MixedEquilibrium failure;
  bool failed = false;

  MixedEquilibrium operator()(double eps, double att) {
    MixedEquilibrium e = sys.evaluate(state, surface, speed, eps, att, initial.empty() ? nullptr : &initial);
    ++solves;
    if (e.ok()) initial = pattern(e);
    else if (!failed) failed = true, failure = e;
    return e;
  }
  MixedEquilibrium give_up(MixedEquilibrium e, MixedStatus status, const std::string &message) const {
    e.status = status;
    e.message = message;
    e.film_solves = solves;
    return e;
  }
  MixedEquilibrium give_up_failure() const { return give_up(failure, failure.status, failure.message); }
  // (load balance, perpendicular force) relative to W
  void residual(const MixedEquilibrium &e, double r[2]) const {
    const double W = sys.parameters().load;
    r[0] = (e.film_load + e.asperity_load - W) / W;
    r[1] = e.perpendicular_load / W;
  }
};

// Cold start: along the load line (attitude 0), the eccentricity at which film + asperities carry W
// (solve_load_share on the control gap h = c (1 - eps)); then Newton turns the resultant onto the load line.
// Sets x = (eps, 0) and returns the state there; `done` when that is the answer already (a failure).
MixedEquilibrium cold_start(BalanceEvaluations &eval, double x[2], bool &done) {
  const auto &sys = eval.sys;
  const double W = sys.parameters().load, c = sys.parameters().clearance;
  const double eps_top = sys.closing_eccentricity(eval.state, 0.0) * (1.0 - 1e-6);
  std::map<double, MixedEquilibrium> memo;
  auto at = [&](double h) -> const MixedEquilibrium & {
    auto it = memo.find(h);
    if (it != memo.end()) return it->second;
    return memo.emplace(h, eval(1.0 - h / c, 0.0)).first->second;
  };
  const double sigma_ref = std::max(1e-12, sys.node_sigma(eval.state).front());
  const auto share = tribo::solve_load_share(
      W, [&](double h) { return at(h).film_load; },
      [&](double h) { return at(h).asperity_load; }, sigma_ref, c * (1.0 - eps_top), c, 1e-6);
  done = true;
  if (eval.failed) return eval.give_up_failure();
  if (share.status == tribo::LoadShareStatus::NotBracketed) {
    // also with the resultant turned freely: the largest load the surfaces carry before they touch is below W
    std::ostringstream m;
    m.precision(6);
    m << "film and asperities carry only " << share.film_load + share.asperity_load << " N of W = " << W
      << " N before the gap closes (eccentricity " << 1.0 - share.h / c << ")";
    return eval.give_up(at(share.h), MixedStatus::GapCloses, m.str());
  }
  done = false;
  x[0] = 1.0 - share.h / c;
  x[1] = 0.0;
  return at(share.h);
}

// Backtracking along the Newton step dx: the gap must stay open, the residual must fall. Returns whether a step
// was accepted (then lambda, the trial state and its residual rt).
bool line_search(BalanceEvaluations &eval, const double x[2], const double dx[2], const double r[2], double &lambda,
                 MixedEquilibrium &trial, double rt[2]) {
  const double norm = std::hypot(r[0], r[1]);
  lambda = 1.0;
  for (int k = 0; k < 30; ++k, lambda *= 0.5) {
    const double e1 = x[0] + lambda * dx[0], a1 = x[1] + lambda * dx[1];
    if (!(e1 >= 0.0) || !(e1 < eval.sys.closing_eccentricity(eval.state, a1) * (1.0 - 1e-9))) continue;
    trial = eval(e1, a1);
    if (eval.failed) return false;
    eval.residual(trial, rt);
    if (std::hypot(rt[0], rt[1]) < (1.0 - 1e-4 * lambda) * norm) return true;
  }
  return false;
}

// Broyden update of the Jacobian J after the step s with residual change y.
void broyden(double J[4], double sx0, double sx1, double y0, double y1) {
  const double ss = sx0 * sx0 + sx1 * sx1;
  if (!(ss > 0.0)) return;
  const double u0 = y0 - (J[0] * sx0 + J[1] * sx1), u1 = y1 - (J[2] * sx0 + J[3] * sx1);
  J[0] += u0 * sx0 / ss, J[1] += u0 * sx1 / ss;
  J[2] += u1 * sx0 / ss, J[3] += u1 * sx1 / ss;
}

}    // namespace

MixedEquilibrium MixedJournalBearingSystem::equilibrium(const MixedWearState &state, double speed,
                                                        const MixedEquilibrium *guess, double rel_tol) const
{
  BalanceEvaluations eval(*this, state, speed,
                          guess && !guess->film.film.pressure.empty() ? pattern(*guess) : std::vector<double>());
  double x[2], J[4];
  bool have_jacobian = false, fresh_jacobian = false;
  MixedEquilibrium cur;
  if (guess && guess->jacobian_valid) {
    x[0] = guess->eccentricity;
    x[1] = guess->attitude;
    std::copy(guess->jacobian, guess->jacobian + 4, J);
    have_jacobian = true;
    cur = eval(x[0], x[1]);
  } else {
    bool done = false;
    cur = cold_start(eval, x, done);
    if (done) return cur;
  }
  if (eval.failed) return eval.give_up_failure();
  double r[2];
  eval.residual(cur, r);
  auto jacobian = [&]() {
    // forward differences: eps by a small share of the distance to the closing eccentricity
    const double de = 1e-6 * std::max(1e-3, closing_eccentricity(state, x[1]) - x[0]);
    const double da = 1e-6;
    double r1[2], r2[2];
    eval.residual(eval(x[0] + de, x[1]), r1);
    eval.residual(eval(x[0], x[1] + da), r2);
    J[0] = (r1[0] - r[0]) / de, J[2] = (r1[1] - r[1]) / de;
    J[1] = (r2[0] - r[0]) / da, J[3] = (r2[1] - r[1]) / da;
    have_jacobian = true;
    fresh_jacobian = true;
  };
  for (int iter = 0; iter < 60; ++iter) {
    if (eval.failed) return eval.give_up_failure();
    if (std::abs(r[0]) <= rel_tol && std::abs(r[1]) <= rel_tol) {
      cur.film_solves = eval.solves;
      cur.jacobian_valid = have_jacobian;
      std::copy(J, J + 4, cur.jacobian);
      finish(cur, p_, speed);
      return cur;
    }
    if (!have_jacobian) jacobian();
    const double det = J[0] * J[3] - J[1] * J[2];
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
      return eval.give_up(cur, MixedStatus::NotConverged, "singular balance Jacobian");
    double dx[2] = {-(J[3] * r[0] - J[1] * r[1]) / det, -(-J[2] * r[0] + J[0] * r[1]) / det};
    dx[1] = std::clamp(dx[1], -0.5, 0.5);
    double lambda = 1.0, rt[2] = {0.0, 0.0};
    MixedEquilibrium trial;
    const bool accepted = line_search(eval, x, dx, r, lambda, trial, rt);
    if (eval.failed) return eval.give_up_failure();
    if (!accepted) {
      if (!fresh_jacobian) {   // a stale (Broyden or warm-start) Jacobian: rebuild it before giving up
        have_jacobian = false;
        continue;
      }
      return eval.give_up(cur, MixedStatus::NotConverged, "balance Newton: no descent along the Newton direction");
    }
    fresh_jacobian = false;
    const double sx0 = lambda * dx[0], sx1 = lambda * dx[1];
    broyden(J, sx0, sx1, rt[0] - r[0], rt[1] - r[1]);
    x[0] += sx0, x[1] += sx1;
    r[0] = rt[0], r[1] = rt[1];
    cur = std::move(trial);
  }
  return eval.give_up(cur, MixedStatus::NotConverged, "balance Newton: 60 iterations");
}

MixedWearRates MixedJournalBearingSystem::wear_rates(const MixedWearState &state, const MixedEquilibrium &eq,
                                                     coupling::RangeUse *use) const
{
  const int n = p_.n_theta;
  MixedWearRates r;
  r.bore.assign(static_cast<std::size_t>(n), 0.0);
  const double area = node_area();
  for (int i = 0; i < n; ++i) {
    const double pa = eq.asperity_pressure[i];
    if (!(pa > 0.0)) continue;
    const coupling::StateLawValues v = p_.law->values(pa, state.bore[i], p_.policy, use);
    r.bore[i] = v.wear_rate;
    r.shaft += v.counterface_wear_rate / n;   // the journal passes every bore node once per turn
    r.bore_volume += v.wear_rate * area;
  }
  return r;
}

// ---------------------------------------------------------------------------------------------------
namespace {

MixedSample sample_of(const MixedJournalBearingSystem &sys, const MixedWearState &st, const MixedEquilibrium &e, double t,
                      double distance, double speed, long steps)
{
  MixedSample s;
  s.t = t;
  s.distance = distance;
  s.speed = speed;
  s.eccentricity = e.eccentricity;
  s.attitude = e.attitude;
  s.h_min = e.h_min;
  s.lambda = e.lambda;
  s.asperity_share = e.asperity_share;
  s.mu = e.mu;
  s.mu_viscous = e.mu_viscous;
  s.mu_boundary = e.mu_boundary;
  s.sigma_contact = e.sigma_contact;
  s.peak_film_pressure = e.peak_film_pressure;
  s.peak_asperity_pressure = e.peak_asperity_pressure;
  s.sommerfeld = e.sommerfeld;
  double sum = 0.0;
  for (double h : st.bore) {
    s.h_max = std::max(s.h_max, h);
    sum += h;
  }
  s.h_mean = sum / static_cast<double>(st.bore.size());
  s.bore_volume = sum * sys.node_area();
  s.shaft_depth = st.shaft;
  s.steps = steps;
  return s;
}

MixedFrame frame_of(const MixedWearState &st, const MixedEquilibrium &e, double t)
{
  MixedFrame f;
  f.t = t;
  f.gap = e.gap;
  f.worn_depth = st.bore;
  f.asperity_pressure = e.asperity_pressure;
  f.pressure = e.film.film.pressure;
  f.fill = e.film.film.fill;
  return f;
}

void check(const MixedRunSettings &settings) {
  if (!(settings.t_end > 0.0) || !std::isfinite(settings.t_end)) throw InvalidCoefficient("t_end must be > 0");
  if (!(settings.depth_step_fraction > 0.0 && settings.depth_step_fraction <= 1.0))
    throw InvalidCoefficient("depth_step_fraction must be in (0, 1]");
}

// The equilibrium at the start: the roughness is lagged on the asperity pressure, so it is settled in three passes.
// Not ok() when a pass fails; the film solves are added to `film_solves`.
MixedEquilibrium settle_start(const MixedJournalBearingSystem &sys, MixedWearState &st, double rel_tol,
                              long &film_solves) {
  MixedEquilibrium eq;
  for (int k = 0; k < 3; ++k) {
    eq = sys.equilibrium(st, sys.parameters().speed_at(0.0), k ? &eq : nullptr, rel_tol);
    film_solves += eq.film_solves;
    if (!eq.ok()) return eq;
    st.asperity_pressure = eq.asperity_pressure;
  }
  return eq;
}

// Largest sliding step: no node wears more than its allowed increment (a fraction of the law's depth spacing where
// it lies, of 0.1 sigma beyond the law's last depth).
double largest_slide(const MixedWearState &st, const MixedWearRates &rates, const MixedEquilibrium &eq,
                     const coupling::StateLaw &law, double fraction) {
  const double depth_spacing_end = law.worn_depth().back();
  double ds_max = HUGE_VAL;
  for (std::size_t i = 0; i < st.bore.size(); ++i) {
    if (!(rates.bore[i] > 0.0)) continue;
    const double h = st.bore[i];
    double cap;
    if (h < depth_spacing_end) {
      const auto &d = law.worn_depth();
      const auto k = static_cast<std::size_t>(std::upper_bound(d.begin(), d.end(), h) - d.begin());
      cap = d[std::min(k, d.size() - 1)] - d[std::min(k, d.size() - 1) - 1];
    } else {
      cap = 0.1 * eq.sigma[i];
    }
    ds_max = std::min(ds_max, fraction * cap / rates.bore[i]);
  }
  return ds_max;
}

// The end of a step from t: the next output (t_next on entry), a speed-table corner, or where ds_max is slid;
// sets the speed u1 there and the distance ds slid.
void step_end(const MixedJournalBearingParameters &p, double t, double ds_max, double &t_next, double &u1,
              double &ds) {
  for (double tk : p.speed_time)   // a speed-table corner ends a step
    if (tk > t * (1.0 + 1e-12) && tk < t_next) t_next = tk;
  const double u0 = p.speed_at(t);
  u1 = p.speed_at(t_next);
  ds = 0.5 * (u0 + u1) * (t_next - t);
  if (ds > ds_max) {   // shorter step: speed linear inside, so solve 0.5 (u0 + u(t + dt)) dt = ds_max
    const double a = (u1 - u0) / (t_next - t);   // du/dt
    const double dt = std::abs(a) > 0.0 ? (-u0 + std::sqrt(u0 * u0 + 2.0 * a * ds_max)) / a : ds_max / u0;
    t_next = std::min(t_next, t + dt);
    u1 = p.speed_at(t_next);
    ds = std::min(ds_max, 0.5 * (u0 + u1) * (t_next - t));
  }
}

}    // namespace

MixedRunReport run_in(const MixedJournalBearingSystem &sys, const MixedRunSettings &settings,
                      const MixedObserver &observer, const MixedFrameObserver &frames)
{
  check(settings);
  const auto &p = sys.parameters();
  const auto &law = *p.law;
  const double dt_out = settings.output_interval > 0.0 ? settings.output_interval : settings.t_end / 200.0;
  std::vector<double> frame_times = settings.frame_times;
  std::sort(frame_times.begin(), frame_times.end());
  std::size_t next_frame = 0;
  MixedRunReport rep;
  MixedWearState st = sys.initial_state();
  double t = 0.0, distance = 0.0;
  auto fail = [&](MixedRunStatus status, const std::string &message) {
    rep.status = status;
    rep.message = message + " at t = " + std::to_string(t) + " s";
    rep.final_state = st;
    return rep;
  };
  MixedEquilibrium eq;
  try {
    eq = settle_start(sys, st, settings.rel_tol, rep.film_solves);
  } catch (const std::out_of_range &e) {
    return fail(MixedRunStatus::LawOutOfRange, e.what());
  }
  const auto not_balanced = [&](const MixedEquilibrium &e) {
    rep.equilibrium_status = e.status;
    rep.equilibrium_message = e.message;
    return fail(MixedRunStatus::EquilibriumFailed, std::string(to_string(e.status)) + ": " + e.message);
  };
  if (!eq.ok()) return not_balanced(eq);
  rep.initial = eq;
  const auto emit = [&] {
    if (observer) observer(sample_of(sys, st, eq, t, distance, p.speed_at(t), rep.steps));
    while (next_frame < frame_times.size() && frame_times[next_frame] <= t * (1.0 + 1e-12) + 1e-300) {
      if (frames) frames(frame_of(st, eq, t));
      ++next_frame;
    }
  };
  emit();
  long out_index = 1;
  while (t < settings.t_end * (1.0 - 1e-12)) {
    if (rep.steps >= settings.max_steps)
      return fail(MixedRunStatus::TooManySteps, "more than " + std::to_string(settings.max_steps) + " wear steps");
    const double next_out = std::min(settings.t_end, out_index * dt_out);
    MixedWearRates rates;
    try {
      rates = sys.wear_rates(st, eq, &rep.range_use);
    } catch (const std::out_of_range &e) {
      return fail(MixedRunStatus::LawOutOfRange, e.what());
    }
    const double ds_max = largest_slide(st, rates, eq, law, settings.depth_step_fraction);
    double t_next = next_out, u1 = 0.0, ds = 0.0;
    step_end(p, t, ds_max, t_next, u1, ds);
    for (std::size_t i = 0; i < st.bore.size(); ++i) st.bore[i] += rates.bore[i] * ds;
    st.shaft += rates.shaft * ds;
    rep.rate_volume_integral += rates.bore_volume * ds;
    st.asperity_pressure = eq.asperity_pressure;
    t = t_next;
    distance += ds;
    ++rep.steps;
    try {
      MixedEquilibrium next = sys.equilibrium(st, u1, &eq, settings.rel_tol);
      rep.film_solves += next.film_solves;
      if (!next.ok()) return not_balanced(next);
      eq = std::move(next);
    } catch (const std::out_of_range &e) {
      return fail(MixedRunStatus::LawOutOfRange, e.what());
    }
    if (t >= next_out * (1.0 - 1e-12)) {
      ++out_index;
      emit();
    } else if (settings.sample_wear_limited_steps) {
      emit();   // a wear-limited step: the run-in transient, resolved step by step
    }
  }
  rep.final_state = st;
  rep.final = eq;
  return rep;
}

// ---------------------------------------------------------------------------------------------------
StribeckResult stribeck_sweep(const MixedJournalBearingSystem &sys, const MixedWearState &state, double speed_min,
                              double speed_max, int points, double rel_tol)
{
  if (!(speed_min > 0.0) || !(speed_max > speed_min) || !std::isfinite(speed_max))
    throw InvalidCoefficient("speed_min, speed_max: need 0 < speed_min < speed_max");
  if (points < 2) throw InvalidCoefficient("points: at least 2");
  StribeckResult r;
  r.points.resize(static_cast<std::size_t>(points));
  MixedEquilibrium eq;
  bool have = false;
  // from the fastest (a thick film, eps small) down: each point warm-starts the next
  for (int k = points - 1; k >= 0; --k) {
    const double u = speed_min * std::pow(speed_max / speed_min, k / double(points - 1));
    MixedEquilibrium next = sys.equilibrium(state, u, have ? &eq : nullptr, rel_tol);
    if (!next.ok()) {
      r.status = next.status;
      r.message = "at speed " + std::to_string(u) + " m/s: " + next.message;
      r.points.erase(r.points.begin(), r.points.begin() + k + 1);
      return r;
    }
    eq = std::move(next);
    have = true;
    StribeckPoint &pt = r.points[static_cast<std::size_t>(k)];
    pt.speed = u;
    pt.hersey = eq.hersey;
    pt.sommerfeld = eq.sommerfeld;
    pt.mu = eq.mu;
    pt.mu_viscous = eq.mu_viscous;
    pt.mu_boundary = eq.mu_boundary;
    pt.lambda = eq.lambda;
    pt.asperity_share = eq.asperity_share;
    pt.eccentricity = eq.eccentricity;
    pt.attitude = eq.attitude;
    pt.h_min = eq.h_min;
  }
  return r;
}

}    // namespace runin::continuum
