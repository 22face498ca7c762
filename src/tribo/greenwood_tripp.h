// Greenwood & Tripp (1970-71) contact of two Gaussian rough surfaces, reduced to one rough surface of
// combined summit roughness sigma against a flat. With eta the summit density, beta the summit radius,
// E* the contact modulus and H = h / sigma the film parameter (h between the mean planes):
//   p_a(h) = K E* F_5/2(H),   K = (16 sqrt 2 / 15) pi (eta beta sigma)^2 sqrt(sigma / beta)
//   A_a / A = pi^2 (eta beta sigma)^2 F_2(H)
// F_n(H) = (2 pi)^-1/2 int_H^inf (s - H)^n exp(-s^2 / 2) ds. F_0, F_1, F_2 in closed form (erfc, exp);
// F_3/2, F_5/2 by composite Gauss-Legendre quadrature in t = sqrt(s - H) (relative accuracy ~1e-13,
// checked against an independent quadrature in the unit test). A load-sharing solve finds the film parameter at which the film and the
// asperities together carry a nominal load (Johnson, Greenwood & Poon 1972).
#pragma once

#include <functional>

namespace runin::tribo {

// Standard Gaussian tail moment F_n(H) (n >= 0).
double greenwood_tripp_f(double n, double H);

// Worn summits (a run-in surface: the top of the height distribution cut off, Pawlus, Reizer & Wieczorowski 2022,
// "Two-process random textures", Materials 15:268; ISO 13565-3). Every summit higher than the top T is flattened
// to T: F_n(H; T) = int_H^T (s - H)^n phi(s) ds + (T - H)^n Q(T) for H < T, and 0 for H >= T, so no summit
// touches a counterface farther than T. T = +inf: F_n(H).
double greenwood_tripp_f_truncated(double n, double H, double T);
// Summit heights after the cut, in units of sigma: sqrt(var(min(x, T))) for x ~ N(0, 1).
double truncated_rms_ratio(double T);

class GreenwoodTripp {
 public:
  // eta: summits per m^2; beta: summit radius (m); sigma: combined rms roughness (m); E*: Pa.
  GreenwoodTripp(double summit_density, double summit_radius, double sigma, double effective_modulus);

  double pressure(double h) const;        // Pa, nominal asperity pressure at gap h (mean planes)
  double area_fraction(double h) const;   // -, real contact area over nominal area
  // The same with the summits cut at `top` (m above the summits' original mean plane; +inf: uncut).
  double pressure(double h, double top) const;
  double area_fraction(double h, double top) const;
  // Worn summits: the volume per nominal area (m) that cutting every summit at `top` removes, pi eta beta sigma^2
  // F_2(top / sigma) (spherical caps of depth d hold pi beta d^2, the Hertz/GW small-cap geometry), and its
  // inverse: the top after a worn volume w (m; 0: +inf).
  double worn_volume(double top) const;
  double top_after_wear(double worn_volume) const;
  double load(double h, double nominal_area) const { return pressure(h) * nominal_area; }   // N
  double coefficient() const { return k_; }   // K (-), p_a = K E* F_5/2

  double summit_density() const { return eta_; }
  double summit_radius() const { return beta_; }
  double sigma() const { return sigma_; }
  double effective_modulus() const { return e_eff_; }

 private:
  double eta_, beta_, sigma_, e_eff_, k_;
};

enum class LoadShareStatus { Converged, FilmCarriesAll, NotBracketed, NotConverged };
const char *to_string(LoadShareStatus status);

struct LoadShare {
  LoadShareStatus status = LoadShareStatus::NotConverged;
  double h = 0.0;              // m, film thickness (mean planes) carrying the load
  double film_parameter = 0.0; // h / sigma
  double film_load = 0.0;      // N
  double asperity_load = 0.0;  // N
  double asperity_fraction = 0.0;   // asperity_load / load
  int iterations = 0;
  bool ok() const { return status == LoadShareStatus::Converged; }
};

// Finds h in [h_min, h_max] with film_load(h) + contact.load(h, nominal_area) = load (both decreasing in h).
// film_load: N, the hydrodynamic load at gap h (e.g. a Reynolds solve). Brent's method to a relative load
// tolerance rel_tol. FilmCarriesAll: the load is reached at h_max with no asperity share worth resolving.
LoadShare solve_load_share(double load, const std::function<double(double)> &film_load,
                           const GreenwoodTripp &contact, double nominal_area, double h_min, double h_max,
                           double rel_tol = 1e-10, int max_iterations = 200);

// General form for a non-uniform gap (a journal bearing): h is the film's control gap (e.g. h_min),
// asperity_load(h) the asperity load integrated over the surface; film_parameter = h / sigma.
LoadShare solve_load_share(double load, const std::function<double(double)> &film_load,
                           const std::function<double(double)> &asperity_load, double sigma, double h_min,
                           double h_max, double rel_tol = 1e-10, int max_iterations = 200);

}    // namespace runin::tribo
