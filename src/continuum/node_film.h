// A surface film on the contact nodes of an element (doc/surface_films.md, "In an element"): the cell's per-summit
// film kinetics (tribo::FilmKinetics) carried by each node as the mean coverage theta_i of the rough body's summits.
//
// A summit in a rough contact slips only while it touches a counter-summit: over a nominal sliding ds its own slip
// is phi ds, phi the fraction of the rough body's summits in contact (the state law's contact_fraction at the
// node's p_i and h_i, measured by the cell). Over a step of sliding ds in time dt the node's coverage follows the
// cell's exact solution with removal exposure phi ds / s_r and growth exposure k_g dt.
//
// The law is built at one interface state, the bare surface's f_base (its samples.contact.f); a node at coverage
// theta shears at f = theta f_film + (1 - theta) f_base, so its friction is the law's scaled by the ratio of
// Tabor's junction closed forms, mu = mu_law(p, h) T(f) / T(f_base), T(f) = f / sqrt(alpha (1 - f^2)): exact at
// theta = 0 and, where the cell's contacts are plastic junctions (mu_body = T(f) at every p and h), at theta = 1.
// The closure's error against the cell with films is measured in doc/surface_films.md.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "tribo/surface_film.h"

namespace runin::continuum {

// The film of the counter body (its own kinetics; the same f_film): a contact then shears at the mean coverage of
// its two summits, as in the cell. Its surface under a node is in the contact zone a fraction `duty` of the time
// (the element's: 1 for a body always under load, footprint / track area for a disk).
struct CounterfaceFilm {
  double coverage = 1.0;          // initial theta, [0, 1]
  double removal_distance = 0.0;  // s_r of its summits' own slip, m
  double growth_rate = 0.0;       // k_g, 1/s
};

struct FilmSettings {
  double coverage = 1.0;          // initial theta of every node, in [0, 1]
  double f_film = 0.0;            // interface coefficient of the covered junction, [0, 1)
  double f_base = 0.0;            // of the bare surface: the law's own interface, (0, 1)
  double alpha = 12.0;            // Tabor's junction growth constant (the law's)
  double removal_distance = 0.0;  // s_r, m of a summit's own slip; 0: sliding does not remove the film
  double growth_rate = 0.0;       // k_g, 1/s; 0: no regrowth
  std::optional<CounterfaceFilm> counterface;  // absent: only the rough body carries a film

  // Throws std::invalid_argument naming the key (film.coverage, film.f_film, film.removal_distance, ...).
  void validate() const;
};

// The film input that can move a node's ln mu by more than `tolerance` over one step of sliding ds (m) in dt (s),
// an upper bound from the kinetics alone: the coverage's exposure over the step (ds / s_r and k_g dt of either body,
// at most 1) times the steepest ln T(f) over the film's range, |f_base - f_film| max d ln T / df at its ends (ln T is
// convex in f). An adaptive run whose smallest step fails while this exceeds the tolerance is stopped by the film's
// input, not by the law: the fastest kinetic input when the exposure itself exceeds the tolerance, else f_film
// (Tabor's friction that steep in the coverage).
enum class FilmInput { None, RemovalDistance, GrowthRate, CounterfaceRemovalDistance, CounterfaceGrowthRate, FFilm };
struct FilmStepBound {
  FilmInput input = FilmInput::None;  // None: the film alone stays within the tolerance over the step
  double change = 0.0;                // the bound on |d ln mu| over the step
};
FilmStepBound film_step_bound(const FilmSettings &settings, double ds, double dt, double tolerance);

class NodeFilm {
 public:
  NodeFilm(const FilmSettings &settings, std::size_t nodes);  // validates

  const FilmSettings &settings() const { return s_; }
  const std::vector<double> &coverage() const { return theta_; }
  const std::vector<double> &counterface_coverage() const { return theta_cf_; }  // empty without its film
  // The coverage a contact at node i shears at: theta_i, or (theta_i + theta_cf_i) / 2 with a counterface film.
  double contact_coverage(std::size_t node) const;
  // mu / mu_law of node i at its coverage: T(f(theta)) / T(f_base).
  double friction_factor(std::size_t node) const;
  // Slides ds (m, nominal) in dt (s); contact_fraction[i] = phi_i (0: a node that carries no load only regrows);
  // the counterface's summits under node i slip phi_i duty ds (0 < duty <= 1).
  void advance(const std::vector<double> &contact_fraction, double ds, double dt, double counterface_duty = 1.0);
  // Contact coverage weighted by `weight` (e.g. p_i A_i); the plain mean when every weight is 0.
  double mean_coverage(const std::vector<double> &weight) const;

 private:
  double tabor(double f) const;

  FilmSettings s_;
  tribo::FilmKinetics kinetics_, counterface_kinetics_;
  std::vector<double> theta_, theta_cf_;
  double tabor_base_ = 0.0;
};

}  // namespace runin::continuum
