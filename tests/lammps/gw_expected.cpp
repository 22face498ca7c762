// Prints the Greenwood-Williamson nominal pressure (runin::tribo kernel) for run_deck.py gw:
//   runin_gw_expected ETA R SIGMA ESTAR D1 [D2 ...]   ->  one "D P N_density A_fraction" line per D
#include "tribo/contact.h"
#include "tribo/greenwood_williamson.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char **argv)
{
  if (argc < 6) {
    std::fprintf(stderr, "usage: runin_gw_expected ETA R SIGMA ESTAR D1 [D2 ...]\n");
    return 2;
  }
  try {
    const runin::tribo::GreenwoodWilliamson gw(std::atof(argv[1]), std::atof(argv[2]), std::atof(argv[3]),
                                               std::atof(argv[4]));
    for (int k = 5; k < argc; ++k) {
      const double d = std::atof(argv[k]);
      std::printf("%.17g %.17g %.17g %.17g\n", d, gw.pressure(d), gw.contact_density(d), gw.area_fraction(d));
    }
  } catch (const runin::tribo::InvalidCoefficient &e) {
    std::fprintf(stderr, "runin_gw_expected: %s\n", e.what());
    return 2;
  }
  return 0;
}
