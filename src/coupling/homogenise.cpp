#include "coupling/homogenise.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace runin::coupling {

StateLaw homogenise(const HomogenisationSamples &samples) {
  if (samples.seeds.size() != samples.pressure.size())
    throw std::invalid_argument("homogenise: " + std::to_string(samples.seeds.size()) + " seed sets for " +
                                std::to_string(samples.pressure.size()) + " pressures");
  const std::size_t depths = samples.worn_depth.size();
  std::array<StateFieldTable, state_field_count> tables;
  for (std::size_t ip = 0; ip < samples.pressure.size(); ++ip) {
    const auto &good = samples.seeds[ip];
    if (good.empty())
      throw std::invalid_argument("homogenise: no seed at p = " + std::to_string(samples.pressure[ip]) + " Pa");
    for (const auto &g : good)
      for (std::size_t f = 0; f < state_field_count; ++f)
        if (g.field[f].size() != depths && !(optional_field(static_cast<StateField>(f)) && g.field[f].empty()))
          throw std::invalid_argument("homogenise: a seed's curve is not on the depth grid");
    for (std::size_t f = 0; f < state_field_count; ++f) {
      // an optional field (contact fraction) only when every sample at every pressure has it
      if (std::any_of(samples.seeds.begin(), samples.seeds.end(), [f](const auto &set) {
            return std::any_of(set.begin(), set.end(), [f](const DepthCurves &g) { return g.field[f].empty(); });
          }))
        continue;
      std::vector<double> mean(depths), low(depths), high(depths);
      for (std::size_t j = 0; j < depths; ++j) {
        double sum = 0, lo = good.front().field[f][j], hi = lo;
        for (const DepthCurves &g : good) {
          const double v = g.field[f][j];
          sum += v, lo = std::min(lo, v), hi = std::max(hi, v);
        }
        mean[j] = std::clamp(sum / static_cast<double>(good.size()), lo, hi);  // round-off may leave [lo, hi]
        low[j] = lo, high[j] = hi;
      }
      tables[f].mean.push_back(std::move(mean));
      tables[f].low.push_back(std::move(low));
      tables[f].high.push_back(std::move(high));
    }
  }
  return StateLaw(samples.pressure, samples.worn_depth, tables, samples.metadata);
}

}  // namespace runin::coupling
