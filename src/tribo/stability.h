// Explicit-integration stability of asperity contact: critical timestep estimates.
// Pure functions, no LAMMPS, SI units. The LAMMPS timestep guard and the benchmarks use them.
#pragma once

#include "tribo/contact.h"

namespace runin::tribo {

// Rayleigh wave speed over shear wave speed, c_R / c_S ~ 0.1631 nu + 0.8766 (fit to the root of
// the Rayleigh equation; within 0.4 % for 0 <= nu < 0.5).
double rayleigh_speed_ratio(double poisson_ratio);

// Time a Rayleigh wave takes to cross a sphere of radius R, the usual DEM critical step:
// t_R = pi R sqrt(rho / G) / (0.1631 nu + 0.8766).
double rayleigh_time(double radius, double shear_modulus, double poisson_ratio, double density);
double rayleigh_time(double radius, const Material &material, double density);

// Head-on Hertz impact at relative normal speed v (F = 4/3 E* sqrt(R*) delta^3/2, reduced mass m*):
// largest overlap delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^(2/5) and contact duration
// t_c = 2 I delta_max / v, I = int_0^1 dx / sqrt(1 - x^(5/2)) = (2/5) B(2/5, 1/2).
double hertz_max_overlap(double effective_modulus, double effective_radius, double effective_mass,
                         double impact_speed);
double hertz_contact_time(double effective_modulus, double effective_radius, double effective_mass,
                          double impact_speed);

// Velocity Verlet is stable on a spring k for dt < 2 sqrt(m/k). For a Hertz contact k is the
// tangent stiffness at the overlap, k_n = 2 E* sqrt(R* delta).
double verlet_limit(double stiffness, double effective_mass);
double hertz_verlet_limit(double effective_modulus, double effective_radius, double effective_mass,
                          double overlap);

// Thesis eq. 2.1 (CFL): dt <= beta h / a, a = sqrt(E / rho), h the smallest element size, 0 < beta <= 1.
double cfl_time_step(double element_size, double youngs_modulus, double density, double beta = 1.0);

// The like-material pair with the given E* and G* (1/E* = 2(1-nu^2)/E, 1/G* = 2(2-nu)/G):
// nu = (1 - 4r) / (1 - 2r), r = G*/E*. For an unlike pair it is an equivalent material.
// Hardness is not determined and is left 0.
Material equivalent_material(double effective_modulus, double effective_shear_modulus);
// As above, but when G*/E* is not that of an isotropic like pair (explicit, hand-set coefficients)
// keep E* and take nu = fallback_poisson_ratio. The Rayleigh time then depends on nu only through
// sqrt(1/(1-nu)) / (0.1631 nu + 0.8766): within +-6 % of nu = 0.3 for 0.2 <= nu <= 0.4.
Material equivalent_material(double effective_modulus, double effective_shear_modulus,
                             double fallback_poisson_ratio);

// Timestep policy of the LAMMPS guard, in units of the smallest Rayleigh time t_R.
// warn above 0.2 t_R (common DEM practice is 0.1-0.3 t_R); fail above 4 t_R, where Verlet is unstable
// on every Hertz contact deeper than ~1e-3 R (doc/benchmarks-micro.md, "Timestep guard").
struct TimeStepPolicy {
  static constexpr double warn_fraction = 0.2;
  static constexpr double fail_factor = 4.0;
};
enum class TimeStepVerdict { ok, warn, fail };
TimeStepVerdict judge_time_step(double dt, double rayleigh_time);

}    // namespace runin::tribo
