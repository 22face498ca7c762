// What the values and optional keywords of pair_coeff runin/asperity mean, shared by the LAMMPS and the LIGGGHTS
// pair (each reads and checks the words itself, with its own messages).
#ifndef RUNIN_PAIR_COEFFICIENTS_H
#define RUNIN_PAIR_COEFFICIENTS_H

#include "tribo/contact_model.h"

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <string>
#include <vector>

namespace runin_pair {

inline constexpr int kExplicitValues = 8;
inline constexpr const char *kExplicitNames[kExplicitValues] = {"E*", "G*", "e", "mu_s", "mu_k", "d_c", "k", "H"};

// 'I J E* G* e mu_s mu_k d_c k H': one hardness for both types, S_y from it (Tabor) unless 'S_y' follows.
inline runin::tribo::ContactParameters explicit_parameters(const double *v)
{
  runin::tribo::ContactParameters p;
  p.effective_modulus = v[0];
  p.effective_shear_modulus = v[1];
  p.restitution = v[2];
  p.mu_static = v[3];
  p.mu_kinetic = v[4];
  p.slip_weakening_distance = v[5];
  p.wear_coefficient = v[6];
  p.hardness_i = p.hardness_j = v[7];
  p.yield_strength = v[7] / runin::tribo::kTaborConstraintFactor;
  p.yield_from_hardness = true;
  return p;
}

// For an ERROR on a wrong number of explicit values: " (missing: d_c k H)" or " (2 too many)".
inline std::string explicit_count_problem(int given)
{
  if (given >= kExplicitValues) return fmt::format(" ({} too many)", given - kExplicitValues);
  std::string missing;
  for (int k = given; k < kExplicitValues; k++) missing += fmt::format("{}{}", missing.empty() ? "" : " ", kExplicitNames[k]);
  return fmt::format(" (missing: {})", missing);
}

// The optional keywords with a number after the values: tau_s, plough, S_y, nu, f, alpha, and with `film`
// (a host that keeps the film coverage) f_film, s_r, k_g.
inline bool optional_keyword(const std::string &keyword, bool film)
{
  for (const char *name : {"tau_s", "plough", "S_y", "nu", "f", "alpha"})
    if (keyword == name) return true;
  return film && (keyword == "f_film" || keyword == "s_r" || keyword == "k_g");
}

inline void set_optional(runin::tribo::ContactParameters &p, const std::string &keyword, double value)
{
  if (keyword == "tau_s")
    p.shear_strength = value;
  else if (keyword == "plough")
    p.ploughing_factor = value;
  else if (keyword == "nu")
    p.poisson_ratio = value;
  else if (keyword == "f")
    p.interface_coefficient = value;
  else if (keyword == "alpha")
    p.junction_alpha = value;
  else if (keyword == "f_film")
    p.film_interface_coefficient = value;
  else if (keyword == "s_r")
    p.film_removal_distance = value;
  else if (keyword == "k_g")
    p.film_growth_rate = value;
  else {
    p.yield_strength = value;
    p.yield_from_hardness = false;
  }
}

// The largest radius per type over all ranks (out: ntypes + 1 values): it bounds the contact cutoff.
inline void largest_radius_per_type(const double *radius, const int *type, int nlocal, int ntypes, MPI_Comm world,
                                    double *out)
{
  std::vector<double> local(ntypes + 1, 0.0);
  for (int i = 0; i < nlocal; i++) local[type[i]] = std::max(local[type[i]], radius[i]);
  MPI_Allreduce(local.data(), out, ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
}

}    // namespace runin_pair

#endif
