// Contact-mechanics kernels shared by the LAMMPS styles and the continuum layer.
// Pure functions and small value classes: no LAMMPS, no I/O. SI units throughout.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace runin::tribo {

// Thrown by the coefficient classes; the message names the offending coefficient.
class InvalidCoefficient : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Throws InvalidCoefficient "<name> must be > 0 and finite, got <value>" unless value is positive and finite.
inline void require_positive_finite(double value, const std::string &name) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw InvalidCoefficient(name + " must be > 0 and finite, got " + std::to_string(value));
}

// Elastic properties of one body.
struct Material {
  double youngs_modulus = 0.0;  // Pa
  double poisson_ratio = 0.0;   // -
  double hardness = 0.0;        // Pa (indentation hardness, used by Archard)
  double yield_strength = 0.0;  // Pa (uniaxial S_y, elastic-plastic contact); 0: unknown (Tabor's H / 2.8)

  void validate(const std::string &name = "material") const;
  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
};

// 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2
double effective_modulus(const Material &a, const Material &b);
// Mindlin: 1/G* = (2-nu1)/G1 + (2-nu2)/G2
double effective_shear_modulus(const Material &a, const Material &b);
// 1/R* = 1/R1 + 1/R2
double effective_radius(double radius_a, double radius_b);

// Hertz sphere-sphere contact: F = 4/3 E* sqrt(R*) delta^(3/2).
class HertzNormal {
 public:
  HertzNormal(double effective_modulus, double effective_radius);

  double contact_radius(double overlap) const;  // a = sqrt(R* delta)
  double force(double overlap) const;
  double stiffness(double overlap) const;        // dF/d(delta) = 2 E* a
  double elastic_energy(double overlap) const;   // 8/15 E* sqrt(R*) delta^(5/2)

 private:
  double e_eff_, r_eff_;
};

// Viscoelastic normal damping parametrised by a coefficient of restitution, in the Tsuji et al. (1992)
// form F_d = -c sqrt(k_n m*) v_n with k_n the current Hertz stiffness. With k_n ~ delta^(1/2) the impact
// is self-similar, so e depends on c alone; c is calibrated once per e by integrating the nondimensional
// Hertz impact x'' = -max(0, x^(3/2) + c sqrt(3/2) x^(1/4) x') (separation where the clamped total force
// reaches zero, as the contact styles evaluate it), so a head-on Hertz impact rebounds with exactly e.
// (The linear-spring mapping c = -2 sqrt(5/6) ln e / sqrt(ln^2 e + pi^2) misses e by up to 10 %.)
// e = 1 switches damping off exactly. Below kMinimumRestitution the calibration's damping factor leaves the
// range its root search covers (and a rebound of 1e-6 of the approach speed is already a plastic impact).
inline constexpr double kMinimumRestitution = 1e-6;
class RestitutionDamping {
 public:
  explicit RestitutionDamping(double coefficient_of_restitution);
  // Restitution of a head-on Hertz impact with damping factor c (the ODE above; 1 for c = 0).
  static double hertz_restitution(double damping_factor);

  // Damping force along the contact normal; normal_velocity < 0 means approach.
  double force(double normal_stiffness, double effective_mass, double normal_velocity) const
  {
    if (factor_ == 0.0) return 0.0;
    return -factor_ * std::sqrt(normal_stiffness * effective_mass) * normal_velocity;
  }
  double restitution() const { return restitution_; }
  bool enabled() const { return factor_ != 0.0; }

 private:
  double restitution_, factor_;
};

// Friction limit with a static-to-kinetic transition over a slip distance d_c:
// mu(slip) = mu_k + (mu_s - mu_k) max(0, 1 - slip/d_c); d_c = 0 drops to mu_k at first slip.
class StaticKineticFriction {
 public:
  StaticKineticFriction(double mu_static, double mu_kinetic, double slip_weakening_distance);

