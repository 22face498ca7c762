// Pin-on-disk with a per-node state law and adaptive wear steps (continuum::run_pin_split, WearSteps): against a
// fine fixed-interval run, the reported F/W lags the state by at most the tolerance (the error control's bound),
// so the error falls in proportion to the tolerance; the worn volumes agree; Archard's invariant holds over 1 km of
// the tribometer set-up; bad settings throw, and the run-in distance of a curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "continuum/pin_on_disk.h"
#include "continuum/pin_state_law.h"
#include "coupling/state_law.h"

using namespace runin;

namespace {

const std::shared_ptr<const coupling::StateLaw> &rough_law() {
  static const auto law = std::make_shared<const coupling::StateLaw>(
      coupling::StateLaw::read_file(std::string(RUNIN_SOURCE_DIR) + "/inputs/state_law_steel_rough.json"));
  return law;
}

// Flat AISI 1020 pin (1.5 mm, 32 rings) on the shipped rough-on-rough law at a set speed.
struct PinSetup {
  double load = 20.0, speed = 0.1, track_radius = 0.05, ramp = 0.05, t_end = 0.05;
  double torque = 0.0, alpha = 0.0, mass = 0.001;  // torque > 0: the torque drive
};

struct Outcome {
  std::vector<continuum::PinOnDiskSample> samples;
  std::vector<double> mu_eff, wear, disk_wear;  // after each sample's slow step
  continuum::SplitReport report;
};

Outcome run(const PinSetup &u, const continuum::WearSteps &steps, double interval) {
  auto held = std::make_shared<continuum::StateLawFriction>();
  held->law = rough_law();
  held->policy = coupling::OutOfRange::Archard;
  held->path = "inputs/state_law_steel_rough.json";
  continuum::PinOnDiskParameters p;
  p.drive = continuum::PinDrive::Speed;
  p.sliding_speed = u.speed;
  p.mass = 0.001;
  p.track_radius = u.track_radius;
  p.normal_load = u.load;
  p.ramp_time = u.ramp;
  p.mass = u.mass;
  if (u.torque > 0.0) {
    p.drive = continuum::PinDrive::Torque;
    p.applied_torque = u.torque;
  }
  const continuum::PinOnDiskSystem system(p, continuum::SlidingFriction::state_law(held, u.alpha));
  continuum::PinStateLawSettings settings;
  settings.flat_radius = 1.5e-3;
  settings.tip.rings = 32;
  settings.tip.effective_modulus = 110e9;
  settings.load = u.load;
  settings.track_radius = u.track_radius;
  continuum::PinStateLaw pin(settings, *held);
  continuum::PinOnDiskRun r;
  r.t_end = u.t_end;
  r.output_interval = interval;
  r.integrator.rtol = 1e-10;  // the fixed interval's s(t) from CVODE: near the drive's closed form
  r.integrator.atol = 1e-14;
  Outcome o;
  o.report = continuum::run_pin_split(system, r, pin, steps, [&](const continuum::PinOnDiskSample &s) {
    o.samples.push_back(s);
    const auto st = pin.state();
    o.mu_eff.push_back(st.mu_eff);
    o.wear.push_back(st.wear_volume);
    o.disk_wear.push_back(st.disk_wear_volume);
  });
  EXPECT_TRUE(o.report.ok()) << o.report.message;
  return o;
}

continuum::WearSteps adaptive(double tolerance, double max_fraction = 1e-3) {
  continuum::WearSteps w;
  w.adaptive = true;
  w.tolerance = tolerance;
  w.max_fraction = max_fraction;
  return w;
}

// mu_eff of the reference at distance s (linear between its samples).
double at(const Outcome &ref, double s) {
  std::size_t i = 1;
  while (i + 1 < ref.samples.size() && ref.samples[i].distance < s) ++i;
  const double s0 = ref.samples[i - 1].distance, s1 = ref.samples[i].distance;
  const double w = s1 > s0 ? std::clamp((s - s0) / (s1 - s0), 0.0, 1.0) : 1.0;
  return ref.mu_eff[i - 1] + w * (ref.mu_eff[i] - ref.mu_eff[i - 1]);
}

// Largest |F/W - mu(s)| / mu(s) of a run against the reference's state.
double mu_error(const Outcome &o, const Outcome &ref) {
  double e = 0.0;
  for (const auto &s : o.samples) {
    const double mu = at(ref, s.distance);
    e = std::max(e, std::abs(s.mu - mu) / mu);
  }
  return e;
}

}  // namespace

