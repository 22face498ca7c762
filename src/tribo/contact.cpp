#include "tribo/contact.h"

#include <algorithm>
#include <cmath>

namespace runin::tribo {

namespace {
void require(bool ok, const std::string &what)
{
  if (!ok) throw InvalidCoefficient(what);
}
constexpr double kPi = 3.14159265358979323846;
}    // namespace

void Material::validate(const std::string &name) const
{
  require(youngs_modulus > 0.0, name + ": Young's modulus must be > 0");
  require(poisson_ratio > -1.0 && poisson_ratio < 0.5, name + ": Poisson ratio must be in (-1, 0.5)");
  require(hardness > 0.0, name + ": hardness must be > 0");
}

double effective_modulus(const Material &a, const Material &b)
{
  return 1.0 / ((1.0 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                (1.0 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
}

double effective_shear_modulus(const Material &a, const Material &b)
{
  return 1.0 / ((2.0 - a.poisson_ratio) / a.shear_modulus() + (2.0 - b.poisson_ratio) / b.shear_modulus());
}

double effective_radius(double radius_a, double radius_b)
{
  return radius_a * radius_b / (radius_a + radius_b);
}

HertzNormal::HertzNormal(double effective_modulus, double effective_radius)
    : e_eff_(effective_modulus), r_eff_(effective_radius)
{
  require(e_eff_ > 0.0, "E*: effective modulus must be > 0");
  require(r_eff_ > 0.0, "R*: effective radius must be > 0");
}

double HertzNormal::contact_radius(double overlap) const
{
  return overlap > 0.0 ? std::sqrt(r_eff_ * overlap) : 0.0;
}

double HertzNormal::force(double overlap) const
{
  return overlap > 0.0 ? 4.0 / 3.0 * e_eff_ * contact_radius(overlap) * overlap : 0.0;
}

double HertzNormal::stiffness(double overlap) const
{
  return 2.0 * e_eff_ * contact_radius(overlap);
}

double HertzNormal::elastic_energy(double overlap) const
{
  return overlap > 0.0 ? 8.0 / 15.0 * e_eff_ * contact_radius(overlap) * overlap * overlap : 0.0;
}

RestitutionDamping::RestitutionDamping(double e) : restitution_(e), factor_(0.0)
{
  require(e > 0.0 && e <= 1.0, "e: coefficient of restitution must be in (0, 1]");
  if (e < 1.0) {
    const double log_e = std::log(e);
    const double beta = log_e / std::sqrt(log_e * log_e + kPi * kPi);
    factor_ = -2.0 * std::sqrt(5.0 / 6.0) * beta;    // > 0
  }
}

double RestitutionDamping::force(double normal_stiffness, double effective_mass,
                                 double normal_velocity) const
{
  if (factor_ == 0.0) return 0.0;
  return -factor_ * std::sqrt(normal_stiffness * effective_mass) * normal_velocity;
}

StaticKineticFriction::StaticKineticFriction(double mu_static, double mu_kinetic, double d_c)
    : mu_s_(mu_static), mu_k_(mu_kinetic), d_c_(d_c)
{
  require(mu_s_ >= 0.0, "mu_s: static friction coefficient must be >= 0");
  require(mu_k_ >= 0.0, "mu_k: kinetic friction coefficient must be >= 0");
  require(mu_k_ <= mu_s_, "mu_k: kinetic friction coefficient must not exceed mu_s");
  require(d_c_ >= 0.0, "d_c: slip-weakening distance must be >= 0");
}

double StaticKineticFriction::coefficient(double slip) const
{
  if (slip <= 0.0) return mu_s_;
  if (d_c_ == 0.0) return mu_k_;
  return mu_k_ + (mu_s_ - mu_k_) * std::max(0.0, 1.0 - slip / d_c_);
}

TangentialUpdate mindlin_coulomb(double kt, double normal_force, const StaticKineticFriction &friction,
                                 const double n[3], const double vt[3], double dt, double spring[3],
                                 double &slip, bool advance)
{
  TangentialUpdate out;
  double trial[3] = {spring[0], spring[1], spring[2]};
  if (advance)
    for (int k = 0; k < 3; ++k) trial[k] += vt[k] * dt;

  // Keep the spring in the current tangent plane (the contact normal rotates as bodies move).
  const double along_normal = trial[0] * n[0] + trial[1] * n[1] + trial[2] * n[2];
  for (int k = 0; k < 3; ++k) trial[k] -= along_normal * n[k];

  double ft[3];
  for (int k = 0; k < 3; ++k) ft[k] = -kt * trial[k];
  const double ft_mag = std::sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]);
  const double limit = friction.coefficient(slip) * std::max(normal_force, 0.0);

  if (ft_mag > limit) {
    out.slipping = true;
    const double scale = ft_mag > 0.0 ? limit / ft_mag : 0.0;
    double slipped_sq = 0.0;
    for (int k = 0; k < 3; ++k) {
      ft[k] *= scale;
      const double relaxed = trial[k] * scale;
      slipped_sq += (trial[k] - relaxed) * (trial[k] - relaxed);
      trial[k] = relaxed;
    }
    out.slip_increment = std::sqrt(slipped_sq);
  }
  for (int k = 0; k < 3; ++k) out.force[k] = ft[k];
  if (advance) {
    for (int k = 0; k < 3; ++k) spring[k] = trial[k];
    slip += out.slip_increment;
  }
  return out;
}

}    // namespace runin::tribo
