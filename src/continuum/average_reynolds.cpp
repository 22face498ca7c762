#include "continuum/average_reynolds.h"

#include "tribo/contact.h"   // InvalidCoefficient
#include "tribo/flow_factors.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <string>

namespace runin::continuum {

using tribo::InvalidCoefficient;
using tribo::require_positive_finite;

namespace {

const double kPi = std::acos(-1.0);


void require_finite(double value, const std::string &name)
{
  if (!std::isfinite(value)) throw InvalidCoefficient(name + " must be finite");
}

// Film coefficients at a face (or node) of gap h.
struct FaceCoefficients {
  double kx = 0.0, ky = 0.0;   // phi h^3 / (12 mu)
  double couette = 0.0;        // u_m h_T + u_d sigma phi_s
};

// The roughness the film equation sees at node k (0: classical Reynolds).
double node_sigma(const ReynoldsSystem &s, int k)
{
  if (s.sigma.empty() || !s.roughness.flow_factors) return s.roughness.averaged_sigma();
  return s.sigma[k];
}

double face_sigma(const ReynoldsSystem &s, int a, int b)
{
  if (s.sigma.empty() || !s.roughness.flow_factors) return s.roughness.averaged_sigma();
  return 0.5 * (s.sigma[a] + s.sigma[b]);
}

FaceCoefficients face_coefficients(const ReynoldsSystem &s, double h, double sigma)
{
  const FilmRoughness &r = s.roughness;
  const double u_m = 0.5 * s.u_moving, u_d = 0.5 * s.u_moving;
  const double hp = std::max(h, 0.0);
  const double h3 = hp * hp * hp / (12.0 * s.viscosity);
  FaceCoefficients c;
  if (sigma == 0.0) {
    c.kx = c.ky = h3;
    c.couette = u_m * hp;
    return c;
  }
  const double H = h / sigma;
  c.kx = tribo::pressure_flow_factor_x(H, r.gamma) * h3;
  c.ky = tribo::pressure_flow_factor_y(H, r.gamma) * h3;
  const double content = r.contact_factor ? tribo::mean_gap(h, sigma) : hp;
  c.couette = u_m * content + u_d * sigma * tribo::shear_flow_factor_pair(H, r.gamma, r.sigma_moving, r.sigma_fixed);
  return c;
}

// Couette content of a cell and its time derivative factor.
double content(const ReynoldsSystem &s, double h, double sigma)
{
  if (sigma > 0.0 && s.roughness.contact_factor) return tribo::mean_gap(h, sigma);
  return std::max(h, 0.0);
}

double content_rate(const ReynoldsSystem &s, int k)
{
  if (s.dhdt.empty()) return 0.0;
  const double sigma = node_sigma(s, k);
  const double dc = sigma > 0.0 && s.roughness.contact_factor ? tribo::contact_factor(s.h[k] / sigma) : 1.0;
  return dc * s.dhdt[k];
}

// p = P u + p0, theta = T u + t0 for each node, given its state.
enum class NodeState : char { Fixed, Full, Cavitated };

struct Affine {
  double P, p0, T, t0;
};

Affine affine(const ReynoldsSystem &s, const std::vector<NodeState> &state, int k)
{
  switch (state[k]) {
  case NodeState::Fixed: return {0.0, s.fixed_pressure[k], 0.0, s.fixed_fill[k]};
  case NodeState::Full: return {1.0, 0.0, 0.0, 1.0};
  case NodeState::Cavitated: return {0.0, 0.0, 1.0, 1.0};
  }
  return {0.0, 0.0, 0.0, 0.0};
}

// One face a -> b: flux = -k (p_b - p_a) / d * w + c theta_up * w (c only along x).
struct Face {
  int a, b;
  double k_over_d_w;   // k w / d
  double c_w;          // couette content x face length (0 across)
};

std::vector<Face> faces(const ReynoldsSystem &s)
{
  std::vector<Face> out;
  out.reserve(2 * s.nodes());
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i) {
      const int a = s.index(i, j);
      if (i + 1 < s.nx || s.periodic_x) {
        const int b = s.index((i + 1) % s.nx, j);
        const FaceCoefficients c = face_coefficients(s, 0.5 * (s.h[a] + s.h[b]), face_sigma(s, a, b));
        out.push_back({a, b, c.kx * s.dy / s.dx, c.couette * s.dy});
      }
      if (j + 1 < s.ny) {
        const int b = s.index(i, j + 1);
        const FaceCoefficients c = face_coefficients(s, 0.5 * (s.h[a] + s.h[b]), face_sigma(s, a, b));
        out.push_back({a, b, c.ky * s.dx / s.dy, 0.0});
      }
    }
  return out;
}

double face_flux(const Face &f, const std::vector<double> &p, const std::vector<double> &theta)
{
  const int up = f.c_w >= 0.0 ? f.a : f.b;
  return -f.k_over_d_w * (p[f.b] - p[f.a]) + f.c_w * theta[up];
}

}    // namespace

