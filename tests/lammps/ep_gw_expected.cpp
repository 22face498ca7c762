// Reference values for tests/lammps/ep_gw.py: the Greenwood-Williamson rough surface (identical summits of
// radius R, Gaussian summit heights of std sigma and mean 0) against a rigid flat at separation d, with the
// elastic-plastic asperity law of fix runin/wall 'normal elastic/plastic' (runin::tribo::JacksonGreen, the
// loading curve: first loading, no unloading) and with Hertz. Per summit:
//
//   N(d) = int_d^inf phi(z) dz,  P(d) = int_d^inf F(z - d) phi(z) dz,  A(d) = int_d^inf pi a(z - d)^2 phi(z) dz
//
// by adaptive Gauss-Kronrod (boost/math/quadrature, 61 points, relative 1e-12) in t = sqrt(z - d), which
// makes the integrand smooth at the contact edge (F ~ omega^3/2 there), on pieces split where the law
// changes branch (omega_c: Hertz to the bridge, 1.9 omega_c: the bridge to the JG fit). The Hertz-GW values of
// runin::tribo::GreenwoodWilliamson (Gauss-Legendre tail moments) are printed next to the Hertz quadrature
// as a cross-check of the quadrature.
//
//   runin_ep_gw_expected integral ESTAR R SIGMA S_Y NU D1 [D2 ...]
//     one line per D: D N P_ep A_ep P_hertz A_hertz P_gw A_gw            (per summit; N, P [N], A [m^2])
//   runin_ep_gw_expected sum ESTAR R S_Y NU HEIGHTS_FILE Z1 [Z2 ...]
//     one line per wall height Z: Z contacts P_ep A_ep P_hertz A_hertz   (sums over the summits of the file,
//     one height per line, each touching where h > Z, interference h - Z)
//   runin_ep_gw_expected law ESTAR R S_Y NU
//     the law's constants: omega_c P_c A_c C B g (transition gap)
#include "tribo/contact.h"
#include "tribo/elastic_plastic.h"
#include "tribo/greenwood_williamson.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace {

using runin::tribo::JacksonGreen;

constexpr double kPi = 3.14159265358979323846;

struct Totals {
  double contacts = 0.0, force_ep = 0.0, area_ep = 0.0, force_hertz = 0.0, area_hertz = 0.0;
};

// Hertz force and area of one summit at interference omega > 0.
double hertz_force(double e_eff, double radius, double omega)
{
  return 4.0 / 3.0 * e_eff * std::sqrt(radius) * omega * std::sqrt(omega);
}
double hertz_area(double radius, double omega) { return kPi * radius * omega; }

// int_lo^hi g(t) dt by adaptive 61-point Gauss-Kronrod to a relative 1e-12, on v in [0, 1],
// t = lo + (hi - lo) v. Boost 1.74 compares the error of the [-1, 1]-mapped piece, not scaled by its
// half-width, with the scaled estimate times tol, so a piece of half-width below 2 eps / tol is split down
// to max_depth however smooth the integrand: on a unit interval that never happens before convergence.
template <class G> double integrate(G g, double lo, double hi)
{
  if (!(hi > lo)) return 0.0;
  const double width = hi - lo;
  double error = 0.0;
  return width * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                     [&](double v) { return g(lo + width * v); }, 0.0, 1.0, 15, 1e-12, &error);
}

// Per-summit GW integrals at separation d: the integrand in t = sqrt(omega), omega = z - d, dz = 2t dt.
Totals integral(const JacksonGreen &law, double sigma, double d)
{
  const double e_eff = law.coefficients().effective_modulus, radius = law.coefficients().effective_radius;
  const double norm = 1.0 / (sigma * std::sqrt(2.0 * kPi));
  auto density = [&](double t) {
    const double u = (d + t * t) / sigma;
    return 2.0 * t * norm * std::exp(-0.5 * u * u);
  };
  // beyond z = max(d, 0) + 12 sigma the density is below 1e-31 of its peak
  const double t_end = std::sqrt(std::max(d, 0.0) + 12.0 * sigma - d);
  const double omega_c = law.critical_interference();
  std::vector<double> cuts = {0.0};
  for (double omega : {omega_c, JacksonGreen::kFitStart * omega_c})
    if (std::sqrt(omega) < t_end) cuts.push_back(std::sqrt(omega));
  cuts.push_back(t_end);

  Totals out;
  out.contacts = 0.5 * std::erfc(d / (sigma * std::sqrt(2.0)));
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double lo = cuts[k], hi = cuts[k + 1];
    out.force_ep += integrate([&](double t) { return law.force(t * t) * density(t); }, lo, hi);
    out.area_ep += integrate([&](double t) { return law.contact_area(t * t) * density(t); }, lo, hi);
    out.force_hertz += integrate([&](double t) { return hertz_force(e_eff, radius, t * t) * density(t); }, lo, hi);
    out.area_hertz += integrate([&](double t) { return hertz_area(radius, t * t) * density(t); }, lo, hi);
  }
  return out;
}

