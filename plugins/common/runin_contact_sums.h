// Per-rank contact sums that every RunIn contact host (pair runin/asperity, fix runin/wall)
// fills during its force evaluation and compute runin/friction reduces over ranks.
#ifndef LMP_RUNIN_CONTACT_SUMS_H
#define LMP_RUNIN_CONTACT_SUMS_H

#include "pointers.h"

#include <type_traits>

namespace LAMMPS_NS {

struct RuninContactSums {
  double normal_force = 0.0;               // sum of |F_n| [N]
  double tangential_force[3] = {0, 0, 0};  // sum of F_t on the counter-body side of each contact [N]
  double adhesion_force = 0.0;             // sum of the adhesion part of the friction strength [N]
  double ploughing_force = 0.0;            // sum of the ploughing part of the friction strength [N]
  double contacts = 0.0;
  double sticking_contacts = 0.0;
  double contact_area = 0.0;               // real contact area [m^2]
  double wear_volume = 0.0;                // volume removed in this step [m^3]
  double frictional_power = 0.0;           // sum of F_t . v_slip dissipated [W]
  // Global-frame force of the contacts on the measured body (RuninContactSource::measure_body), from the
  // contacts that cross its boundary: the reaction the body feels [N]
  double body_force[3] = {0, 0, 0};
  // Global-frame force on the rigid counterface the host owns (fix runin/wall), this rank's share [N]
  double counterface_force[3] = {0, 0, 0};

  static constexpr int NVALUES = 17;
  // Flat view for MPI reductions, in declaration order.
  void pack(double *out) const
  {
    const double v[NVALUES] = {normal_force, tangential_force[0], tangential_force[1], tangential_force[2],
                               adhesion_force, ploughing_force, contacts, sticking_contacts, contact_area,
                               wear_volume, frictional_power, body_force[0], body_force[1], body_force[2],
                               counterface_force[0], counterface_force[1], counterface_force[2]};
    for (int i = 0; i < NVALUES; i++) out[i] += v[i];
  }
};

// Implemented by the styles that own contacts, so the compute needs no list of them.
class RuninContactSource {
 public:
  // the exception specification of LAMMPS's Pointers (noexcept(false) in newer releases), which the styles
  // that mix this in inherit: theirs may not be looser than this one
  virtual ~RuninContactSource() noexcept(std::is_nothrow_destructible_v<LAMMPS_NS::Pointers>) {}
  virtual const RuninContactSums &contact_sums() const = 0;
  // Cumulative volume worn off rigid counterfaces (not atoms) that the host owns, the same on every rank.
  virtual double counterface_wear_volume() const { return 0.0; }
  // Sum the global-frame contact force on the atoms of this group into RuninContactSums::body_force from
  // the next force evaluation on (0: none). Set by compute runin/friction at init.
  virtual void measure_body(int groupbit) = 0;
  // Whether the host owns a rigid counterface (its force is RuninContactSums::counterface_force).
  virtual bool has_counterface() const { return false; }
};

}    // namespace LAMMPS_NS

#endif
