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

}    // namespace runin::tribo
