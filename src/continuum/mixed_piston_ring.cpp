#include "continuum/mixed_piston_ring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <boost/math/tools/roots.hpp>

#include "tribo/flow_factors.h"
#include "tribo/greenwood_tripp.h"

namespace runin::continuum {
namespace {

constexpr double kPi = 3.14159265358979323846;

void require_positive(double v, const char *name) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(name) + " must be positive and finite, got " + std::to_string(v));
}

// ln F_5/2(H) on a uniform grid (H in [-1, 12]; 0 beyond 12) with its exact slope d ln F_5/2 / dH = -2.5 F_3/2 / F_5/2; cubic Hermite in
// between (relative error < 1e-9, unit test). The direct quadrature costs ~200 exp per call, and a cycle makes
// ~1e6 calls.
class F52Table {
 public:
  F52Table() {
    for (int k = 0; k <= kN; ++k) {
      const double H = kMin + k * kStep;
      const double f = tribo::greenwood_tripp_f(2.5, H);
      lnf_[k] = std::log(f);
      slope_[k] = -2.5 * tribo::greenwood_tripp_f(1.5, H) / f;
    }
  }
  double operator()(double H) const {
    if (H >= kMax) return 0.0;   // F_5/2(12) = 4e-34: no contact
    if (H <= kMin) return tribo::greenwood_tripp_f(2.5, H);
    const double u = (H - kMin) / kStep;
    const int k = std::min(static_cast<int>(u), kN - 1);
    const double t = u - k, t2 = t * t, t3 = t2 * t;
    const double v = (2 * t3 - 3 * t2 + 1) * lnf_[k] + (t3 - 2 * t2 + t) * kStep * slope_[k] +
                     (-2 * t3 + 3 * t2) * lnf_[k + 1] + (t3 - t2) * kStep * slope_[k + 1];
    return std::exp(v);
  }

 private:
  static constexpr double kMin = -1.0, kMax = 12.0, kStep = 0.01;
  static constexpr int kN = 1300;
  double lnf_[kN + 1], slope_[kN + 1];
};

const F52Table &f52() {
  static const F52Table table;
  return table;
}

// Asperity pressures below this are no contact (no law lookup, no wear): 1e-9 of the law's lowest pressure.
double contact_floor(const coupling::StateLaw &law) { return 1e-9 * law.pressure().front(); }

double trapezoid(const std::vector<double> &v, double dx) {
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) s += ((i == 0 || i + 1 == v.size()) ? 0.5 : 1.0) * v[i];
  return s * dx;
}

}  // namespace

double f52_interpolated(double H) { return f52()(H); }

SummitStatistics summit_statistics(const coupling::StateLaw &law) {
  const auto &m = law.metadata();
  const char *need = "a law without the statistics mixed lubrication needs: ";
  if (!m.contains("surface") || !m["surface"].is_object())
    throw std::invalid_argument(std::string(need) + "no surface metadata (surface.R, surface.spacing)");
  const auto &s = m["surface"];
  for (const char *key : {"R", "spacing"})
    if (!s.contains(key) || !s[key].is_number() || !(s[key].get<double>() > 0.0))
      throw std::invalid_argument(std::string(need) + "surface." + key + " missing or not positive");
  const double spacing = s["spacing"].get<double>();
  return {1.0 / (spacing * spacing), s["R"].get<double>()};
}

const char *to_string(RingFilmStatus status) {
  switch (status) {
  case RingFilmStatus::Ok: return "ok";
  case RingFilmStatus::FilmNotConverged: return "film solve not converged";
  case RingFilmStatus::LoadNotBracketed: return "load balance not bracketed";
  case RingFilmStatus::LoadNotConverged: return "load balance not converged";
  case RingFilmStatus::LawOutOfRange: return "state law out of range";
  }
  return "?";
}