// Exact sums over a sample of summit heights against a flat at height z.
Totals sample_sum(const JacksonGreen &law, const std::vector<double> &heights, double z)
{
  const double e_eff = law.coefficients().effective_modulus, radius = law.coefficients().effective_radius;
  Totals out;
  for (double h : heights) {
    const double omega = h - z;
    if (!(omega > 0.0)) continue;
    out.contacts += 1.0;
    out.force_ep += law.force(omega);
    out.area_ep += law.contact_area(omega);
    out.force_hertz += hertz_force(e_eff, radius, omega);
    out.area_hertz += hertz_area(radius, omega);
  }
  return out;
}

double number(const char *text, const char *what)
{
  char *end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') {
    std::fprintf(stderr, "runin_ep_gw_expected: %s must be a number, got '%s'\n", what, text);
    std::exit(2);
  }
  return value;
}

int usage()
{
  std::fprintf(stderr,
               "usage: runin_ep_gw_expected integral ESTAR R SIGMA S_Y NU D1 [D2 ...]\n"
               "       runin_ep_gw_expected sum ESTAR R S_Y NU HEIGHTS_FILE Z1 [Z2 ...]\n"
               "       runin_ep_gw_expected law ESTAR R S_Y NU\n");
  return 2;
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  try {
    if (mode == "integral" && argc >= 8) {
      const double e_eff = number(argv[2], "ESTAR"), radius = number(argv[3], "R"), sigma = number(argv[4], "SIGMA");
      const JacksonGreen law(e_eff, radius, number(argv[5], "S_Y"), number(argv[6], "NU"));
      const runin::tribo::GreenwoodWilliamson gw(1.0, radius, sigma, e_eff);
      for (int k = 7; k < argc; ++k) {
        const double d = number(argv[k], "D");
        const Totals t = integral(law, sigma, d);
        std::printf("%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", d, t.contacts, t.force_ep, t.area_ep,
                    t.force_hertz, t.area_hertz, gw.pressure(d), gw.area_fraction(d));
      }
    } else if (mode == "sum" && argc >= 8) {
      const JacksonGreen law(number(argv[2], "ESTAR"), number(argv[3], "R"), number(argv[4], "S_Y"),
                             number(argv[5], "NU"));
      std::ifstream in(argv[6]);
      if (!in) {
        std::fprintf(stderr, "runin_ep_gw_expected: cannot read %s\n", argv[6]);
        return 2;
      }
      std::vector<double> heights;
      for (double h; in >> h;) heights.push_back(h);
      for (int k = 7; k < argc; ++k) {
        const double z = number(argv[k], "Z");
        const Totals t = sample_sum(law, heights, z);
        std::printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", z, t.contacts, t.force_ep, t.area_ep, t.force_hertz,
                    t.area_hertz);
      }
    } else if (mode == "law" && argc == 6) {
      const JacksonGreen law(number(argv[2], "ESTAR"), number(argv[3], "R"), number(argv[4], "S_Y"),
                             number(argv[5], "NU"));
      std::printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", law.critical_interference(), law.critical_force(),
                  law.critical_area(), law.yield_factor(), law.area_exponent(), law.transition_gap());
    } else {
      return usage();
    }
  } catch (const runin::tribo::InvalidCoefficient &e) {
    std::fprintf(stderr, "runin_ep_gw_expected: %s\n", e.what());
    return 2;
  }
  return 0;
}