  double coefficient(double accumulated_slip) const
  {
    if (accumulated_slip <= 0.0) return mu_s_;
    if (d_c_ == 0.0) return mu_k_;
    return mu_k_ + (mu_s_ - mu_k_) * std::max(0.0, 1.0 - accumulated_slip * inv_d_c_);
  }
  // The part of coefficient() above mu_k: (mu_s - mu_k) max(0, 1 - slip/d_c).
  double static_excess(double accumulated_slip) const
  {
    if (accumulated_slip <= 0.0) return mu_s_ - mu_k_;
    if (d_c_ == 0.0) return 0.0;
    return (mu_s_ - mu_k_) * std::max(0.0, 1.0 - accumulated_slip * inv_d_c_);
  }
  // Limit force when the kinetic level is given as a force (e.g. adhesion + ploughing, friction_strength.h):
  // kinetic_force + static_excess(slip) F_n; with kinetic_force = mu_k F_n this is coefficient(slip) F_n.
  double limit_force(double accumulated_slip, double normal_force, double kinetic_force) const
  {
    return kinetic_force + static_excess(accumulated_slip) * normal_force;
  }
  double mu_static() const { return mu_s_; }
  double mu_kinetic() const { return mu_k_; }
  double slip_weakening_distance() const { return d_c_; }

 private:
  double mu_s_, mu_k_, d_c_;
  double inv_d_c_;    // 1 / d_c (0 for d_c = 0): a multiplication in the force loop
};

// Outcome of one tangential update of a contact.
struct TangentialUpdate {
  double force[3] = {0.0, 0.0, 0.0};  // on body i
  double force_magnitude = 0.0;        // |force|
  double slip_increment = 0.0;         // sliding distance taken by the slider this step
  bool slipping = false;
};

// The Mindlin spring of mindlin_coulomb below with its Coulomb limit given as a force (>= 0), for force
// loops that compute the limit themselves. Inline: it runs once per contact and step.
//
// The update is LAMMPS's pair granular 'tangential mindlin' (GRANULAR/pair_granular.cpp, compute(),
// LAMMPS 29Sep2021) operation for operation, so that without damping the two agree to round-off:
//  1. frame update: if the stored spring has a normal part that matters, |xi.n| k_t > 1e-10 limit
//     (LAMMPS's EPSILON * Fscrit), it is projected onto the current tangent plane and rescaled to its old
//     length (Luding 2008, Granular Matter 10:235, eq. 17): a rotating contact turns the spring, it
//     does not shorten it. Below the threshold it is left as is (the same branch as LAMMPS);
//  2. xi += v_t dt (v_t is tangential by construction, so xi is not projected again);
//  3. F_t = -k_t xi; if |F_t| > limit, F_t is scaled to the limit and the spring set to -F_t / k_t, with
//     the expressions of LAMMPS (spring = -1/k_t (limit F_t / |F_t|), F_t *= limit / |F_t|).
// RunIn's own parts: the limit is the caller's (static -> kinetic weakening, friction strength, F_n
// clamped at 0); slip_increment is the length by which the spring was shortened at the limit,
// (|F_t| - limit) / k_t = |xi| - limit / k_t, and is added to 'slip' (LAMMPS keeps no slip distance).
// With advance = false (LAMMPS setup) nothing is stored: the force comes from the stored spring after the
// frame update of step 1 on a copy (LAMMPS takes the stored spring unrotated, and at the limit rescales it
// even at setup); in a continued run the spring is already in the tangent plane, so the two agree.
inline TangentialUpdate mindlin_spring(double kt, double limit, const double n[3], const double vt[3], double dt,
                                       double spring[3], double &slip, bool advance)
{
  TangentialUpdate out;
  double xi[3] = {spring[0], spring[1], spring[2]};

  // 1. rotate into the current tangent plane, keeping the length
  const double along_normal = xi[0] * n[0] + xi[1] * n[1] + xi[2] * n[2];
  if (std::fabs(along_normal) * kt > 1e-10 * limit) {
    // one square root of the squared ratio: LAMMPS takes two (both lengths), a longer chain of dependent
    // operations for the same factor to rounding. A spring (almost) along the normal has no direction in
    // the plane left: it is dropped, as LAMMPS drops a zero projection (the ratio stays finite). The test
    // scales the projection up, not the length down: 1e-300 |xi|^2 of a micrometre spring is subnormal,
    // and subnormal arithmetic costs the force loop about half its speed.
    const double length_sq = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
    for (int k = 0; k < 3; ++k) xi[k] -= along_normal * n[k];
    const double projected_sq = xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2];
    const double restore = projected_sq * 1e300 > length_sq ? std::sqrt(length_sq / projected_sq) : 0.0;
    for (int k = 0; k < 3; ++k) xi[k] *= restore;
  }
  // 2. advance with the tangential relative velocity
  if (advance)
    for (int k = 0; k < 3; ++k) xi[k] += vt[k] * dt;

  // 3. trial force and the Coulomb limit
  double ft[3];
  for (int k = 0; k < 3; ++k) ft[k] = -kt * xi[k];
  const double ft_mag = std::sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]);
  out.force_magnitude = ft_mag;
  if (ft_mag > limit) {
    // (LAMMPS also tests |xi| != 0 here: with a finite k_t, |F_t| > limit >= 0 implies it)
    out.slipping = true;
    out.force_magnitude = limit;
    // two divisions where LAMMPS takes five (xi = -limit F_t / (|F_t| k_t) per component): equal to rounding
    const double inv_kt = 1.0 / kt, scale = limit / ft_mag;
    // the spring shrinks along itself from |xi| = |F_t| / k_t to limit / k_t: the slider slips by the difference
    out.slip_increment = (ft_mag - limit) * inv_kt;
    for (int k = 0; k < 3; ++k) {
      ft[k] *= scale;
      xi[k] = -inv_kt * ft[k];
    }
  }
  for (int k = 0; k < 3; ++k) out.force[k] = ft[k];
  if (advance) {
    for (int k = 0; k < 3; ++k) spring[k] = xi[k];
    slip += out.slip_increment;
  }
  return out;
}

