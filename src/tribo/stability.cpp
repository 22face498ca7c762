#include "tribo/stability.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace runin::tribo {

namespace {
constexpr double kPi = 3.14159265358979323846;

void require_positive(double value, const char *what)
{
  if (!(value > 0.0) || !std::isfinite(value)) throw InvalidCoefficient(std::string(what) + " must be > 0");
}

// E = 2 (1 - nu^2) E* of the like pair; an E* near the largest double overflows it (E* = 1e308 did, and was
// then reported as a shear modulus that is not > 0)
Material like_pair_material(double e_eff, double nu)
{
  Material m;
  m.poisson_ratio = nu;
  m.youngs_modulus = 2.0 * (1.0 - nu * nu) * e_eff;
  if (!std::isfinite(m.youngs_modulus)) {
    char message[160];
    std::snprintf(message, sizeof message,
                  "E*: effective modulus %.4g is too large (its Young's modulus 2 (1 - nu^2) E* overflows)", e_eff);
    throw InvalidCoefficient(message);
  }
  return m;
}
}    // namespace

double rayleigh_speed_ratio(double poisson_ratio)
{
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    throw InvalidCoefficient("nu: Poisson ratio must be in (-1, 0.5)");
  return 0.1631 * poisson_ratio + 0.8766;
}

double rayleigh_time(double radius, double shear_modulus, double poisson_ratio, double density)
{
  require_positive(radius, "R: radius");
  require_positive(shear_modulus, "G: shear modulus");
  require_positive(density, "rho: density");
  return kPi * radius * std::sqrt(density / shear_modulus) / rayleigh_speed_ratio(poisson_ratio);
}

double rayleigh_time(double radius, const Material &material, double density)
{
  return rayleigh_time(radius, material.shear_modulus(), material.poisson_ratio, density);
}

double hertz_max_overlap(double e_eff, double r_eff, double m_eff, double v)
{
  require_positive(e_eff, "E*: effective modulus");
  require_positive(r_eff, "R*: effective radius");
  require_positive(m_eff, "m*: effective mass");
  require_positive(v, "v: impact speed");
  return std::pow(15.0 * m_eff * v * v / (16.0 * e_eff * std::sqrt(r_eff)), 0.4);
}

double hertz_contact_time(double e_eff, double r_eff, double m_eff, double v)
{
  static const double half_period_integral = 0.4 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  return 2.0 * half_period_integral * hertz_max_overlap(e_eff, r_eff, m_eff, v) / v;
}

double verlet_limit(double stiffness, double m_eff)
{
  require_positive(stiffness, "k: stiffness");
  require_positive(m_eff, "m*: effective mass");
  return 2.0 * std::sqrt(m_eff / stiffness);
}

double hertz_verlet_limit(double e_eff, double r_eff, double m_eff, double overlap)
{
  require_positive(overlap, "delta: overlap");
  return verlet_limit(HertzNormal(e_eff, r_eff).stiffness(overlap), m_eff);
}

double cfl_time_step(double element_size, double youngs_modulus, double density, double beta)
{
  require_positive(element_size, "h: element size");
  require_positive(youngs_modulus, "E: Young's modulus");
  require_positive(density, "rho: density");
  if (!(beta > 0.0 && beta <= 1.0)) throw InvalidCoefficient("beta: CFL factor must be in (0, 1]");
  return beta * element_size / std::sqrt(youngs_modulus / density);
}

Material equivalent_material(double e_eff, double g_eff)
{
  require_positive(e_eff, "E*: effective modulus");
  require_positive(g_eff, "G*: effective shear modulus");
  const double r = g_eff / e_eff;
  // nu in (-1, 0.5) maps to r in (1/6, 1/3)
  if (!(r > 1.0 / 6.0 && r < 1.0 / 3.0))
    throw InvalidCoefficient("G*/E*: must be in (1/6, 1/3) for an isotropic material, got " + std::to_string(r));
  return like_pair_material(e_eff, (1.0 - 4.0 * r) / (1.0 - 2.0 * r));
}

Material equivalent_material(double e_eff, double g_eff, double fallback_nu)
{
  require_positive(e_eff, "E*: effective modulus");
  const double r = g_eff / e_eff;
  if (r > 1.0 / 6.0 && r < 1.0 / 3.0) return equivalent_material(e_eff, g_eff);
  if (!(fallback_nu > -1.0 && fallback_nu < 0.5)) throw InvalidCoefficient("nu: Poisson ratio must be in (-1, 0.5)");
  return like_pair_material(e_eff, fallback_nu);
}

TimeStepVerdict judge_time_step(double dt, double rayleigh)
{
  if (dt > TimeStepPolicy::fail_factor * rayleigh) return TimeStepVerdict::fail;
  if (dt > TimeStepPolicy::warn_fraction * rayleigh) return TimeStepVerdict::warn;
  return TimeStepVerdict::ok;
}

}    // namespace runin::tribo
