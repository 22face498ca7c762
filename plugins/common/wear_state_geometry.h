// The geometry of a wear-state row on both hosts (the RUNIN/WEAR_STATE fixes of plugins/lammps and
// plugins/liggghts, whose first five columns are the same): one truncated sphere whose cap volume is
// lost + flattened - gained, so wear and plastic flattening act on the same summit.
#pragma once

#include "tribo/asperity_geometry.h"

namespace runin_host {

// WEAR_DEPTH and FLAT_RADIUS of `row` (W: the wear-state fix, its column names) from its volumes and the radius,
// starting from its current WEAR_DEPTH (per step, after a small change of the volumes). Returns whether either
// changed.
template <class W> inline bool refresh_worn_row(double *row, double radius)
{
  if (!(radius > 0.0)) {
    const bool changed = row[W::WEAR_DEPTH] != 0.0 || row[W::FLAT_RADIUS] != 0.0;
    row[W::WEAR_DEPTH] = row[W::FLAT_RADIUS] = 0.0;
    return changed;
  }
  const runin::tribo::WornAsperity worn = runin::tribo::worn_asperity(
      radius, row[W::VOLUME_LOST] + row[W::VOLUME_FLATTENED], row[W::VOLUME_GAINED], row[W::WEAR_DEPTH]);
  const bool changed = (worn.summit_drop != row[W::WEAR_DEPTH]) | (worn.flat_radius != row[W::FLAT_RADIUS]);
  row[W::WEAR_DEPTH] = worn.summit_drop;
  row[W::FLAT_RADIUS] = worn.flat_radius;
  return changed;
}

// Volume of the summit cap pressed flat when a summit (radius R) sinks by a further depth d from its current
// drop h: V(h + d) - V(h), V(h) = pi h^2 (3R - h) / 3.
inline double flattened_volume(double radius, double drop, double depth)
{
  constexpr double kPiThird = 3.14159265358979323846 / 3.0;
  const double h0 = drop > 0.0 ? drop : 0.0, h1 = h0 + depth;
  return kPiThird * (h1 * h1 * (3.0 * radius - h1) - h0 * h0 * (3.0 * radius - h0));
}

}    // namespace runin_host