// Mindlin-type tangential spring (k_t = 8 G* a) with history and a Coulomb limit.
// 'spring' is the stored tangential displacement (3 values) and 'slip' the accumulated
// slip distance; both persist per contact. 'normal' is the unit normal (j -> i),
// 'tangential_velocity' the relative tangential velocity of i w.r.t. j.
// When 'advance' is false (LAMMPS setup) the history is read but not changed.
// The limit is mu(slip) max(F_n, 0): a negative normal force gives no friction (LAMMPS: mu |F_n|).
inline TangentialUpdate mindlin_coulomb(double tangential_stiffness, double normal_force,
                                        const StaticKineticFriction &friction, const double normal[3],
                                        const double tangential_velocity[3], double dt, double spring[3],
                                        double &slip, bool advance)
{
  const double limit = friction.coefficient(slip) * std::max(normal_force, 0.0);
  return mindlin_spring(tangential_stiffness, limit, normal, tangential_velocity, dt, spring, slip, advance);
}

// Re-stick (healing): a contact that did not slip in this step while its tangential relative speed is
// below 'restick_speed' sticks again, and its accumulated slip resets so the limit returns to mu_s.
// restick_speed = 0 never heals (the limit stays weakened for the life of the contact).
inline bool resticks(const TangentialUpdate &update, double tangential_speed, double restick_speed)
{
  return restick_speed > 0.0 && !update.slipping && tangential_speed < restick_speed;
}
// The same test from the squared speed (no square root in the force loop).
inline bool resticks_squared(const TangentialUpdate &update, double tangential_speed_sq, double restick_speed)
{
  return restick_speed > 0.0 && !update.slipping && tangential_speed_sq < restick_speed * restick_speed;
}

inline double mindlin_stiffness(double effective_shear_modulus, double contact_radius)
{
  return 8.0 * effective_shear_modulus * contact_radius;
}

}    // namespace runin::tribo
