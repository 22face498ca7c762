// Seed averaging of `runin homogenise` (doc/homogenise.md, "From samples to the law"): the cell samples of each grid
// pressure, each already on the law's worn-depth grid, make the state law. At every (p, h) and for every field the
// law's mean is the mean over that pressure's seeds and its band (low, high) their minimum and maximum.
#pragma once

#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/state_law.h"

namespace runin::coupling {

// One sample (one seed at one pressure) on the worn-depth grid: [StateField][depth index].
struct DepthCurves {
  std::array<std::vector<double>, state_field_count> field;
};

struct HomogenisationSamples {
  std::vector<double> pressure;                  // Pa, the law's pressure grid
  std::vector<double> worn_depth;                // m, the law's h grid
  std::vector<std::vector<DepthCurves>> seeds;   // per pressure: its good seeds, each on worn_depth
  nlohmann::json metadata = nlohmann::json::object();
};

// The law of the samples. The mean is kept within [low, high] (summing may round it out of a flat band). Throws
// std::invalid_argument when a pressure has no seed or a curve's length is not the depth grid's, and as the
// StateLaw constructor does.
StateLaw homogenise(const HomogenisationSamples &samples);

}  // namespace runin::coupling