void MixedRingParameters::validate() const {
  crank.validate();
  require_positive(crank_speed, "crank_speed");
  if (!gas.empty()) gas.validate();
  require_positive(bore, "bore");
  require_positive(face_width, "face_width");
  if (!(crown_height >= 0.0) || !std::isfinite(crown_height))
    throw std::invalid_argument("crown_height must be >= 0");
  if (!(elastic_pressure >= 0.0) || !std::isfinite(elastic_pressure))
    throw std::invalid_argument("elastic_pressure must be >= 0");
  require_positive(viscosity, "viscosity");
  if (supply == OilSupply::Starved) require_positive(oil_film, "oil_film");
  if (nodes < 5 || nodes > 20001) throw std::invalid_argument("nodes must lie in [5, 20001]");
  if (steps_per_cycle < 8 || steps_per_cycle > 1000000) throw std::invalid_argument("steps_per_cycle must lie in [8, 1e6]");
  require_positive(effective_modulus, "effective_modulus");
  require_positive(summits.density, "summit density");
  require_positive(summits.radius, "summit radius");
  if (liner == LinerRoughness::Fixed && !(liner_sigma >= 0.0)) throw std::invalid_argument("liner_sigma must be >= 0");
  if (!(gamma >= 1.0 / 9.0 && gamma <= 9.0)) throw std::invalid_argument("gamma must lie in [1/9, 9]");
}

double MixedRingParameters::cycle_angle() const { return gas.empty() ? 2.0 * kPi : gas.cycle; }
double MixedRingParameters::period() const { return cycle_angle() / crank_speed; }
double MixedRingParameters::load_per_length(double theta) const {
  return (elastic_pressure + (gas.empty() ? 0.0 : gas.at(theta))) * face_width;
}
double MixedRingParameters::liner_speed(double theta) const { return -crank.velocity(theta, crank_speed); }
double MixedRingParameters::circumference() const { return kPi * bore; }

// ---------------------------------------------------------------------------------------------------
MixedPistonRing::MixedPistonRing(MixedRingParameters parameters, std::shared_ptr<const coupling::StateLaw> law,
                                 coupling::OutOfRange policy) :
    p_(std::move(parameters)), law_(std::move(law)), policy_(policy) {
  p_.validate();
  if (!law_) throw std::invalid_argument("state law: none given");
  worn_.assign(p_.nodes, 0.0);
  update_profile();
  update_roughness(std::vector<double>(p_.nodes, 0.0));
}

double MixedPistonRing::crown(int i) const {
  const double u = 2.0 * x(i) / p_.face_width - 1.0;
  return p_.crown_height * u * u;
}

void MixedPistonRing::update_profile() {
  profile_.resize(p_.nodes);
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < p_.nodes; ++i) lowest = std::min(lowest, crown(i) + worn_[i]);
  for (int i = 0; i < p_.nodes; ++i) profile_[i] = crown(i) + worn_[i] - lowest;
}

void MixedPistonRing::update_roughness(const std::vector<double> &pressure) {
  const double p_low = law_->pressure().front();
  rq_.resize(p_.nodes);
  sigma_.resize(p_.nodes);
  k_.resize(p_.nodes);
  uncut_sigma_.resize(p_.nodes);
  top_.assign(p_.nodes, HUGE_VAL);
  const bool cut = p_.worn_surface == WornSurface::TruncatedSummits;
  const coupling::OutOfRange lookup = policy_ == coupling::OutOfRange::Error ? coupling::OutOfRange::Clamp : policy_;
  for (int i = 0; i < p_.nodes; ++i) {
    // rq at the node's sliding-mean asperity pressure (the lowest grid pressure without contact); its p
    // dependence is weak (rq(p, 0) 184-199 nm over 1-20 MPa in the steel law). Cut summits keep the unworn spread.
    const double p = pressure[i] > 0.0 ? pressure[i] : p_low;
    rq_[i] = law_->value(coupling::StateField::Rq, p, cut ? 0.0 : worn_[i], coupling::Band::Mean, lookup);
    const double liner = p_.liner == LinerRoughness::Law ? rq_[i] : p_.liner_sigma;
    sigma_[i] = std::sqrt(rq_[i] * rq_[i] + liner * liner);
    uncut_sigma_[i] = sigma_[i];
    const tribo::GreenwoodTripp gt(p_.summits.density, p_.summits.radius, sigma_[i], p_.effective_modulus);
    k_[i] = gt.coefficient() * p_.effective_modulus;
    if (cut && sigma_[i] > 0.0) {
      top_[i] = gt.top_after_wear(worn_[i]);
      const double ratio = top_[i] == HUGE_VAL ? 1.0 : tribo::truncated_rms_ratio(top_[i] / sigma_[i]);
      rq_[i] *= ratio;
      sigma_[i] *= ratio;
    }
  }
  film_rq_ = weighted_rq(pressure);
  film_liner_ = p_.liner == LinerRoughness::Law ? film_rq_ : p_.liner_sigma;
  film_sigma_ = std::sqrt(film_rq_ * film_rq_ + film_liner_ * film_liner_);
}

