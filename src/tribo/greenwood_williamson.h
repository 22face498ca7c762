// Greenwood-Williamson (1966) rough-surface contact against a rigid flat: identical spherical
// summits of radius R, areal density eta, Gaussian summit heights (std sigma, mean 0), each a
// Hertz contact. Pure functions, SI units.
#pragma once

namespace runin::tribo {

// Tail moment of the Gaussian summit-height density phi (mean 0, std sigma):
//   F_nu(d) = int_d^inf (z - d)^nu phi(z) dz,  nu >= 0.
// Computed by Gauss-Legendre quadrature in t = sqrt(z - d), which makes the integrand smooth
// at the contact edge; relative accuracy ~1e-12 for 0 <= nu <= 4 and |d| <= 50 sigma.
double gaussian_tail_moment(double nu, double separation, double sigma);

class GreenwoodWilliamson {
 public:
  GreenwoodWilliamson(double summit_density, double summit_radius, double summit_sigma,
                      double effective_modulus);

  // Per unit nominal area at separation d (flat to the mean summit plane):
  double contact_density(double separation) const;  // eta F_0           [1/m^2]
  double area_fraction(double separation) const;    // pi eta R F_1      [-]
  double pressure(double separation) const;         // 4/3 eta E* sqrt(R) F_3/2  [Pa]

  double summit_density() const { return eta_; }
  double summit_radius() const { return radius_; }
  double summit_sigma() const { return sigma_; }
  double effective_modulus() const { return e_eff_; }

 private:
  double eta_, radius_, sigma_, e_eff_;
};

}    // namespace runin::tribo