// Bound: an accepted step changes mu_eff by at most tol |mu_eff| and F/W over it is the held value, so
// |F/W(s_k) - mu(s_k)| <= tol |mu(s_k-1)| ~ tol |mu(s_k)|; the node states are integrated along s (RK4 in the
// law's own sub-steps) whatever the step, so the worn volumes agree to round-off of that quadrature. The
// reference: a fixed interval of 10 us (1 um of sliding at most), its mu_eff after each step interpolated in s.
TEST(PinAdaptiveWearSteps, FollowsFixedIntervalWithinTolerance) {
  const PinSetup u;
  const Outcome ref = run(u, {}, 1e-5);
  const std::vector<double> tolerances = {1e-2, 3e-3, 1e-3};
  std::vector<double> errors;
  for (double tol : tolerances) {
    const Outcome a = run(u, adaptive(tol, 1.0), 1e-3);  // no cap on the step: the tolerance alone sets it
    const double e = mu_error(a, ref);
    errors.push_back(e);
    EXPECT_LE(e, 1.05 * tol + 1e-5) << "tolerance " << tol;
    EXPECT_LT(a.samples.size(), ref.samples.size());
    EXPECT_NEAR(a.samples.back().distance / ref.samples.back().distance, 1.0, 1e-6);  // CVODE's s(t): 5e-7
    EXPECT_NEAR(a.wear.back() / ref.wear.back(), 1.0, tol) << "tolerance " << tol;
    EXPECT_NEAR(a.disk_wear.back() / ref.disk_wear.back(), 1.0, tol) << "tolerance " << tol;
    std::printf("tolerance %g: %zu samples (%ld rejected), max |F/W - mu| / mu = %.3g; worn volume / fixed - 1 = %.2g, "
                "disk %.2g\n",
                tol, a.samples.size(), a.report.rejected_steps, e, a.wear.back() / ref.wear.back() - 1.0,
                a.disk_wear.back() / ref.disk_wear.back() - 1.0);
  }
  // first order in the tolerance
  for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
    const double order = std::log(errors[k] / errors[k + 1]) / std::log(tolerances[k] / tolerances[k + 1]);
    std::printf("observed order %g -> %g: %.3f\n", tolerances[k], tolerances[k + 1], order);
    EXPECT_GT(order, 0.8);
    EXPECT_LT(order, 1.2);
  }
  // the fixed interval's own lag at 1 ms (0.1 mm of sliding at most) is far above the adaptive run's
  const Outcome coarse = run(u, {}, 1e-3);
  const double coarse_error = mu_error(coarse, ref);
  std::printf("fixed interval 1 ms: max |F/W - mu| / mu = %.3g\n", coarse_error);
  EXPECT_GT(coarse_error, errors.front());
}

// Torque drive with alpha > 0: the full dynamics (at the output interval) over the ramp and wherever the pin would
// lag its quasi-static speed V_ss = (T / r - mu_eff W) / (alpha W) by more than the tolerance, quasi-static steps
// elsewhere. Against a 10 us fixed interval: F/W along s in slip, the sliding distance and the speed at the end.
TEST(PinAdaptiveWearSteps, TorqueDriveFallsBackToTheDynamics) {
  PinSetup u;
  u.track_radius = 0.02;
  u.ramp = 0.01;
  u.t_end = 0.1;
  // alpha W = 20 N s/m (tau = m / (alpha W) = 50 us): V_ss 0.1 -> 0.117 m/s; alpha W = 4 N s/m (250 us): 0.1 -> 0.186
  for (double alpha : {1.0, 0.2}) {
    u.alpha = alpha;
    u.torque = u.track_radius * (0.0397 * 20 + alpha * 20 * 0.1);  // V_ss = 0.1 m/s at the law's peak mu
    const Outcome ref = run(u, {}, 1e-5);
    // the reference's own lag of F/W behind its state: what the stretches of dynamics (at its interval) carry
    double lag = 0.0;
    for (std::size_t k = 0; k < ref.samples.size(); ++k) {
      const auto &s = ref.samples[k];
      if (s.state == continuum::ContactState::Slip && s.distance > 0.0)
        lag = std::max(lag, std::abs(s.mu - alpha * s.speed - ref.mu_eff[k]) / ref.mu_eff[k]);
    }
    for (double tol : {1e-2, 1e-3}) {
      const Outcome a = run(u, adaptive(tol), 1e-5);  // the dynamics' stretches at the reference's interval
      double e = 0.0;  // the friction law's part of F/W (F/W - alpha V) against the reference's state
      for (const auto &s : a.samples)
        if (s.state == continuum::ContactState::Slip && s.distance > 0.0) {
          const double mu = at(ref, s.distance);
          e = std::max(e, std::abs(s.mu - alpha * s.speed - mu) / mu);
        }
      const auto &x = a.samples.back(), &y = ref.samples.back();
      std::printf("torque drive, alpha %g, tolerance %g: %zu samples (%ld rejected, %ld stretches of dynamics, %ld "
                  "CVODE steps; reference %zu, %ld), max |F/W - alpha V - mu| / mu = %.3g (the reference's own lag "
                  "%.3g); s / reference - 1 = %.2g, V %.2g\n",
                  alpha, tol, a.samples.size(), a.report.rejected_steps, a.report.fallbacks, a.report.fast.steps,
                  ref.samples.size(), ref.report.fast.steps, e, lag, x.distance / y.distance - 1,
                  x.speed / y.speed - 1);
      EXPECT_LT(a.samples.size(), ref.samples.size() / 3);
      EXPECT_GT(a.report.fast.steps, 0);
      EXPECT_LE(e, std::max(2.0 * tol, 1.05 * lag));
      EXPECT_NEAR(x.distance / y.distance, 1.0, tol);
      EXPECT_NEAR(x.speed / y.speed, 1.0, tol);
    }
  }
  // samples land on the stop times in the quasi-static steps too
  auto stops = adaptive(1e-2);
  stops.stop_times = {0.0501, 0.0777};
  const Outcome a = run(u, stops, 1e-5);
  for (double t : stops.stop_times)
    EXPECT_TRUE(std::any_of(a.samples.begin(), a.samples.end(),
                            [&](const continuum::PinOnDiskSample &s) { return std::abs(s.t - t) < 1e-12; }))
        << t;
  u.alpha = 0.0;  // no steady sliding under a held torque
  EXPECT_THROW(run(u, adaptive(1e-3), 1e-3), std::invalid_argument);
}