void MixedPistonRing::set_worn_depth(std::vector<double> h) {
  if (static_cast<int>(h.size()) != p_.nodes) throw std::invalid_argument("worn depth: one value per node");
  worn_ = std::move(h);
  update_profile();
  update_roughness(std::vector<double>(p_.nodes, 0.0));
}

void MixedPistonRing::advance_wear(const std::vector<double> &dh, double cycles, const std::vector<double> &pressure) {
  for (int i = 0; i < p_.nodes; ++i) worn_[i] += cycles * dh[i];
  update_profile();
  update_roughness(pressure);
}

double MixedPistonRing::worn_volume() const { return p_.circumference() * trapezoid(worn_, dx()); }

double MixedPistonRing::weighted_rq(const std::vector<double> &w) const {
  double sw = 0.0, s = 0.0;
  for (int i = 0; i < p_.nodes; ++i) sw += w[i], s += w[i] * rq_[i];
  if (sw > 0.0) return s / sw;
  for (double v : rq_) s += v;
  return s / p_.nodes;
}

double MixedPistonRing::weighted_sigma(const std::vector<double> &w) const {
  double sw = 0.0, s = 0.0;
  for (int i = 0; i < p_.nodes; ++i) sw += w[i], s += w[i] * sigma_[i];
  if (sw > 0.0) return s / sw;
  for (double v : sigma_) s += v;
  return s / p_.nodes;
}

double MixedPistonRing::asperity_pressure(int i, double gap) const
{
  if (top_[i] == HUGE_VAL) return k_[i] * f52()(gap / sigma_[i]);
  // cut summits stand on the unworn summit plane, worn_i nearer the liner than the face's mean plane
  const double s = uncut_sigma_[i];
  return k_[i] * tribo::greenwood_tripp_f_truncated(2.5, (gap - worn_[i]) / s, top_[i] / s);
}

double MixedPistonRing::wear_scale(int i) const
{
  if (top_[i] == HUGE_VAL && p_.worn_surface != WornSurface::TruncatedSummits) return sigma_[i];
  // the cut moves by dT = dw / (2 pi eta beta sigma F_1(T / sigma)); an uncut start is taken at T = 4 sigma
  const double s = uncut_sigma_[i];
  const double t = std::min(top_[i] / s, 4.0);
  const double scale = 2.0 * M_PI * p_.summits.density * p_.summits.radius * s * s * tribo::greenwood_tripp_f(1.0, t);
  return std::min(sigma_[i], scale);
}

