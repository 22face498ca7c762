// Thesis set-ups shared by the benchmarks (one definition each).
#pragma once

#include <cmath>

#include "continuum/journal_bearing.h"

namespace runin::bench {

// The journal bearing of the thesis (ch. 5): R = 12.5 mm, c = 25 um, L = 25 mm, steel, arc +-0.3 rad on `nodes`
// nodes, 9.81 N per half, drive k = 0.5 N m/rad with 0.3 of critical damping, Archard k = 1e-3, H = 1.2 GPa.
inline continuum::JournalBearingParameters journal_bearing_thesis(int nodes = 256, int halves = 2) {
  continuum::JournalBearingParameters p;
  p.bore = continuum::BoreGeometry{12.5e-3, 25e-6, 25e-3, 200e9, 0.29, 0.3, nodes};
  p.load = 9.81;
  p.inertia = 6e-5;
  p.coupling_stiffness = 0.5;
  p.coupling_damping = 2.0 * 0.3 * std::sqrt(0.5 * 6e-5);
  p.wear_coefficient = 1e-3;
  p.hardness = 1.2e9;
  p.halves = halves;
  return p;
}

}  // namespace runin::bench
