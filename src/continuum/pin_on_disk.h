// Pin-on-disk tribometer (thesis ch. 4): a pin of mass m at track radius r, pressed with
// load W. Torque drive (the thesis's model): an applied torque ramps up and is held:
//   J dw/dt = T_app(t) - T_f,   J = m r^2,   V = r w,   ds/dt = |V|
//   stick: w = 0, T_f = T_app            while |T_app| < mu_static W r
//   slip:  T_f = sign(w) mu(s, |V|, R) W r
// y = (w, s, R); R is the friction law's state (feedback roughness), constant 0 otherwise.
// Break-away and re-stick are events located by CVODE root finding.
// Speed drive (a tribometer run at a set sliding speed, as the thesis's reference experiment):
// V(t) ramps linearly to sliding_speed over ramp_time and is held; the pin slides from t = 0 and
// the friction force is the law's, F = mu(s, V, R) W (the drive supplies whatever torque it takes).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "continuum/cvode_integrator.h"
#include "continuum/sliding_friction.h"
#include "continuum/stick_slip_loop.h"  // ContactState, SolveStatus, SolveReport
#include "continuum/contact_stress.h"
#include "tribo/subsurface_stress.h"

namespace runin::continuum {

enum class PinDrive { Torque, Speed };

struct PinOnDiskParameters {
  PinDrive drive = PinDrive::Torque;
  double sliding_speed = 0.0;   // m/s, speed drive: held after the ramp
  double mass = 0.0;            // kg, pin as a point mass on the track
  double track_radius = 0.0;    // m
  double normal_load = 0.0;     // N
  double applied_torque = 0.0;  // N m, torque drive: held after the ramp
  double ramp_time = 2.0;       // s, linear ramp from 0; 0 = step at t = 0

  void validate() const;  // throws std::invalid_argument naming the field
  double inertia() const { return mass * track_radius * track_radius; }
  double prescribed_speed(double t) const;         // speed drive: V(t)
  double prescribed_acceleration(double t) const;  // speed drive: dV/dt (left-continuous at the ramp end)
};

struct PinOnDiskSample {
  double t = 0.0;
  double applied_torque = 0.0;   // N m (speed drive: the drive's torque T_f + J dw/dt)
  double friction_force = 0.0;   // N, = friction_torque / r
  double friction_torque = 0.0;  // N m, resisting torque in J dw/dt = T_app - T_f
  double mu = 0.0;               // mobilised coefficient friction_force / W (stick: below mu_static)
  double mu_law = 0.0;           // the law's sliding value at this s without the speed term
  double speed = 0.0;            // m/s, V = r w
  double distance = 0.0;         // m, accumulated sliding distance s
  double roughness = 0.0;        // friction-law state R (feedback model), 0 without one
  ContactState state = ContactState::Stick;
};

// The physics only: right-hand side, friction torque and event functions for y = (w, s, R).
class PinOnDiskSystem {
 public:
  PinOnDiskSystem(PinOnDiskParameters parameters, SlidingFriction friction);

  const PinOnDiskParameters &parameters() const { return p_; }
  const SlidingFriction &friction() const { return friction_; }

  double applied_torque(double t) const;
  static constexpr std::size_t state_size = 3;
  double static_torque_limit() const;  // mu_static W r at the initial friction state
  double static_torque_limit(const double *y) const;  // at the state y
  // `direction` = +-1 is the sliding direction (sign of w) in slip, unused in stick.
  double friction_torque(double t, const double *y, ContactState state, int direction) const;
  void rhs(double t, const double *y, double *dydt, ContactState state, int direction) const;
  // Stick ends when this crosses zero upwards.
  double breakaway_function(double t) const { return std::abs(applied_torque(t)) - static_torque_limit(); }
  double breakaway_function(double t, const double *y) const {
    return std::abs(applied_torque(t)) - static_torque_limit(y);
  }
  PinOnDiskSample sample(double t, const double *y, ContactState state, int direction) const;

 private:
  PinOnDiskParameters p_;
  SlidingFriction friction_;
};

struct PinOnDiskRun {
  double t_end = 4.0;             // s
  double output_interval = 1e-3;  // s; events and the ramp end are added to the grid
  double initial_speed = 0.0;     // m/s; nonzero starts in slip
  CvodeIntegrator::Settings integrator;
  int max_events = 1000;          // guards against stick-slip chattering