// The film at a given h_min. U < 0: solved mirrored (the inlet is always the leading edge x = 0 of RingFace).
FaceSolution MixedPistonRing::solve(double h_min, double speed, double squeeze, const std::vector<double> *fill_prev,
                                    double dt, double load) const {
  const int n = p_.nodes;
  const bool mirror = speed < 0.0;
  auto at = [&](const std::vector<double> &v, int i) { return mirror ? v[n - 1 - i] : v[i]; };
  RingFace ring;
  ring.width = p_.face_width;
  ring.viscosity = p_.viscosity;
  ring.speed = std::abs(speed);
  ring.min_gap = h_min;
  ring.squeeze_velocity = squeeze;
  ring.profile.resize(n);
  for (int i = 0; i < n; ++i) ring.profile[i] = at(profile_, i);
  ring.roughness.sigma_moving = film_liner_;
  ring.roughness.sigma_fixed = film_rq_;
  ring.roughness.gamma = p_.gamma;
  if (p_.supply == OilSupply::Starved) {
    // the oil layer on the liner enters at U h_oil; the Couette content of the inlet is theta U h_T / 2
    const double h_in = tribo::mean_gap(h_min + ring.profile[0], ring.roughness.averaged_sigma());
    ring.inlet_fill = std::min(1.0, 2.0 * p_.oil_film / h_in);
  }
  if (fill_prev && !fill_prev->empty()) {
    ring.fill_prev.resize(n);
    for (int i = 0; i < n; ++i) ring.fill_prev[i] = at(*fill_prev, i);
    ring.dt = dt;
  }
  const RingFaceResult r = solve_ring_face(ring);
  FaceSolution s;
  s.status = r.film.ok() ? RingFilmStatus::Ok : RingFilmStatus::FilmNotConverged;
  s.speed = speed;
  s.load = load;
  s.h_min = h_min;
  s.squeeze_velocity = squeeze;
  s.film_load = r.load;
  s.viscous_friction = std::abs(r.friction);
  s.film_solves = 1;
  s.gap.resize(n);
  s.pressure.resize(n);
  s.fill.resize(n);
  s.asperity_pressure.resize(n);
  for (int i = 0; i < n; ++i) {
    const int j = mirror ? n - 1 - i : i;
    s.gap[i] = h_min + profile_[i];
    s.pressure[i] = r.film.pressure.empty() ? 0.0 : r.film.pressure[j];
    s.fill[i] = r.film.fill.empty() ? 1.0 : std::clamp(r.film.fill[j], 0.0, 1.0);   // round-off at 0 and 1
    s.asperity_pressure[i] = asperity_pressure(i, s.gap[i]);
  }
  s.asperity_load = trapezoid(s.asperity_pressure, dx());
  return s;
}

namespace {
// The contact of a balanced face: the law at each node that carries asperity pressure (mu_body, wear rate), the
// boundary friction, the peak pressures and lambda at the smallest gap.
void add_contact(const MixedPistonRing &ring, FaceSolution &out, coupling::RangeUse *use) {
  const int n = ring.parameters().nodes;
  const auto &law = ring.law();
  const auto &worn = ring.worn_depth();
  out.mu_body.assign(n, 0.0);
  out.wear_rate.assign(n, 0.0);
  const double floor = contact_floor(law);
  double boundary = 0.0;
  int i_min = 0;
  for (int i = 0; i < n; ++i) {
    if (out.gap[i] < out.gap[i_min]) i_min = i;
    out.peak_film_pressure = std::max(out.peak_film_pressure, out.pressure[i]);
    out.peak_asperity_pressure = std::max(out.peak_asperity_pressure, out.asperity_pressure[i]);
    if (out.asperity_pressure[i] <= floor) continue;
    const auto v = law.values(out.asperity_pressure[i], worn[i], ring.policy(), use);
    out.mu_body[i] = v.mu_body;
    out.wear_rate[i] = v.wear_rate;
    boundary += ((i == 0 || i == n - 1) ? 0.5 : 1.0) * v.mu_body * out.asperity_pressure[i];
  }
  out.boundary_friction = boundary * ring.dx();
  out.lambda = out.h_min / ring.sigma()[i_min];
}
}  // namespace