double FilmRoughness::sigma() const { return std::hypot(sigma_moving, sigma_fixed); }

double FilmRoughness::averaged_sigma() const { return flow_factors ? sigma() : 0.0; }

void FilmRoughness::validate() const
{
  if (!(sigma_moving >= 0.0) || !std::isfinite(sigma_moving))
    throw InvalidCoefficient("roughness.sigma_moving must be >= 0 and finite, got " + std::to_string(sigma_moving));
  if (!(sigma_fixed >= 0.0) || !std::isfinite(sigma_fixed))
    throw InvalidCoefficient("roughness.sigma_fixed must be >= 0 and finite, got " + std::to_string(sigma_fixed));
  if (sigma() > 0.0) tribo::pressure_flow_factor_x(1.0, gamma);   // range check of gamma
}

void ReynoldsSystem::validate() const
{
  if (nx < 2) throw InvalidCoefficient("nx: the grid needs >= 2 nodes along x");
  if (ny < 1) throw InvalidCoefficient("ny: the grid needs >= 1 node across");
  require_positive_finite(dx, "dx");
  require_positive_finite(dy, "dy");
  require_positive_finite(viscosity, "viscosity");
  require_finite(u_moving, "u_moving");
  roughness.validate();
  const auto n = static_cast<std::size_t>(nodes());
  if (h.size() != n) throw InvalidCoefficient("h: one gap per node needed");
  for (double v : h)
    if (!(v > 0.0) || !std::isfinite(v))
      throw InvalidCoefficient("h: the film gap must be > 0 at every node (the surfaces touch), got " +
                               std::to_string(v));
  if (!dhdt.empty() && dhdt.size() != n) throw InvalidCoefficient("dhdt: one value per node or none");
  if (!sigma.empty()) {
    if (sigma.size() != n) throw InvalidCoefficient("sigma: one roughness per node or none");
    for (double v : sigma)
      if (!(v >= 0.0) || !std::isfinite(v)) throw InvalidCoefficient("sigma: node roughness must be >= 0 and finite");
  }
  if (!theta_prev.empty()) {
    if (theta_prev.size() != n) throw InvalidCoefficient("theta_prev: one value per node or none");
    require_positive_finite(dt, "dt");
  }
  if (fixed.size() != n || fixed_pressure.size() != n || fixed_fill.size() != n)
    throw InvalidCoefficient("fixed: fixed, fixed_pressure and fixed_fill need one value per node");
  if (std::none_of(fixed.begin(), fixed.end(), [](char f) { return f != 0; }))
    throw InvalidCoefficient("fixed: at least one node must carry a prescribed pressure");
}

const char *to_string(ReynoldsStatus status)
{
  switch (status) {
  case ReynoldsStatus::Converged: return "converged";
  case ReynoldsStatus::NotConverged: return "not converged";
  case ReynoldsStatus::SingularMatrix: return "singular matrix";
  }
  return "?";
}

