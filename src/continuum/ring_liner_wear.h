// Archard wear of a piston-ring face and the cylinder liner, with profile update.
// Contact across the ring's axial width w, with the gap at zero approach in ring cell i (centre z_i)
//   g_i = crown (2 z_i / w)^2 + h_ring_i + h_liner(under cell i),
// is either (FaceContact::HalfPlane, the default of the CLI) an elastic half-plane line contact
// solved by the boundary-element kernel of half_plane_contact.h (piecewise-constant panels = the
// ring cells, combined modulus E*), or (FaceContact::Winkler) a Winkler layer
//   p_i = k_c max(0, d - g_i);
// in both the approach d is set so that pi D sum_i p_i dz = W (load equilibrium).
// Sliding the ring by ds wears depth (k/H) p ds, shared between ring face and liner
// (ring_share : 1 - ring_share); the liner gets it where the ring covers it (cell overlaps, so
// volumes are conserved exactly). Steps are explicit in slip distance; the adaptive step is
// safety * ArchardWear::stable_slip_step(k_c), the bound of the linearised update.
// Wear deeper than the ring's radial thickness or the liner wall is not a run-in any more: the
// update that crosses it stops the wear with a status (RingWornThrough / LinerWornThrough).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "continuum/contact_stress.h"
#include "continuum/half_plane_contact.h"
#include "continuum/node_state_law.h"
#include "tribo/wear.h"

namespace runin::continuum {

enum class FaceContact { Winkler, HalfPlane };

struct RingLinerWearSettings {
  FaceContact contact = FaceContact::Winkler;
  double bore = 0.1;             // m, D
  double ring_width = 0.01;      // m, w
  double crown_height = 0.0;     // m, parabolic ring-face crown (0 = flat)
  int ring_cells = 64;
  double liner_begin = 0.0;      // m, liner grid along the stroke coordinate x (ring centre positions)
  double liner_end = 0.0;        // m
  int liner_cells = 512;
  double foundation_modulus = 0.0;  // Pa/m, k_c (Winkler)
  double contact_modulus = 0.0;     // Pa, E* of ring and liner (HalfPlane)
  double ring_share = 0.5;       // share of the worn volume taken by the ring face (tribo::wear_share)
  double step_safety = 0.5;      // adaptive step = safety * stable_slip_step
  double fixed_step = 0.0;       // m; > 0 replaces the adaptive step (to show the instability)
  double ring_thickness = 0.0;   // m, radial; wear depth limit of the ring face (0: unchecked)
  double liner_wall = 0.0;       // m, liner wall thickness; wear depth limit of the liner (0: unchecked)

  void validate() const;  // throws std::invalid_argument
};

enum class RingLinerWearStatus { Ok, RingWornThrough, LinerWornThrough };
const char *to_string(RingLinerWearStatus status);

struct ContactPressure {
  std::vector<double> pressure;  // Pa, per ring cell
  double peak = 0.0;             // Pa
  double mean = 0.0;             // Pa, over the loaded width
  double width = 0.0;            // m, loaded axial width
};

class RingLinerWear {
 public:
  RingLinerWear(RingLinerWearSettings settings, tribo::ArchardWear wear);

  const RingLinerWearSettings &settings() const { return s_; }
  const tribo::ArchardWear &archard() const { return wear_; }
  double ring_cell_width() const { return dz_; }
  double liner_cell_width() const { return dx_; }
  double ring_cell_centre(int i) const;   // z, m, from -w/2 to w/2
  double liner_cell_centre(int j) const;  // x, m
  double step() const;                    // slip per wear update, m

  // Shares `other`'s liner (same grid; both rings then wear and see one liner). Throws
  // std::invalid_argument if the liner grids differ.
  void share_liner(const RingLinerWear &other);
  // Stiffness per area that bounds the explicit wear step: k_c (Winkler) or 1 / lambda_min(K).
  double contact_stiffness() const { return stiffness_; }