FaceSolution MixedPistonRing::balance(double h_prev, double speed, double load, const std::vector<double> *fill_prev,
                                      double dt, coupling::RangeUse *use, double guess) const {
  // Root of excess(h) = film load + asperity load - W' in u = ln h: bracket outward from the guess, then
  // Anderson-Bjorck regula falsi until |excess| <= kLoadTolerance W' (every film solve is kept, none repeated).
  constexpr double kLoadTolerance = 1e-8;
  constexpr int kMaxSolves = 200;
  const bool transient = dt > 0.0;
  int solves = 0;
  FaceSolution best;
  double best_residual = std::numeric_limits<double>::infinity();
  auto F = [&](double u) {
    const double h = std::exp(u);
    FaceSolution s = solve(h, speed, transient ? (h - h_prev) / dt : 0.0, fill_prev, dt, load);
    ++solves;
    const double f = s.film_load + s.asperity_load - load;
    if (std::abs(f) < best_residual) best_residual = std::abs(f), best = std::move(s);
    return f;
  };
  const double sigma_min = *std::min_element(sigma_.begin(), sigma_.end());
  const double sigma_max = *std::max_element(sigma_.begin(), sigma_.end());
  const double u_floor = std::log(1e-3 * sigma_min), u_ceiling = std::log(0.1 * p_.face_width);
  const double g = guess > 0.0 ? guess : (transient && h_prev > 0.0 ? h_prev : 3.0 * sigma_max);
  const double tolerance = kLoadTolerance * load;
  RingFilmStatus status = RingFilmStatus::Ok;
  double ua = std::clamp(std::log(g), u_floor, u_ceiling), fa = F(ua);
  if (std::abs(fa) > tolerance) {
    double step = transient ? 0.01 : 0.1;
    double ub = ua, fb = fa;
    const int direction = fa > 0.0 ? 1 : -1;   // excess > 0: the gap is too small
    while ((fb > 0.0) == (fa > 0.0) && std::abs(fb) > tolerance) {
      ua = ub;
      fa = fb;
      ub = ua + direction * step;
      if (ub > u_ceiling || ub < u_floor) {
        status = RingFilmStatus::LoadNotBracketed;
        break;
      }
      fb = F(ub);
      step *= 2.0;
    }
    // Anderson-Bjorck on [ua, ub] (signs differ)
    while (status == RingFilmStatus::Ok && best_residual > tolerance) {
      if (solves >= kMaxSolves || std::abs(ub - ua) < 1e-13) {
        status = RingFilmStatus::LoadNotConverged;
        break;
      }
      double uc = (ua * fb - ub * fa) / (fb - fa);
      if (!(uc > std::min(ua, ub) && uc < std::max(ua, ub))) uc = 0.5 * (ua + ub);
      const double fc = F(uc);
      if ((fc > 0.0) == (fb > 0.0)) {
        const double m = 1.0 - fc / fb;
        fa *= m > 0.0 ? m : 0.5;
      } else {
        ua = ub;
        fa = fb;
      }
      ub = uc;
      fb = fc;
    }
  }
  FaceSolution out = std::move(best);
  out.film_solves = solves;
  // a failed trial solve away from the root does not matter; the kept one must have converged
  out.status = out.status != RingFilmStatus::Ok ? RingFilmStatus::FilmNotConverged : status;
  add_contact(*this, out, use);
  return out;
}

FaceSolution MixedPistonRing::step(const FaceState &prev, double speed, double load, double dt,
                                   coupling::RangeUse *use) const {
  if (!(dt > 0.0)) throw std::invalid_argument("step: dt must be positive");
  return balance(prev.h_min, speed, load, &prev.fill, dt, use, prev.h_min * std::exp(std::clamp(prev.log_rate, -0.5, 0.5)));
}

FaceSolution MixedPistonRing::steady(double speed, double load, coupling::RangeUse *use, double guess) const {
  return balance(0.0, speed, load, nullptr, 0.0, use, guess);
}

