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
#include "runin_roughness_compute.h"

namespace LAMMPS_NS {

class FixRuninWearState;

// The LAMMPS adaptor of the compute both hosts share (runin_roughness_compute.h), with LAMMPS's own parts: the
// surface statistics (keyword surface), the per-atom heights, the rise of a body's free surface.
class ComputeRuninRoughness
    : public runin_roughness::RoughnessCompute<ComputeRuninRoughness, Compute, FixRuninWearState> {
 public:
  enum PerAtomColumn { HEIGHT = 0, WEAR_DEPTH, NPERATOM };
  // Entries of the surface (height-field) statistics, appended after the bearing ratios (keyword surface).
  // S_RA .. S_RZ in the order of runin_roughness::Entry (runin_roughness::write_fixed fills them)
  enum SurfaceEntry { S_RA = 0, S_RQ, S_RSK, S_RKU, S_RP, S_RV, S_RZ, S_MEAN, S_COVERED, NSURFACE };

  ComputeRuninRoughness(class LAMMPS *, int, char **);
  ~ComputeRuninRoughness() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  friend class runin_roughness::RoughnessCompute<ComputeRuninRoughness, Compute, FixRuninWearState>;
  static constexpr const char *atom_style = "atom_style sphere";
  void more_entries(double *out)
  {
    if (surface_dx > 0.0) compute_surface(out);
  }

  int nmax;
  double **peratom;               // per-atom summit height above the mean plane, wear depth h

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