ReynoldsSolution ReynoldsSolver::solve(const ReynoldsSystem &s, const std::optional<std::vector<double>> &initial) const
{
  s.validate();
  const int n = s.nodes();
  const std::vector<Face> fs = faces(s);
  const double cell = s.dx * s.dy;

  std::vector<int> unknown(n, -1);
  int m = 0;
  for (int k = 0; k < n; ++k)
    if (!s.fixed[k]) unknown[k] = m++;

  std::vector<NodeState> state(n, NodeState::Full);
  for (int k = 0; k < n; ++k) {
    if (s.fixed[k]) state[k] = NodeState::Fixed;
    else if (initial && k < static_cast<int>(initial->size()) && (*initial)[k] < 0.0) state[k] = NodeState::Cavitated;
  }
  std::vector<double> rate(n, 0.0), cont(n, 0.0);
  for (int k = 0; k < n; ++k) {
    rate[k] = content_rate(s, k);
    cont[k] = content(s, s.h[k], node_sigma(s, k));
  }

  ReynoldsSolution sol;
  sol.pressure.assign(n, 0.0);
  sol.fill.assign(n, 1.0);
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  Eigen::VectorXd u(m);
  status_ = ReynoldsStatus::NotConverged;
  for (int iter = 1; iter <= max_iterations_; ++iter) {
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(8 * static_cast<std::size_t>(m));
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
    // residual row r: sum of outflows of cell k; a term coef * p_l or coef * theta_l
    auto add_p = [&](int row, int l, double coef) {
      const Affine a = affine(s, state, l);
      if (a.P != 0.0) trip.emplace_back(row, unknown[l], coef * a.P);
      rhs[row] -= coef * a.p0;
    };
    auto add_t = [&](int row, int l, double coef) {
      const Affine a = affine(s, state, l);
      if (a.T != 0.0) trip.emplace_back(row, unknown[l], coef * a.T);
      rhs[row] -= coef * a.t0;
    };
    for (const Face &f : fs) {
      const int up = f.c_w >= 0.0 ? f.a : f.b;
      // flux a->b = kdw (p_a - p_b) + c_w theta_up: outflow of a, inflow of b
      for (const auto &[cellnode, sign] : {std::pair<int, double>{f.a, 1.0}, {f.b, -1.0}}) {
        const int row = unknown[cellnode];
        if (row < 0) continue;
        add_p(row, f.a, sign * f.k_over_d_w);
        add_p(row, f.b, -sign * f.k_over_d_w);
        if (f.c_w != 0.0) add_t(row, up, sign * f.c_w);
      }
    }
    for (int k = 0; k < n; ++k) {
      const int row = unknown[k];
      if (row < 0) continue;
      double coef = rate[k] * cell;
      if (!s.theta_prev.empty()) {
        coef += cont[k] * cell / s.dt;
        rhs[row] += cont[k] * cell / s.dt * s.theta_prev[k];
      }
      if (coef != 0.0) add_t(row, k, coef);
    }
    Eigen::SparseMatrix<double> A(m, m);
    A.setFromTriplets(trip.begin(), trip.end());
    lu.compute(A);
    if (lu.info() != Eigen::Success) {
      status_ = ReynoldsStatus::SingularMatrix;
      sol.status = status_;
      sol.iterations = iter;
      return sol;
    }
    u = lu.solve(rhs);
    bool changed = false;
    for (int k = 0; k < n; ++k) {
      if (state[k] == NodeState::Fixed) continue;
      const Affine a = affine(s, state, k);
      const double uk = u[unknown[k]];
      sol.pressure[k] = a.P * uk + a.p0;
      sol.fill[k] = a.T * uk + a.t0;
      const NodeState next = uk >= 0.0 ? NodeState::Full : NodeState::Cavitated;
      if (next != state[k]) changed = true;
      state[k] = next;
    }
    sol.iterations = iter;
    if (!changed) {
      status_ = ReynoldsStatus::Converged;
      break;
    }
  }
  for (int k = 0; k < n; ++k)
    if (s.fixed[k]) {
      sol.pressure[k] = s.fixed_pressure[k];
      sol.fill[k] = s.fixed_fill[k];
    }
  // mass residual of every cell from the face fluxes
  std::vector<double> net(n, 0.0);
  for (const Face &f : fs) {
    const double q = face_flux(f, sol.pressure, sol.fill);
    net[f.a] += q;
    net[f.b] -= q;
  }
  sol.residual = 0.0;
  for (int k = 0; k < n; ++k) {
    if (s.fixed[k]) continue;
    double r = net[k] + rate[k] * cell * sol.fill[k];
    if (!s.theta_prev.empty()) r += cont[k] * cell / s.dt * (sol.fill[k] - s.theta_prev[k]);
    sol.residual = std::max(sol.residual, std::abs(r));
  }
  sol.status = status_;
  return sol;
}