CycleResult MixedPistonRing::cycle(FaceState &state, bool keep_curve, int frame_every) const {
  CycleResult c;
  const int n = p_.nodes, steps = p_.steps_per_cycle;
  const double dtheta = p_.cycle_angle() / steps, dt = dtheta / p_.crank_speed, circ = p_.circumference();
  c.wear.assign(n, 0.0);
  c.mean_asperity_pressure.assign(n, 0.0);
  c.asperity_impulse.assign(n, 0.0);
  c.min_h = c.min_lambda = std::numeric_limits<double>::infinity();
  double force_dt = 0.0, load_dt = 0.0, asperity_dt = 0.0, work = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double theta = k * dtheta;
    const double U = p_.liner_speed(theta), W = p_.load_per_length(theta);
    FaceSolution s;
    try {
      s = step(state, U, W, dt, &c.use);
    } catch (const std::out_of_range &e) {
      c.status = RingFilmStatus::LawOutOfRange;
      c.message = "crank angle " + std::to_string(theta * 180.0 / kPi) + " deg: " + e.what();
      return c;
    }
    c.film_solves += s.film_solves;
    if (s.status != RingFilmStatus::Ok) {
      c.status = s.status;
      c.message = std::string(to_string(s.status)) + " at crank angle " + std::to_string(theta * 180.0 / kPi) +
                  " deg (h_min " + std::to_string(s.h_min) + " m, W' " + std::to_string(W) + " N/m)";
      return c;
    }
    state.log_rate = std::log(s.h_min / state.h_min);
    state.h_min = s.h_min;
    state.fill = s.fill;
    const double ds = std::abs(U) * dt;
    const double F = s.friction() * circ;
    force_dt += F * dt;
    load_dt += W * circ * dt;
    asperity_dt += s.asperity_load * circ * dt;
    work += F * ds;
    c.sliding_distance += ds;
    for (int i = 0; i < n; ++i) {
      c.wear[i] += s.wear_rate[i] * ds;
      c.mean_asperity_pressure[i] += s.asperity_pressure[i] * ds;
      c.asperity_impulse[i] += s.asperity_pressure[i] * dt;
    }
    c.min_h = std::min(c.min_h, s.h_min);
    c.min_lambda = std::min(c.min_lambda, s.lambda);
    c.peak_film_pressure = std::max(c.peak_film_pressure, s.peak_film_pressure);
    c.peak_asperity_pressure = std::max(c.peak_asperity_pressure, s.peak_asperity_pressure);
    if (keep_curve) {
      CrankSample cs;
      cs.crank_angle = theta;
      cs.t = k * dt;
      cs.speed = U;
      cs.load = W * circ;
      cs.h_min = s.h_min;
      cs.friction_force = F;
      cs.mu = s.mu();
      cs.asperity_share = s.asperity_share();
      cs.lambda = s.lambda;
      cs.peak_film_pressure = s.peak_film_pressure;
      cs.peak_asperity_pressure = s.peak_asperity_pressure;
      c.curve.push_back(cs);
      if (frame_every > 0 && k % frame_every == 0)
        c.frames.push_back({theta, k * dt, s.gap, s.pressure, s.fill, s.asperity_pressure, worn_});
    }
  }
  const double period = steps * dt;
  if (c.sliding_distance > 0.0)
    for (double &p : c.mean_asperity_pressure) p /= c.sliding_distance;
  c.mean_friction_force = force_dt / period;
  c.mu = load_dt > 0.0 ? force_dt / load_dt : 0.0;
  c.asperity_share = load_dt > 0.0 ? asperity_dt / load_dt : 0.0;
  c.power_loss = work / period;
  const double swept = 0.25 * kPi * p_.bore * p_.bore * 2.0 * p_.crank.crank_radius;
  c.fmep = work / swept;
  return c;
}

RingFilmStatus MixedPistonRing::start(FaceState &state, std::string &message) const {
  FaceSolution s;
  try {
    s = steady(p_.liner_speed(0.0), p_.load_per_length(0.0), nullptr);
  } catch (const std::out_of_range &e) {
    message = e.what();
    return RingFilmStatus::LawOutOfRange;
  }
  if (s.status != RingFilmStatus::Ok) {
    message = std::string(to_string(s.status)) + " in the start solve at crank angle 0";
    return s.status;
  }
  state.h_min = s.h_min;
  state.fill = s.fill;
  state.started = true;
  const CycleResult warm = cycle(state, false);
  if (!warm.ok()) message = "start cycle: " + warm.message;
  return warm.status;
}

