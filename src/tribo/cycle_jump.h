// Cycle jumping for slow wear (McColl, Ding & Leen 2004, Wear 256:1114; Podra & Andersson 1999, Tribol. Int.
// 32:71): the contact mechanics shakes down within a few summit encounters, the worn geometry changes over a
// much longer sliding distance. A phase of N steps slides at physical conditions; each summit's worn volume over
// the phase, Delta V, is its own Archard rate times the phase length; the jump then adds (M - 1) Delta V, so the
// cycle stands for M phases of sliding (the worn geometry follows from the volumes, asperity_geometry.h).
// No LAMMPS; doc/fix_runin_wear_jump.rst.
#pragma once

namespace runin::tribo {

// The extra phases (M - 1) a jump applies: the requested ones, or fewer when they would add more than max_depth to
// the mean worn depth (worn volume over the nominal area; phase_depth is the phase's own addition to it). The state
// tolerance is on the mean depth, not on single summits: the summits in contact in a phase wear many times the
// mean, and a jump moves the load onto others, as sliding does. A phase that wore nothing (the counter-body out of
// contact, e.g. still settling after the last jump) is not repeated: 0. requested >= 0, phase_depth >= 0 and max_depth > 0,
// all finite (throws InvalidCoefficient naming the argument otherwise).
double jump_extra(double requested, double phase_depth, double max_depth);

// The largest extra factor e in [0, upper] for which the jump changes no summit's height by more than max_change:
// change(e) is the largest change of one summit's height that the jump e makes (nondecreasing in e, change(0) = 0).
// upper when change(upper) <= max_change, else the bisection's lower end (change <= max_change) to 1e-13 of upper.
// The state tolerance of a deep jumped cell (doc/fix_runin_wear_jump.rst, "Choosing the jump"): the summits in
// contact carry the wear and one jump moves each of them, so the jump is bounded by what it does to them, whatever
// the mean depth that is. max_change > 0 and finite, upper >= 0 (InvalidCoefficient naming max_change otherwise).
// The mean depth the next jump may add, from the measured relative change of the state over the last cycle (its
// jump and the phase after it): depth x tolerance / change, by at most a factor 2 up or down per cycle, and not
// below 1e-3 x floor_reference. An error controller on what the state does, not on h: where the state changes fast
// (the plastic flattening at the start, the first contacts of new summits) the jumps shrink until the sliding of
// the phases has shaken it down; where it has settled they grow (up to max_change, jump_extra_within_change).
// change >= 0, tolerance in (0, 1), depth and floor_reference > 0, all finite (InvalidCoefficient naming them).
double jump_depth_by_rate(double depth, double change, double tolerance, double floor_reference);

void check_max_change(double max_change);
template <class Change>
double jump_extra_within_change(double upper, double max_change, Change change)
{
  check_max_change(max_change);
  if (!(upper > 0.0) || change(upper) <= max_change) return upper > 0.0 ? upper : 0.0;
  double low = 0.0, high = upper;
  for (int iteration = 0; iteration < 44 && high - low > 1e-13 * upper; ++iteration) {
    const double mid = 0.5 * (low + high);
    (change(mid) <= max_change ? low : high) = mid;
  }
  return low;
}

}    // namespace runin::tribo
