// Test helper: reads a state law with the continuum side's reader (coupling::StateLaw::read_file) and prints its
// grid and one lookup per pressure as JSON, so tests/cli/check_homogenise.py checks what the machine elements read.
//   runin_read_state_law LAW.json [P H1 H2 ...]   (with P: mu_body and rq at (P, H_i) as "lookup")
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "coupling/ave_time_reader.h"
#include "coupling/state_law.h"

int main(int argc, char **argv) {
  if (argc < 2 || argc == 3) {
    std::cerr << "usage: runin_read_state_law LAW.json [P H1 H2 ...]\n";
    return 2;
  }
  try {
    const auto law = runin::coupling::StateLaw::read_file(argv[1]);
    nlohmann::json out = {{"pressure", law.pressure()}, {"worn_depth", law.worn_depth()}, {"has_band", law.has_band()}};
    for (double p : law.pressure()) {
      const auto v = law.values(p, 0.5 * law.worn_depth().back());
      out["mid_depth"].push_back({{"pressure", p}, {"mu_body", v.mu_body}, {"wear_rate", v.wear_rate}, {"rq", v.rq}});
    }
    if (argc > 3) {
      const double p = std::stod(argv[2]);
      for (int i = 3; i < argc; ++i) {
        const double h = std::stod(argv[i]);
        const auto v = law.values(p, h);
        out["lookup"].push_back({{"pressure", p}, {"worn_depth", h}, {"mu_body", v.mu_body}, {"rq", v.rq}});
      }
    }
    std::cout << out.dump() << "\n";
  } catch (const std::exception &e) {
    std::cerr << "runin_read_state_law: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