// ---------------------------------------------------------------------------------------------------
void RunInSettings::validate() const {
  if (cycles < 1) throw std::invalid_argument("cycles must be >= 1");
  if (!(jump_depth_fraction > 0.0)) throw std::invalid_argument("jump_depth_fraction must be positive");
  if (!(jump_sigma_fraction > 0.0)) throw std::invalid_argument("jump_sigma_fraction must be positive");
  if (!(growth >= 1.0)) throw std::invalid_argument("growth must be >= 1");
  if (!(max_cycle_wear_fraction > 0.0)) throw std::invalid_argument("max_cycle_wear_fraction must be positive");
  if (frame_every < 0) throw std::invalid_argument("frame_every must be >= 0");
  if (max_computed_cycles < 1) throw std::invalid_argument("max_computed_cycles must be >= 1");
}

namespace {
// Cycles the computed one stands for: as many as keep every node's wear within its limit (`ratio`: the largest
// wear / limit), growing by at most `growth` per jump; the last cycle is computed.
long cycles_to_jump(const RunInSettings &settings, double ratio, long previous_jump, long done) {
  long jump = 1;
  if (settings.jumping) {
    const double cap = std::min(settings.growth * static_cast<double>(previous_jump), 1e15);
    const double want = ratio > 0.0 ? std::floor(1.0 / ratio) : cap;
    jump = static_cast<long>(std::max(1.0, std::min(want, cap)));
    // the last cycle is computed
    if (done < settings.cycles - 1) jump = std::min(jump, settings.cycles - 1 - done);
    else jump = 1;
  }
  return jump;
}

// The observer's row of a computed cycle (the face as it was during it).
CycleSample cycle_sample(const MixedPistonRing &system, const CycleResult &r, long done, long jump) {
  const auto &p = system.parameters();
  const int n = system.nodes();
  const auto &h = system.worn_depth();
  double max_h = 0.0, mean_h = 0.0;
  for (double v : h) max_h = std::max(max_h, v), mean_h += v;
  mean_h /= n;
  CycleSample s;
  s.cycle = done;
  s.jump = jump;
  s.time = done * p.period();
  s.sliding_distance = done * r.sliding_distance;
  s.mean_friction_force = r.mean_friction_force;
  s.mu = r.mu;
  s.power_loss = r.power_loss;
  s.fmep = r.fmep;
  s.min_h = r.min_h;
  s.min_lambda = r.min_lambda;
  s.asperity_share = r.asperity_share;
  s.rq = system.weighted_rq(r.asperity_impulse);
  s.sigma = system.weighted_sigma(r.asperity_impulse);
  s.max_worn_depth = max_h;
  s.mean_worn_depth = mean_h;
  s.worn_volume = system.worn_volume();
  s.cycle_wear_volume = p.circumference() * [&] {
    double v = 0.0;
    for (int i = 0; i < n; ++i) v += ((i == 0 || i == n - 1) ? 0.5 : 1.0) * r.wear[i];
    return v * system.dx();
  }();
  s.peak_film_pressure = r.peak_film_pressure;
  s.peak_asperity_pressure = r.peak_asperity_pressure;
  return s;
}
}  // namespace