double ReynoldsSolver::flux_x(const ReynoldsSystem &s, const ReynoldsSolution &sol, int i, int j)
{
  const int a = s.index(i, j), b = s.index((i + 1) % s.nx, j);
  const FaceCoefficients c = face_coefficients(s, 0.5 * (s.h[a] + s.h[b]), face_sigma(s, a, b));
  const Face f{a, b, c.kx * s.dy / s.dx, c.couette * s.dy};
  return face_flux(f, sol.pressure, sol.fill);
}

double ReynoldsSolver::flux_y(const ReynoldsSystem &s, const ReynoldsSolution &sol, int i, int j)
{
  const int a = s.index(i, j), b = s.index(i, j + 1);
  const FaceCoefficients c = face_coefficients(s, 0.5 * (s.h[a] + s.h[b]), face_sigma(s, a, b));
  const Face f{a, b, c.ky * s.dx / s.dy, 0.0};
  return face_flux(f, sol.pressure, sol.fill);
}

// ---------------------------------------------------------------------------------------------------
namespace {

// Shear stress on surface 1 (moving at U) at a node: Couette part carried by the filled share theta,
// Poiseuille part phi_fp h/2 dp/dx.
double shear_stress(const ReynoldsSystem &s, double h, double sigma, double fill, double dpdx)
{
  const FilmRoughness &r = s.roughness;
  double f = 1.0, fp = 1.0;
  if (sigma > 0.0) {
    const double H = h / sigma;
    const double s0 = r.sigma();   // the split between the surfaces (a per-node sigma keeps it)
    const double s2 = s0 * s0;
    const double vr = s2 > 0.0 ? (r.sigma_moving * r.sigma_moving - r.sigma_fixed * r.sigma_fixed) / s2 : 0.0;
    f = tribo::shear_stress_factor_f(H) - vr * tribo::shear_stress_factor_fs(H, r.gamma);
    fp = tribo::shear_stress_factor_fp(H, r.gamma);
  }
  return fill * s.viscosity * s.u_moving / h * f + fp * 0.5 * h * dpdx;
}

// Shear on the x-face (i + 1/2, j): midpoint rule of the friction integral, second order. The fill is the
// upwind one the Couette flux carries, so in a cavitated zone theta h_face is the transported content; on a
// fixed boundary row (the bearing ends) it is the adjacent row's (fill_row): the prescribed boundary fill
// only feeds inflow and would otherwise put a full-film strip of width dy/2 into a cavitated zone (O(dy)).
double face_shear(const ReynoldsSystem &s, const ReynoldsSolution &sol, int i, int j, int fill_row,
                  bool full_film = false)
{
  const int a = s.index(i, j), b = s.index((i + 1) % s.nx, j);
  const double h = 0.5 * (s.h[a] + s.h[b]);
  const int up = s.u_moving >= 0.0 ? i : (i + 1) % s.nx;
  const double fill = full_film ? 1.0 : sol.fill[s.index(up, fill_row)];
  return shear_stress(s, h, face_sigma(s, a, b), fill, (sol.pressure[b] - sol.pressure[a]) / s.dx);
}

}    // namespace