// Samples land on the requested stop times (VTK frames) and at t_end; the torque drive is refused.
TEST(PinAdaptiveWearSteps, StopsAndSettings) {
  const PinSetup u;
  auto steps = adaptive(1e-3);
  steps.stop_times = {0.0123, 0.04};
  const Outcome a = run(u, steps, 1e-3);
  for (double t : steps.stop_times)
    EXPECT_TRUE(std::any_of(a.samples.begin(), a.samples.end(),
                            [&](const continuum::PinOnDiskSample &s) { return std::abs(s.t - t) < 1e-12; }))
        << t;
  EXPECT_DOUBLE_EQ(a.samples.back().t, u.t_end);
  for (double bad : {0.0, -1e-3, 0.2, std::nan(""), HUGE_VAL}) {
    auto w = adaptive(bad);
    EXPECT_THROW(w.validate(), std::invalid_argument) << bad;
  }
}

// Archard's invariant over 1 km of the tribometer set-up (inputs/pin_on_disk_tribometer.toml: 20 N, 0.5 m/s on a
// 20 mm track, 2000 s): worn volume / (K integral W ds) within 2 % for the pin and for the disk.
TEST(PinAdaptiveWearSteps, ArchardOverOneKilometre) {
  PinSetup u;
  u.speed = 0.5;
  u.track_radius = 0.02;
  u.t_end = 2000.0;
  const Outcome a = run(u, adaptive(1e-3), 2e-3);
  const double slid = a.samples.back().distance;
  EXPECT_NEAR(slid, 0.5 * (2000.0 - 0.025), 1e-9);
  const auto r = continuum::archard_ratios(*rough_law(), a.wear.back(), a.disk_wear.back(), u.load * slid);
  std::printf("1 km: %zu samples, Archard ratio pin %.6f, disk %.6f\n", a.samples.size(), r.pin, r.disk);
  EXPECT_NEAR(r.pin, 1.0, 0.02);
  EXPECT_NEAR(r.disk, 1.0, 0.02);
  EXPECT_LT(a.samples.size(), 20000u);
}

// Steady value: the distance-weighted mean of F/W over the last 10 % of sliding; the run-in distance: the first
// sample from which on F/W stays within 2 % of it.
TEST(PinAdaptiveWearSteps, RunInDistance) {
  std::vector<continuum::PinOnDiskSample> samples;
  for (int i = 0; i <= 100; ++i) {
    continuum::PinOnDiskSample s;
    s.distance = i;
    s.mu = i < 30 ? 0.5 : (i < 40 ? 0.3 : 0.2);  // 0.3 is 50 % above the steady 0.2
    samples.push_back(s);
  }
  samples[95].mu = 0.203;  // inside 2 %: mean over (90, 100] = 0.2003
  const auto r = continuum::run_in_distance(samples);
  EXPECT_NEAR(r.steady_mu, 0.2 + 0.003 / 10, 1e-12);
  EXPECT_DOUBLE_EQ(r.distance, 40.0);
  samples.back().mu = 0.25;
  EXPECT_LT(continuum::run_in_distance(samples).distance, 0.0);
}
