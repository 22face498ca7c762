// Contact-mechanics kernels shared by the LAMMPS styles and the continuum layer.
// Pure functions and small value classes: no LAMMPS, no I/O. SI units throughout.
#pragma once

#include <stdexcept>
#include <string>

namespace runin::tribo {

// Thrown by the coefficient classes; the message names the offending coefficient.
class InvalidCoefficient : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Elastic properties of one body.
struct Material {
  double youngs_modulus = 0.0;  // Pa
  double poisson_ratio = 0.0;   // -
  double hardness = 0.0;        // Pa (indentation hardness, used by Archard)

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

// Viscoelastic normal damping parametrised by a coefficient of restitution
// (Tsuji et al. 1992): F_d = -2 sqrt(5/6) beta sqrt(k_n m*) v_n, beta = ln e / sqrt(ln^2 e + pi^2),
// with k_n the current Hertz stiffness. e = 1 switches damping off exactly.
class RestitutionDamping {
 public:
  explicit RestitutionDamping(double coefficient_of_restitution);

  // Damping force along the contact normal; normal_velocity < 0 means approach.
  double force(double normal_stiffness, double effective_mass, double normal_velocity) const;
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

  double coefficient(double accumulated_slip) const;
  double mu_static() const { return mu_s_; }
  double mu_kinetic() const { return mu_k_; }

 private:
  double mu_s_, mu_k_, d_c_;
};

// Outcome of one tangential update of a contact.
struct TangentialUpdate {
  double force[3] = {0.0, 0.0, 0.0};  // on body i
  double slip_increment = 0.0;         // sliding distance taken by the slider this step
  bool slipping = false;
};

// Mindlin-type tangential spring (k_t = 8 G* a) with history and a Coulomb limit.
// 'spring' is the stored tangential displacement (3 values) and 'slip' the accumulated
// slip distance; both persist per contact. 'normal' is the unit normal (j -> i),
// 'tangential_velocity' the relative tangential velocity of i w.r.t. j.
// When 'advance' is false (LAMMPS setup) the history is read but not changed.
TangentialUpdate mindlin_coulomb(double tangential_stiffness, double normal_force,
                                 const StaticKineticFriction &friction, const double normal[3],
                                 const double tangential_velocity[3], double dt, double spring[3],
                                 double &slip, bool advance);

// Re-stick (healing): a contact that did not slip in this step while its tangential relative speed is
// below 'restick_speed' sticks again, and its accumulated slip resets so the limit returns to mu_s.
// restick_speed = 0 never heals (the limit stays weakened for the life of the contact).
inline bool resticks(const TangentialUpdate &update, double tangential_speed, double restick_speed)
{
  return restick_speed > 0.0 && !update.slipping && tangential_speed < restick_speed;
}

inline double mindlin_stiffness(double effective_shear_modulus, double contact_radius)
{
  return 8.0 * effective_shear_modulus * contact_radius;
}

}    // namespace runin::tribo