void HydroJournalBearing::validate() const
{
  require_positive_finite(radius, "radius");
  require_positive_finite(length, "length");
  require_positive_finite(clearance, "clearance");
  require_positive_finite(viscosity, "viscosity");
  require_finite(omega, "omega");
  if (gap_addition.empty() && (!(eccentricity_ratio >= 0.0) || !(eccentricity_ratio < 1.0)))
    throw InvalidCoefficient("eccentricity_ratio must be in [0, 1) (at 1 the gap closes), got " +
                             std::to_string(eccentricity_ratio));
  if (!gap_addition.empty() && (!(eccentricity_ratio >= 0.0) || !std::isfinite(eccentricity_ratio)))
    throw InvalidCoefficient("eccentricity_ratio must be >= 0 and finite, got " + std::to_string(eccentricity_ratio));
  require_finite(line_of_centres, "line_of_centres");
  if (!gap_addition.empty() && gap_addition.size() != static_cast<std::size_t>(n_theta))
    throw InvalidCoefficient("gap_addition: one value per circumferential node (n_theta) or none");
  for (double v : gap_addition) require_finite(v, "gap_addition");
  if (!node_sigma.empty() && node_sigma.size() != static_cast<std::size_t>(n_theta))
    throw InvalidCoefficient("node_sigma: one value per circumferential node (n_theta) or none");
  for (double v : node_sigma)
    if (!(v >= 0.0) || !std::isfinite(v)) throw InvalidCoefficient("node_sigma must be >= 0 and finite");
  require_finite(groove_angle, "groove_angle");
  if (!(supply_pressure >= 0.0) || !std::isfinite(supply_pressure))
    throw InvalidCoefficient("supply_pressure must be >= 0 and finite");
  if (n_theta < 8) throw InvalidCoefficient("n_theta: at least 8 circumferential nodes needed");
  if (n_axial < 3) throw InvalidCoefficient("n_axial: at least 3 axial nodes needed (both ends included)");
  if (!(boundary_friction >= 0.0) || !std::isfinite(boundary_friction))
    throw InvalidCoefficient("boundary_friction must be >= 0 and finite");
  roughness.validate();
}

namespace {

int groove_column(const HydroJournalBearing &b)
{
  const double a = std::fmod(std::fmod(b.groove_angle, 2.0 * kPi) + 2.0 * kPi, 2.0 * kPi);
  return static_cast<int>(std::lround(a / (2.0 * kPi / b.n_theta))) % b.n_theta;
}

}    // namespace

ReynoldsSystem HydroJournalBearing::system() const
{
  validate();
  ReynoldsSystem s;
  s.nx = n_theta;
  s.ny = n_axial;
  s.dx = 2.0 * kPi * radius / n_theta;
  s.dy = length / (n_axial - 1);
  s.periodic_x = true;
  s.viscosity = viscosity;
  s.u_moving = omega * radius;
  s.roughness = roughness;
  const int n = s.nodes();
  s.h.resize(n);
  s.fixed.assign(n, 0);
  s.fixed_pressure.assign(n, 0.0);
  s.fixed_fill.assign(n, 1.0);
  if (!node_sigma.empty()) {
    s.sigma.resize(n);
    for (int j = 0; j < n_axial; ++j)
      for (int i = 0; i < n_theta; ++i) s.sigma[s.index(i, j)] = node_sigma[i];
  }
  const int g = groove_column(*this);
  for (int j = 0; j < n_axial; ++j)
    for (int i = 0; i < n_theta; ++i) {
      const int k = s.index(i, j);
      s.h[k] = clearance * (1.0 + eccentricity_ratio * std::cos(i * 2.0 * kPi / n_theta - line_of_centres));
      if (!gap_addition.empty()) s.h[k] += gap_addition[i];
      if (j == 0 || j == n_axial - 1) s.fixed[k] = 1;
      else if (i == g) {
        s.fixed[k] = 1;
        s.fixed_pressure[k] = supply_pressure;
      }
    }
  return s;
}

