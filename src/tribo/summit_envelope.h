// The surface of a layer of spherical summits as a height field: z(x, y) = the upper envelope of the summits'
// caps (flat where worn or plastically flattened), sampled on a grid over the nominal area, and its statistics.
// Used by compute runin/roughness (keyword `surface`): each rank rasterises its own summits, the grids combine by
// an element-wise maximum (MPI_MAX). Resolution and convergence: doc/compute_runin_roughness.rst.
#pragma once

#include "tribo/surface_statistics.h"

#include <cstddef>
#include <vector>

namespace runin::tribo {

// One summit: axis at (x, y), sphere of radius R whose top cap of height `drop` (>= 0) is cut flat, the whole
// sphere raised so that its centre sits at height `centre`. Height at horizontal distance r <= R from the axis:
// centre + min(sqrt(R^2 - r^2), R - drop) (for drop > R: the flat alone, within r^2 < 2 R drop - drop^2).
struct EnvelopeSummit {
  double x, y, centre, radius, drop;
};

class SummitEnvelope {
 public:
  // Grid of nx x ny cells over [x0, x0 + lx) x [y0, y0 + ly), one sample at each cell centre; a periodic direction
  // wraps the caps across it. Throws std::invalid_argument for empty grids or lengths <= 0.
  SummitEnvelope(double x0, double y0, double lx, double ly, std::size_t nx, std::size_t ny, bool periodic_x,
                 bool periodic_y);

  // Raise the field to the summit's cap within horizontal distance `footprint` (clamped to R) of its axis.
  void add(const EnvelopeSummit &s, double footprint);
  // The radius within which the summit's cap lies above `floor` (R when the floor is at or below the centre, 0
  // when it is above the top): caps of summits below the envelope's lowest point need not be drawn further out.
  static double footprint_above(const EnvelopeSummit &s, double floor);

  // Samples, row-major [iy * nx + ix]; -inf where no cap reaches (e.g. the target of MPI_Allreduce with MPI_MAX).
  std::vector<double> &heights() { return z_; }
  const std::vector<double> &heights() const { return z_; }
  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }

 private:
  double x0_, y0_, lx_, ly_, dx_, dy_;
  std::size_t nx_, ny_;
  bool px_, py_;
  std::vector<double> z_;
};

// Statistics of an envelope's samples: samples no cap reached (holes in the layer) take `base` (e.g. the lowest
// summit centre); `covered` is the fraction of samples under a cap.
struct EnvelopeStatistics {
  RoughnessStatistics roughness;    // of the field (mean = mean material height above z = 0)
  double covered = 0.0;
};
EnvelopeStatistics envelope_statistics(const std::vector<double> &heights, double base);

}    // namespace runin::tribo