RunInReport run_in(MixedPistonRing &system, const RunInSettings &settings, const CycleObserver &observer) {
  settings.validate();
  RunInReport report;
  const auto &depth = system.law().worn_depth();
  const int n = system.nodes();
  FaceState state;
  std::string message;
  if (system.start(state, message) != RingFilmStatus::Ok) {
    report.status = RunInStatus::CycleFailed;
    report.message = message;
    return report;
  }
  long done = 0, previous_jump = 1;
  while (done < settings.cycles) {
    if (report.computed_cycles >= settings.max_computed_cycles) {
      report.status = RunInStatus::TooManyCycles;
      report.message = "more than " + std::to_string(settings.max_computed_cycles) + " computed cycles after " +
                       std::to_string(done) + " of " + std::to_string(settings.cycles) +
                       " (each cycle wears near the jump limit: raise the jump fractions or run fewer cycles)";
      report.cycles = done;
      return report;
    }
    CycleResult r = system.cycle(state, true, settings.frame_every);
    ++report.computed_cycles;
    if (!r.ok()) {
      report.status = RunInStatus::CycleFailed;
      report.message = "cycle " + std::to_string(done) + ": " + r.message;
      report.cycles = done;
      return report;
    }
    report.use.below_pressure += r.use.below_pressure;
    report.use.above_pressure += r.use.above_pressure;
    report.use.beyond_depth += r.use.beyond_depth;
    report.use.lookups += r.use.lookups;
    // the jump: no node wears more than its limit
    const auto &h = system.worn_depth();
    const auto &sigma = system.sigma();
    double ratio = 0.0;
    for (int i = 0; i < n; ++i) {
      if (r.wear[i] > settings.max_cycle_wear_fraction * sigma[i]) {
        report.status = RunInStatus::WearPerCycleTooLarge;
        report.message = "cycle " + std::to_string(done) + " wears face node " + std::to_string(i) + " by " +
                         std::to_string(1e9 * r.wear[i]) + " nm, more than " +
                         std::to_string(settings.max_cycle_wear_fraction) + " sigma (" + std::to_string(1e9 * sigma[i]) +
                         " nm): not a gradual run-in at fixed geometry (mostly asperity contact: check the load, the "
                         "crown and the oil)";
        report.cycles = done;
        if (report.computed_cycles == 1) report.first = r;
        return report;
      }
      double limit = settings.jump_sigma_fraction * system.wear_scale(i);
      const auto upper = std::upper_bound(depth.begin(), depth.end(), h[i]);
      if (upper != depth.end())
        limit = std::min(limit, settings.jump_depth_fraction * (*upper - *(upper - 1)));
      ratio = std::max(ratio, r.wear[i] / limit);
    }
    const long jump = cycles_to_jump(settings, ratio, previous_jump, done);
    const CycleSample s = cycle_sample(system, r, done, jump);
    if (observer) observer(s);
    report.booked_wear_volume += static_cast<double>(jump) * s.cycle_wear_volume;
    system.advance_wear(r.wear, static_cast<double>(jump), r.mean_asperity_pressure);
    done += jump;
    previous_jump = jump;
    if (report.computed_cycles == 1) report.first = r;
    report.last = std::move(r);
  }
  report.cycles = done;
  return report;
}

// ---------------------------------------------------------------------------------------------------
std::vector<RingStribeckPoint> stribeck_sweep(const MixedPistonRing &system, double load, double speed_min,
                                          double speed_max, int points, coupling::RangeUse *use) {
  require_positive(load, "load");
  require_positive(speed_min, "speed_min");
  require_positive(speed_max, "speed_max");
  if (!(speed_max > speed_min)) throw std::invalid_argument("speed_max must exceed speed_min");
  if (points < 2 || points > 100000) throw std::invalid_argument("points must lie in [2, 100000]");
  std::vector<RingStribeckPoint> out;
  const double eta = system.parameters().viscosity;
  for (int k = 0; k < points; ++k) {
    const double U = speed_min * std::pow(speed_max / speed_min, static_cast<double>(k) / (points - 1));
    const FaceSolution s = system.steady(U, load, use, out.empty() ? 0.0 : out.back().h_min);
    RingStribeckPoint pt;
    pt.status = s.status;
    pt.speed = U;
    pt.duty = eta * U / load;
    pt.h_min = s.h_min;
    pt.lambda = s.lambda;
    pt.mu = s.mu();
    pt.asperity_share = s.asperity_share();
    pt.viscous_friction = s.viscous_friction;
    pt.boundary_friction = s.boundary_friction;
    out.push_back(pt);
  }
  return out;
}

}  // namespace runin::continuum
