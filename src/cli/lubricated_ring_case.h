// The lubricated piston-ring case: `runin piston-ring CASE` with a [lubrication] (and optional [stribeck]) table
// (doc/lubricated_piston_ring.md).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "continuum/mixed_piston_ring.h"

namespace runin::cli {

struct LubricatedRingCase {
  std::string path, title;
  continuum::MixedRingParameters parameters;
  continuum::RunInSettings run;
  std::shared_ptr<const coupling::StateLaw> law;
  std::string law_path;
  coupling::OutOfRange policy = coupling::OutOfRange::Archard;
  std::string liner_roughness = "law";   // law | fixed
  int frames_per_cycle = 36;             // VTK frames of the first and last cycle
  struct Stribeck {
    double load = 0.0;                   // N/m, W'
    double speed_min = 0.0, speed_max = 0.0;
    int points = 50;
  };
  std::optional<Stribeck> stribeck;
};

// True when the case file has a [lubrication] or [stribeck] table (the lubricated mode).
bool is_lubricated_ring_case(const std::string &path);
LubricatedRingCase read_lubricated_ring_case(const std::string &path, const std::optional<std::string> &law_path);

}  // namespace runin::cli