  void validate() const;
};

using PinOnDiskObserver = std::function<void(const PinOnDiskSample &)>;
// Called after each output-grid sample (after the observer): true when the friction was changed there (the
// state law's operator splitting, doc/state_law_continuum.md); CVODE then restarts from that sample.
using PinOnDiskRefresh = std::function<bool()>;

// The stepper: CVODE per contact phase, restarted at each event, at the ramp end and where `refresh` says.
// Numerical failure is reported in the status, bad settings throw std::invalid_argument; an exception from the
// observer or refresh propagates.
SolveReport simulate(const PinOnDiskSystem &system, const PinOnDiskRun &run, const PinOnDiskObserver &observer,
                     const PinOnDiskRefresh &refresh = {});

// Thesis eq. 4.10/4.11: speed under a constant torque T with mu = mu0 + alpha V,
// sliding from V0: V(t) = V_ss + (V0 - V_ss) exp(-alpha W t / m),
// V_ss = (T / r - mu0 W) / (alpha W). alpha = 0 gives the constant-acceleration limit.
double thesis_speed(const PinOnDiskParameters &p, double mu0, double alpha, double v0, double t);
// Eq. 4.11 solved for T: the constant torque that takes the pin from V0 to V1 at t1.
double thesis_torque_for_speed(const PinOnDiskParameters &p, double mu0, double alpha, double v0, double v1,
                               double t1);

// One-screen numbers of a run.
struct PinOnDiskSummary {
  double peak_friction_force = 0.0, peak_time = 0.0;
  double breakaway_time = -1.0;  // -1: never broke away (speed drive: 0)
  double start_friction_force = 0.0;  // largest |F| up to the first slip sample: mu_static W at break-away
  double steady_time = -1.0;     // -1: not steady (see steady_tolerance)
  double steady_friction_force = 0.0;
  double steady_mu = 0.0, steady_mu_law = 0.0, final_speed = 0.0;  // final values
  static constexpr double steady_tolerance = 0.02;  // relative, on friction force and speed
};
// Peak: largest |friction force|, timed at the first sample within 1e-6 of it.
// Time to equilibrium: from the first sample after which friction force and speed stay within
// steady_tolerance of their final values (equilibrium_time of each, the later of the two);
// "not steady" if that is in the last 10 % of the run.
PinOnDiskSummary summarise(const std::vector<PinOnDiskSample> &samples);

// Run-in distance of a run: `steady_mu` = the mean of F/W over the last `tail` of the sliding distance (each
// sample's mu weighted by the distance slid since the previous sample: F/W is held over it), `distance` = the
// sliding distance of the first sample from which on |mu - steady_mu| <= tolerance |steady_mu| (-1: none).
struct RunInDistance {
  double steady_mu = 0.0, distance = -1.0;
  double tolerance = 0.0, tail = 0.0;
};
RunInDistance run_in_distance(const std::vector<PinOnDiskSample> &samples, double tolerance = 0.02,
                              double tail = 0.1);

// Subsurface stress below the pin contact (doc/subsurface_stress.md): the von Mises field of
// each body on the section y = 0 through the contact (x along the sliding direction, 64 x 64 points to
// 1.5 contact radii wide and deep), from the pressure p and the friction shear q = mu p. The disk carries
// q in the sliding direction, the pin the opposite shear (mu -> -mu); each body uses its own Poisson ratio.
// BodyStress: continuum/contact_stress.h (shared with the line contacts).
struct ContactStress {
  std::string method;                  // "Hertz closed form (Hamilton 1983)" or "influence functions (...)"
  double friction_coefficient = 0.0;   // mu used for q = mu p
  double contact_radius = 0.0;         // m, of the pressure used
  double peak_pressure = 0.0;          // Pa
  BodyStress pin, disk;
};
// Hertzian contact: Hamilton's closed form.
ContactStress hertz_contact_stress(double peak_pressure, double contact_radius, double friction_coefficient,
                                   const tribo::Material &pin, const tribo::Material &disk, int points = 64);
// Any axisymmetric ring pressure (the worn profile): the Boussinesq/Cerruti influence tier on points x points
// patches centred on the section's abscissae.
ContactStress ring_contact_stress(const std::vector<double> &ring_pressure, double ring_width,
                                  double friction_coefficient, const tribo::Material &pin,
                                  const tribo::Material &disk, int points = 64);

}  // namespace runin::continuum
