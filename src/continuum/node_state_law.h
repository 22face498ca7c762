// Per-node run-in state of a continuum contact driven by a homogenised state law (doc/state_law_continuum.md).
//
// Each contact node i (a ring of the pin face, a node of a bearing half, a face cell of a piston ring) carries
// its own surface state h_i, the mean worn depth of the rough body there, and reads the law at its own nominal
// pressure p_i:
//   mu_eff = sum_i mu(p_i, h_i) p_i A_i / sum_i p_i A_i       (nodes with p_i = 0 carry nothing: not looked up)
//   dh_i/ds = wear_rate(p_i, h_i)                              (the rough body; the same dh_i wears the geometry)
//   dc_i/ds = counterface_wear_rate(p_i, h_i)                  (the counter body's mean worn depth there)
// advance() integrates dh_i/ds at the held pressures over a slid distance ds (classic RK4 per node, ds split
// into sub-steps bounded by the law's own h-stiffness and h-grid spacing), so the update is stable and, the
// law's rates being >= 0, monotone. The caller re-solves the contact pressure between calls: the bound on that
// outer step (pressure-wear feedback) is stable_contact_step().
//
// Outside the law's pressure grid a lookup is an error (std::out_of_range naming the node's p and the grid) or,
// with OutOfRange::Clamp, the nearest grid pressure; every lookup and every clamp is counted in use().
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "continuum/node_film.h"
#include "coupling/state_law.h"

namespace runin::continuum {

class NodeStateLaw {
 public:
  // `nodes` states, all h_i = 0 (unworn). Throws std::invalid_argument on a null law.
  NodeStateLaw(std::shared_ptr<const coupling::StateLaw> law, coupling::OutOfRange policy, std::size_t nodes);

  std::size_t size() const { return h_.size(); }
  const std::vector<double> &state() const { return h_; }            // h_i, m
  const std::vector<double> &counterface() const { return c_; }      // counter body's worn depth per node, m
  const coupling::StateLaw &law() const { return *law_; }
  coupling::OutOfRange policy() const { return policy_; }
  const coupling::RangeUse &use() const { return use_; }
  void reset_state(std::vector<double> h);  // sets h_i (size must match), e.g. for tests
  // A surface film on the nodes (node_film.h): friction scaled by its coverage, which advance() moves. Throws
  // std::invalid_argument when the law has no contact_fraction field or the settings are bad (naming the key).
  // counterface_duty: the fraction of the time the counter body's surface under a node is in the contact zone.
  void set_film(const FilmSettings &settings, double counterface_duty = 1.0);
  const NodeFilm *film() const { return film_ ? &*film_ : nullptr; }

  // Pressure-weighted friction coefficient; 0 if no node carries load. Sizes must equal size().
  double mu_effective(const std::vector<double> &pressure, const std::vector<double> &area);
  // Per-node mu(p_i, h_i); 0 where p_i <= 0.
  std::vector<double> node_mu(const std::vector<double> &pressure) const;
  // Static coefficient for the stick/break-away limit: the pressure-weighted peak over h of mu(p_i, h) (the
  // law's peak at each node's pressure). Not counted in use().
  double peak_mu(const std::vector<double> &pressure, const std::vector<double> &area) const;

  struct Increment {
    std::vector<double> body;         // dh_i, m (the rough body's wear depth increment)
    std::vector<double> counterface;  // dc_i, m (the counter body's)
    int substeps = 0;                 // the most RK4 sub-steps any node took
  };
  // Slides ds >= 0 at the held pressures in dt >= 0 s: h_i += dh_i (the film, if any, over ds and dt, at each
  // node's contact fraction at the start of the step); returns the increments.
  Increment advance(const std::vector<double> &pressure, double ds, double dt = 0.0);
  // Bound on every sub-step of advance(): 0.05 / (largest |d wear_rate / dh| of the law). Each node's sub-steps
  // are also bounded by the h-grid spacing at its own depth over its own rate (no stage jumps a grid cell), so a
  // node deep in a log-spaced law is not stepped at the spacing of the first cells.
  double substep_bound() const { return substep_; }
  // Bound on the outer (contact re-solve) step for a contact whose pressure falls by `stiffness` Pa per metre
  // of uniform wear: the linearised update h += (w/p)(p0 - K h) ds is stable for ds < 2 / (K max_i w_i/p_i);
  // returns safety times that (infinity without wear or load). A node outside the pressure grid (clamped) has a
  // rate that does not follow its pressure: its w/p is taken at the nearest grid pressure.
  double stable_contact_step(const std::vector<double> &pressure, double stiffness, double safety);

 private:
  std::shared_ptr<const coupling::StateLaw> law_;
  coupling::OutOfRange policy_;
  std::vector<double> h_, c_;
  std::optional<NodeFilm> film_;
  double counterface_duty_ = 1.0;
  coupling::RangeUse use_;
  double substep_ = 0.0;
  // Largest sliding distance one RK4 sub-step of a node at depth h and rate w may take (ds_left caps it).
  double substep(double h, double w, double ds_left) const;

  // RK4 of every loaded node's h over ds > 0 (advance()); phi (when not empty) gets each node's contact fraction at
  // the step's start.
  void wear_nodes(const std::vector<double> &pressure, double ds, Increment &inc, std::vector<double> &phi);
};

// One line for a summary: "N lookups, M clamped below p_min, K above p_max, L beyond the last worn depth".
std::string describe(const coupling::RangeUse &use, const coupling::StateLaw &law);
// The summary's WARNING when lookups left the pressure grid (empty if none): how many, and what the policy did
// with them (Clamp: wear rates held at the grid edge, which breaks Archard's law there; Archard: proportional to p).
std::string out_of_range_warning(const coupling::RangeUse &use, const coupling::StateLaw &law,
                                 coupling::OutOfRange policy);

}  // namespace runin::continuum
