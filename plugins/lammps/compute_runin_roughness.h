// compute runin/roughness: surface statistics (Ra, Rq, Rsk, Rku, Rp, Rv, Rz, bearing ratios) of the
// summit heights of a group of asperity particles, lowered by their wear depth when a RunIn wear
// state exists; per-atom summit height above the mean plane and wear depth. With `surface dx`, also the
// statistics of the surface itself: the envelope of the summit caps rasterised on a grid of spacing dx.
#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(runin/roughness,ComputeRuninRoughness);
// clang-format on
#else

#ifndef LMP_COMPUTE_RUNIN_ROUGHNESS_H
#define LMP_COMPUTE_RUNIN_ROUGHNESS_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeRuninRoughness : public Compute {
 public:
  enum PerAtomColumn { HEIGHT = 0, WEAR_DEPTH, NPERATOM };
  // Entries of the surface (height-field) statistics, appended after the bearing ratios (keyword surface).
  // S_RA .. S_RZ in the order of runin_roughness::Entry (runin_roughness::write_fixed fills them)
  enum SurfaceEntry { S_RA = 0, S_RQ, S_RSK, S_RKU, S_RP, S_RV, S_RZ, S_MEAN, S_COVERED, NSURFACE };

  ComputeRuninRoughness(class LAMMPS *, int, char **);
  ~ComputeRuninRoughness() override;
  void init() override;
  void compute_vector() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  std::vector<double> depths;    // bearing depths below the highest summit
  double sign;                    // +1: side up (z + r - h); -1: side down (-(z - r + h))
  int nmax;
  double **peratom;               // per-atom summit height above the mean plane, wear depth h
  class FixRuninWearState *fix_wear;    // nullptr: no wear state, h = 0

  double surface_dx;              // grid spacing of the height field (0: no surface statistics)

  double wear_depth(int i) const;
  double rise(int i) const;       // the uniform rise of the free surface of i's body (volume-conserving flattening)
  void compute_surface(double *out);

  double summit(int i) const;
  double mean_height();           // first reduction: count and sum of summit heights
};

}    // namespace LAMMPS_NS

#endif
#endif