HydroJournalResult solve_journal_bearing(const HydroJournalBearing &b, const tribo::GreenwoodTripp *contact,
                                         const ReynoldsSolver &solver, const std::vector<double> *initial)
{
  const ReynoldsSystem s = b.system();
  HydroJournalResult r;
  r.film = initial ? solver.solve(s, *initial) : solver.solve(s);
  const ReynoldsSolution &sol = r.film;
  const int nx = s.nx, ny = s.ny;
  const double dth = 2.0 * kPi / nx;
  double fx = 0.0, fy = 0.0, ax = 0.0, ay = 0.0, asperity_normal = 0.0, shear = 0.0, cav_area = 0.0;
  std::vector<double> p_asperity(nx, 0.0);   // the gap depends on theta only
  if (contact)
    for (int i = 0; i < nx; ++i) p_asperity[i] = contact->pressure(s.h[s.index(i, 0)]);
  for (int j = 0; j < ny; ++j) {
    const double wy = (j == 0 || j == ny - 1) ? 0.5 : 1.0;
    for (int i = 0; i < nx; ++i) {
      const int k = s.index(i, j);
      const double area = wy * s.dx * s.dy;
      const double th = i * dth - b.line_of_centres;
      const double p = sol.pressure[k];
      fx += p * std::cos(th) * area;
      fy += p * std::sin(th) * area;
      r.peak_pressure = std::max(r.peak_pressure, p);
      const int fill_row = std::clamp(j, 1, ny - 2);
      shear += face_shear(s, sol, i, j, fill_row, b.full_film_shear_in_cavitation) * area;
      if (sol.fill[s.index(i, fill_row)] < 1.0) cav_area += area;
      if (contact) {
        const double pa = p_asperity[i];
        ax += pa * std::cos(th) * area;
        ay += pa * std::sin(th) * area;
        asperity_normal += pa * area;
      }
    }
  }
  r.load_radial = -fx;
  r.load_tangential = fy;
  r.load = std::hypot(fx, fy);
  r.attitude_angle = std::atan2(r.load_tangential, r.load_radial);
  const double n_rev = b.omega / (2.0 * kPi);
  const double P = r.load / (2.0 * b.radius * b.length);
  r.sommerfeld = P > 0.0 ? (b.radius / b.clearance) * (b.radius / b.clearance) * b.viscosity * n_rev / P : 0.0;
  r.asperity_load = std::hypot(ax, ay);
  r.friction_force = shear + b.boundary_friction * asperity_normal;
  r.friction_torque = r.friction_force * b.radius;
  const double total = std::hypot(fx + ax, fy + ay);
  r.total_load = total;
  double film_normal = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      film_normal += ((j == 0 || j == ny - 1) ? 0.5 : 1.0) * s.dx * s.dy * sol.pressure[s.index(i, j)];
  r.asperity_share = asperity_normal > 0.0 ? asperity_normal / (asperity_normal + film_normal) : 0.0;
  r.friction_coefficient = total > 0.0 ? r.friction_force / total : 0.0;
  r.cavitated_fraction = cav_area / (2.0 * kPi * b.radius * b.length);

  const int g = groove_column(b);
  for (int j = 1; j < ny - 1; ++j) {
    r.inlet_flow += ReynoldsSolver::flux_x(s, sol, g, j);
    r.outlet_flow += ReynoldsSolver::flux_x(s, sol, (g + nx - 1) % nx, j);
  }
  for (int i = 0; i < nx; ++i) {
    if (i == g) continue;
    r.side_leakage += -ReynoldsSolver::flux_y(s, sol, i, 0) + ReynoldsSolver::flux_y(s, sol, i, ny - 2);
  }
  // cavitation boundary at mid-length: rupture from sqrt(p) linear to zero (p ~ (theta_c - theta)^2 at a
  // Reynolds-type rupture), reformation at the last cavitated node
  const int jm = ny / 2;
  int first = -1, last = -1;
  for (int step = 1; step < nx; ++step) {
    const int i = (g + step) % nx;
    if (sol.fill[s.index(i, jm)] < 1.0) {
      if (first < 0) first = step;
      last = step;
    }
  }
  if (first > 1) {
    const double p1 = sol.pressure[s.index((g + first - 1) % nx, jm)];
    const double p2 = sol.pressure[s.index((g + first - 2 + nx) % nx, jm)];
    const double s1 = std::sqrt(std::max(p1, 0.0)), s2 = std::sqrt(std::max(p2, 0.0));
    double pos = first - 1;
    if (s2 > s1) pos += std::min(1.0, s1 / (s2 - s1));
    r.rupture_angle = std::fmod(g * dth + pos * dth, 2.0 * kPi);
    r.reformation_angle = std::fmod(g * dth + last * dth, 2.0 * kPi);
  }
  return r;
}