  // State law (doc/state_law_continuum.md): each ring cell i carries h_i (the ring face is the rough body);
  // an update wears the face by the law's dh_i = wear_rate(p_i, h_i) ds (the Archard k/H and ring_share are not
  // used) and the liner under cell i by the counterface's dc_i (counterface_wear_rate), spread over the
  // overlapped liner cells as the Archard share is. The step is safety * 2 / (k_c max w/p over the law's grid).
  // With `film`, the ring face's nodes carry it (NodeStateLaw::set_film).
  void attach_state_law(std::shared_ptr<const coupling::StateLaw> law, coupling::OutOfRange policy,
                        const std::optional<FilmSettings> &film = std::nullopt);
  NodeStateLaw *state_law() { return law_ ? &*law_ : nullptr; }
  const NodeStateLaw *state_law() const { return law_ ? &*law_ : nullptr; }
  // mu_eff = sum mu(p_i, h_i) p_i / sum p_i of the ring at x_ring under `load` (cells of equal area).
  double mu_effective(double x_ring, double load);
  double peak_mu(double x_ring, double load) const;  // the law's peak at these pressures (static limit)

  // Contact of the ring centred at x_ring under load W (Winkler: exact water filling; half-plane:
  // active-set BEM, std::runtime_error if it does not converge).
  ContactPressure pressure(double x_ring, double load) const;
  // Liner pressure (cell averages) under the ring at x_ring; 0 where the ring is not.
  std::vector<double> liner_pressure(double x_ring, double load) const;

  // Slides the ring from x_from to x_to (one direction); the load varies linearly along it.
  // Returns false (and does nothing more, now or later) once a wear depth passes its limit; see
  // status() and message(). Throws std::out_of_range if the ring leaves the liner grid.
  // dt: the time the slide takes (a film on the face grows over it; 0 without one).
  bool slide(double x_from, double x_to, double load_from, double load_to, double dt = 0.0);
  RingLinerWearStatus status() const { return status_; }
  bool ok() const { return status_ == RingLinerWearStatus::Ok; }
  const std::string &message() const { return message_; }  // what crossed which limit; empty while ok

  const std::vector<double> &ring_wear() const { return ring_wear_; }    // m, per ring cell
  const std::vector<double> &liner_wear() const { return *liner_wear_; }  // m, per liner cell
  double ring_volume() const;   // m^3, pi D sum h dz
  double liner_volume() const;  // m^3 this ring wore into the liner (= the liner's, unless shared)
  double shared_liner_volume() const;  // m^3 of the whole liner profile (all rings sharing it)
  double archard_volume() const { return archard_volume_; }  // sum of ArchardWear::volume(W, ds)
  long updates() const { return updates_; }

 private:
  std::vector<double> gaps(double x_ring) const;
  template <typename Visit>
  void for_each_overlap(double x_ring, Visit visit) const;  // visit(ring cell, liner cell, overlap length)
  void update(double x_ring, double load, double ds, double dt);

  RingLinerWearSettings s_;
  tribo::ArchardWear wear_;
  double dz_ = 0.0, dx_ = 0.0;
  std::vector<double> ring_wear_;
  std::shared_ptr<std::vector<double>> liner_wear_;
  double stiffness_ = 0.0;
  Eigen::MatrixXd compliance_;                    // half-plane K over the ring cells
  mutable ToeplitzBlockCache blocks_;
  mutable std::vector<char> active_;              // last active set (warm start)
  double archard_volume_ = 0.0;
  double liner_volume_ = 0.0;  // m^3, worn into the liner by this ring
  long updates_ = 0;
  RingLinerWearStatus status_ = RingLinerWearStatus::Ok;
  std::string message_;
  std::optional<NodeStateLaw> law_;
  double law_factor_ = 0.0;  // max over the law's grid of wear_rate / p, 1/Pa
};

// Subsurface stress below a ring face contact (doc/subsurface_stress.md), plane strain (the contact is a line
// around the bore, D >> w): x is the axial coordinate along the face (ring cell centres, -w/2..w/2), z the
// depth into each body. The liner (body a) carries the friction shear q = mu p in +x (the ring sliding in +x
// for mu > 0), the ring face (body b) -q. Influence tier on the ring-cell pressure (any worn face):
LineContactStress ring_face_stress(const RingLinerWear &wear, const std::vector<double> &pressure, double mu,
                                   const tribo::Material &liner, const tribo::Material &ring, int points = 48);
// McEwen's closed form on the Hertz contact of the crowned, unworn face under `load` (N around the bore):
// crown radius w^2 / (8 crown_height), load per length W / (pi D), E* = contact_modulus. Empty when the face
// is not Hertzian: no crown, or the Hertz width 2b reaches the face width.
std::optional<LineContactStress> ring_face_hertz_stress(const RingLinerWearSettings &settings, double load, double mu,
                                                        const tribo::Material &liner, const tribo::Material &ring,
                                                        int points = 48);

}  // namespace runin::continuum