// ---------------------------------------------------------------------------------------------------
void RingFace::validate() const
{
  require_positive_finite(width, "width");
  require_positive_finite(viscosity, "viscosity");
  require_finite(speed, "speed");
  require_positive_finite(min_gap, "min_gap");
  require_finite(squeeze_velocity, "squeeze_velocity");
  require_finite(inlet_pressure, "inlet_pressure");
  require_finite(outlet_pressure, "outlet_pressure");
  if (!(inlet_fill >= 0.0 && inlet_fill <= 1.0)) throw InvalidCoefficient("inlet_fill must be in [0, 1]");
  if (profile.size() < 3) throw InvalidCoefficient("profile: at least 3 nodes needed");
  for (double v : profile)
    if (!(v >= 0.0) || !std::isfinite(v)) throw InvalidCoefficient("profile: heights above h_min must be >= 0");
  if (!fill_prev.empty()) {
    if (fill_prev.size() != profile.size()) throw InvalidCoefficient("fill_prev: one value per profile node needed");
    for (double v : fill_prev)
      if (!(v >= 0.0 && v <= 1.0)) throw InvalidCoefficient("fill_prev must be in [0, 1]");
    require_positive_finite(dt, "dt");
  }
  roughness.validate();
}

ReynoldsSystem RingFace::system() const
{
  validate();
  ReynoldsSystem s;
  s.nx = static_cast<int>(profile.size());
  s.ny = 1;
  s.dx = width / (s.nx - 1);
  s.dy = 1.0;
  s.viscosity = viscosity;
  s.u_moving = speed;
  s.roughness = roughness;
  s.h.resize(s.nx);
  for (int i = 0; i < s.nx; ++i) s.h[i] = min_gap + profile[i];
  s.dhdt.assign(s.nx, squeeze_velocity);
  s.fixed.assign(s.nx, 0);
  s.fixed_pressure.assign(s.nx, 0.0);
  s.fixed_fill.assign(s.nx, 1.0);
  s.fixed[0] = s.fixed[s.nx - 1] = 1;
  s.fixed_pressure[0] = inlet_pressure;
  s.fixed_fill[0] = inlet_fill;
  s.fixed_pressure[s.nx - 1] = outlet_pressure;
  if (!fill_prev.empty()) {
    s.theta_prev = fill_prev;
    s.dt = dt;
  }
  return s;
}

RingFaceResult solve_ring_face(const RingFace &ring, const tribo::GreenwoodTripp *contact, const ReynoldsSolver &solver)
{
  const ReynoldsSystem s = ring.system();
  RingFaceResult r;
  r.film = solver.solve(s);
  const ReynoldsSolution &sol = r.film;
  const int n = s.nx;
  for (int i = 0; i < n; ++i) {
    const double w = (i == 0 || i == n - 1) ? 0.5 : 1.0;
    r.load += w * s.dx * sol.pressure[i];
    if (i + 1 < n) r.friction += s.dx * face_shear(s, sol, i, 0, 0);
    if (contact) r.asperity_load += w * s.dx * contact->pressure(s.h[i]);
  }
  r.inlet_flow = ReynoldsSolver::flux_x(s, sol, 0, 0);
  r.outlet_flow = ReynoldsSolver::flux_x(s, sol, n - 2, 0);
  return r;
}

}    // namespace runin::continuum
