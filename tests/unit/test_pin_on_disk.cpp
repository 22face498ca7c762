// Pin-on-disk torque balance (thesis ch. 4) against closed forms: eq. 4.10/4.11, the
// break-away time of the ramp, exact stick, re-stick, and a tabulated micro law.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "continuum/pin_on_disk.h"
#include "tribo/feedback.h"

using namespace runin::continuum;

namespace {
// Thesis numbers: W = 0.981 N, m = 0.001 kg, r = 0.102 m, mu0 = 0.95, alpha = 0.68 s/m.
constexpr double kMass = 0.001, kRadius = 0.102, kLoad = 0.981, kMu0 = 0.95, kAlpha = 0.68;

PinOnDiskParameters thesis_parameters(double torque, double ramp_time) {
  PinOnDiskParameters p;
  p.mass = kMass;
  p.track_radius = kRadius;
  p.normal_load = kLoad;
  p.applied_torque = torque;
  p.ramp_time = ramp_time;
  return p;
}

PinOnDiskRun tight_run(double t_end, double interval, double initial_speed = 0.0) {
  PinOnDiskRun run;
  run.t_end = t_end;
  run.output_interval = interval;
  run.initial_speed = initial_speed;
  run.integrator.rtol = 1e-11;
  run.integrator.atol = 1e-14;
  return run;
}

std::vector<PinOnDiskSample> run_all(const PinOnDiskSystem &system, const PinOnDiskRun &run, SolveReport *report) {
  std::vector<PinOnDiskSample> samples;
  *report = simulate(system, run, [&](const PinOnDiskSample &s) { samples.push_back(s); });
  return samples;
}
}  // namespace

TEST(PinOnDisk, ThesisTorqueFromEq411) {
  const auto p = thesis_parameters(0.0, 0.0);
  // exp(-alpha W t / m) = exp(-1334) = 0, so T = r W (mu0 + alpha V1).
  const double torque = thesis_torque_for_speed(p, kMu0, kAlpha, 0.0, 0.1, 2.0);
  EXPECT_NEAR(torque, kRadius * kLoad * (kMu0 + kAlpha * 0.1), 1e-15);
  EXPECT_NEAR(torque, 0.10186, 1e-5);  // thesis prints ~40 N m; see doc/pin_on_disk.md
  // alpha = 0 limit: constant acceleration.
  EXPECT_NEAR(thesis_torque_for_speed(p, kMu0, 0.0, 0.0, 0.1, 2.0), kRadius * (kMu0 * kLoad + kMass * 0.05), 1e-15);
}

TEST(PinOnDisk, ConstantTorqueMatchesEq410) {
  // Tolerance 1e-6 relative on V at several times, CVODE at rtol 1e-11.
  for (const double v0 : {0.05, 0.3}) {  // accelerating and decelerating towards V_ss = 0.1 m/s
    const double torque = kRadius * kLoad * (kMu0 + kAlpha * 0.1);
    const PinOnDiskSystem system(thesis_parameters(torque, 0.0), SlidingFriction::constant(kMu0, kAlpha));
    SolveReport report;
    const auto samples = run_all(system, tight_run(0.02, 1e-4, v0), &report);
    ASSERT_TRUE(report.ok()) << report.message;
    EXPECT_TRUE(report.breakaway_times.empty());
    EXPECT_TRUE(report.restick_times.empty());
    int checked = 0;
    for (const auto &s : samples)
      for (const double t : {2e-4, 1e-3, 3e-3, 1e-2, 2e-2})
        if (std::abs(s.t - t) < 1e-12) {
          const double exact = thesis_speed(system.parameters(), kMu0, kAlpha, v0, s.t);
          EXPECT_NEAR(s.speed / exact, 1.0, 1e-6) << "t = " << s.t << ", V0 = " << v0;
          EXPECT_EQ(s.state, ContactState::Slip);
          ++checked;
        }
    EXPECT_EQ(checked, 5);
  }
}

TEST(PinOnDisk, ThesisTorqueReachesTargetSpeedAtTwoSeconds) {
  const auto p0 = thesis_parameters(0.0, 0.0);
  const double torque = thesis_torque_for_speed(p0, kMu0, kAlpha, 0.0, 0.1, 2.0);
  const PinOnDiskSystem system(thesis_parameters(torque, 0.0), SlidingFriction::constant(kMu0, kAlpha));
  SolveReport report;
  const auto samples = run_all(system, tight_run(2.0, 0.5), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.breakaway_times.size(), 1u);  // step load above the static limit: breaks away at t = 0
  EXPECT_EQ(report.breakaway_times[0], 0.0);
  EXPECT_NEAR(samples.back().t, 2.0, 1e-15);
  EXPECT_NEAR(samples.back().speed / 0.1, 1.0, 1e-6);
}

TEST(PinOnDisk, BreakAwayEventOfTheRampAndExactStick) {
  const double mu = 0.55, ramp = 2.0;
  const double limit = mu * kLoad * kRadius;
  const double torque = 1.5 * limit;
  const PinOnDiskSystem system(thesis_parameters(torque, ramp), SlidingFriction::constant(mu));
  SolveReport report;
  auto run = tight_run(2.5, 1e-2);
  run.integrator.rtol = 1e-8;  // event location does not depend on the state tolerance
  run.integrator.atol = 1e-12;
  const auto samples = run_all(system, run, &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.breakaway_times.size(), 1u);
  const double expected = mu * kLoad * kRadius * ramp / torque;
  EXPECT_NEAR(report.breakaway_times[0] / expected, 1.0, 1e-8);

  int stick_samples = 0;
  bool event_sampled = false;
  for (const auto &s : samples) {
    if (s.t == report.breakaway_times[0]) event_sampled = true;
    if (s.state != ContactState::Stick) continue;
    ++stick_samples;
    EXPECT_EQ(s.friction_torque, s.applied_torque);  // exact, not a regularised law
    EXPECT_EQ(s.speed, 0.0);
    EXPECT_EQ(s.distance, 0.0);
    EXPECT_LE(s.applied_torque, limit * (1 + 1e-12));
  }
  EXPECT_GT(stick_samples, 100);
  EXPECT_TRUE(event_sampled);
  // Without a speed term the pin accelerates after break-away at (T - mu W r) / J.
  const double t_end = samples.back().t;
  EXPECT_GT(samples.back().speed, 0.0);
  EXPECT_NEAR(samples.back().friction_torque, limit, 1e-15);
  EXPECT_DOUBLE_EQ(t_end, 2.5);
}

TEST(PinOnDisk, ReSticksWhenSpeedReachesZeroBelowTheStaticLimit) {
  const double mu_s = 0.6, mu_k = 0.4, v0 = 0.05;
  const double torque = 0.5 * mu_k * kLoad * kRadius;  // held, below both limits
  const PinOnDiskSystem system(thesis_parameters(torque, 0.0), SlidingFriction::static_kinetic(mu_s, mu_k));
  SolveReport report;
  const auto samples = run_all(system, tight_run(0.05, 1e-3, v0), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.restick_times.size(), 1u);
  // Constant deceleration (T / r - mu_k W) / m until V = 0.
  const double stop_time = v0 * kMass / (mu_k * kLoad - torque / kRadius);
  EXPECT_NEAR(report.restick_times[0] / stop_time, 1.0, 1e-8);
  EXPECT_EQ(samples.back().state, ContactState::Stick);
  EXPECT_EQ(samples.back().speed, 0.0);
  EXPECT_EQ(samples.back().friction_torque, torque);
  EXPECT_NEAR(samples.back().distance, 0.5 * v0 * stop_time, 1e-9 * v0 * stop_time);
}

TEST(PinOnDisk, LawFileFrictionIsReproducedAlongTheSlidingDistance) {
  // Micro law in nm: spring loading to mu = 0.6 at 100 nm, linear fall to 0.3 at 500 nm, then flat.
  using runin::coupling::FrictionLaw;
  const FrictionLaw law{"micro.txt", "v_slide", "c_fric[3]", "nm", 1e-9,
                        runin::coupling::TabulatedLaw({0.0, 100.0, 500.0}, {0.0, 0.6, 0.3}), std::nullopt};
  const double scale = 1e5;  // 1 nm micro -> 0.1 mm macro
  const auto friction = SlidingFriction::from_law(law, FrictionLaw::Branch::Table, scale);
  EXPECT_EQ(friction.static_coefficient(), 0.6);

  const double torque = 0.7 * kLoad * kRadius, ramp = 1.0;
  const PinOnDiskSystem system(thesis_parameters(torque, ramp), friction);
  SolveReport report;
  const auto samples = run_all(system, tight_run(1.1, 1e-3), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.breakaway_times.size(), 1u);
  EXPECT_NEAR(report.breakaway_times[0] / (0.6 / 0.7 * ramp), 1.0, 1e-8);
  int slipping = 0;
  for (const auto &s : samples) {
    if (s.state != ContactState::Slip) continue;
    ++slipping;
    const double micro_nm = 100.0 + s.distance / (scale * 1e-9);  // sliding starts at the peak
    const double expected = micro_nm >= 500.0 ? 0.3 : 0.6 - 0.3 * (micro_nm - 100.0) / 400.0;
    EXPECT_NEAR(s.mu, expected, 1e-12) << "s = " << s.distance;
  }
  EXPECT_GT(slipping, 50);
  EXPECT_GT(samples.back().distance, 400e-9 * scale);  // the run covered the whole decay
}

TEST(PinOnDisk, NumericalFailureIsAStatusNotAnException) {
  const PinOnDiskSystem system(thesis_parameters(0.2, 0.0), SlidingFriction::constant(kMu0, kAlpha));
  auto run = tight_run(1.0, 1.0, 0.05);
  run.integrator.max_steps = 3;
  const SolveReport report = simulate(system, run, [](const PinOnDiskSample &) {});
  EXPECT_EQ(report.status, SolveStatus::IntegratorFailure);
  EXPECT_NE(report.message.find("CV_TOO_MUCH_WORK"), std::string::npos) << report.message;
}

TEST(PinOnDisk, RejectsImpossibleParameters) {
  auto p = thesis_parameters(0.1, 2.0);
  p.mass = -1.0;
  EXPECT_THROW(PinOnDiskSystem(p, SlidingFriction::constant(kMu0)), std::invalid_argument);
  EXPECT_THROW(SlidingFriction::constant(-0.1), std::invalid_argument);
}

TEST(PinOnDisk, SummaryFindsPeakBreakAwayAndSteadyState) {
  const PinOnDiskSystem system(thesis_parameters(0.10186, 2.0), SlidingFriction::constant(kMu0, kAlpha));
  SolveReport report;
  const auto samples = run_all(system, tight_run(3.0, 1e-3), &report);
  ASSERT_TRUE(report.ok());
  const auto summary = summarise(samples);
  EXPECT_EQ(summary.breakaway_time, report.breakaway_times[0]);
  EXPECT_NEAR(summary.steady_mu, kMu0 + kAlpha * summary.final_speed, 1e-9);
  EXPECT_GT(summary.steady_time, 1.95);
  EXPECT_LT(summary.steady_time, 2.05);
}

TEST(PinOnDisk, ConstantTorqueDistanceMatchesIntegralOfEq410) {
  // s(t) = V_ss t + (V0 - V_ss) tau (1 - exp(-t / tau)), tau = m / (alpha W): 1e-6 relative.
  const double torque = kRadius * kLoad * (kMu0 + kAlpha * 0.1), v0 = 0.3;
  const PinOnDiskSystem system(thesis_parameters(torque, 0.0), SlidingFriction::constant(kMu0, kAlpha));
  SolveReport report;
  const auto samples = run_all(system, tight_run(0.02, 1e-3, v0), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  const double tau = kMass / (kAlpha * kLoad), v_ss = (torque / kRadius - kMu0 * kLoad) / (kAlpha * kLoad);
  ASSERT_NEAR(v_ss, 0.1, 1e-12);
  for (const auto &s : samples) {
    if (s.t < 1e-3) continue;
    const double exact = v_ss * s.t + (v0 - v_ss) * tau * (1.0 - std::exp(-s.t / tau));
    EXPECT_NEAR(s.distance / exact, 1.0, 1e-6) << "t = " << s.t;
  }
}

TEST(PinOnDisk, VelocityWeakeningFollowsEq410WithTheMinusSign) {
  // mu = mu0 - alpha V: eq. 4.10 with alpha -> -alpha, exp(+alpha W t / m) growth away from V_ss.
  const double torque = kRadius * kLoad * (kMu0 - kAlpha * 0.1), v0 = 0.12;  // V_ss = 0.1, unstable
  const PinOnDiskSystem system(thesis_parameters(torque, 0.0), SlidingFriction::constant(kMu0, -kAlpha));
  SolveReport report;
  const auto samples = run_all(system, tight_run(5e-3, 1e-3, v0), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  for (const auto &s : samples) {
    const double exact = thesis_speed(system.parameters(), kMu0, -kAlpha, v0, s.t);
    EXPECT_NEAR(s.speed / exact, 1.0, 1e-6) << "t = " << s.t;
  }
  EXPECT_GT(samples.back().speed, 5.0 * v0);  // V - V_ss grew by exp(3.3) = 27
}

TEST(PinOnDisk, FeedbackRoughnessFollowsItsClosedFormAlongTheSlidingDistance) {
  // dR/ds = -A K1 R + B K2 / R  =>  R(s)^2 = R*^2 + (R0^2 - R*^2) exp(-2 A K1 s); mu = C1 R + C2 / R.
  runin::tribo::FeedbackCoefficients k{0.2, 0.2, 1.0, 1.0, 50.0, 50.0};
  const runin::tribo::FeedbackModel model(k, runin::tribo::FeedbackKind::dry);
  const auto friction = SlidingFriction::feedback(model, 4.0, true, kAlpha);
  EXPECT_DOUBLE_EQ(friction.static_coefficient(), 0.85);
  const double torque = kRadius * kLoad * 0.9, ramp = 1.0;
  const PinOnDiskSystem system(thesis_parameters(torque, ramp), friction);
  SolveReport report;
  const auto samples = run_all(system, tight_run(2.0, 1e-3), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.breakaway_times.size(), 1u);
  EXPECT_NEAR(report.breakaway_times[0] / (0.85 / 0.9 * ramp), 1.0, 1e-8);  // mu(R0) sets break-away
  for (const auto &s : samples) {
    const double exact = model.exact_roughness(4.0, s.distance);
    EXPECT_NEAR(s.roughness / exact, 1.0, 1e-6) << "s = " << s.distance;
    EXPECT_NEAR(s.mu_law, model.mu(s.roughness), 1e-12);
  }
  // Thesis claim 3 (in the coefficient): mu falls from mu(R0) = 0.85 towards mu(R*) = 0.4.
  EXPECT_NEAR(samples.back().mu_law, 0.4, 1e-3);
  EXPECT_GT(samples.front().mu_law, 2.0 * samples.back().mu_law);
}

TEST(PinOnDisk, FeedbackPerTimeEvolvesDuringStick) {
  runin::tribo::FeedbackCoefficients k{0.2, 0.2, 1.0, 1.0, 1.0, 1.0};
  const runin::tribo::FeedbackModel model(k, runin::tribo::FeedbackKind::dry);
  const PinOnDiskSystem system(thesis_parameters(0.01 * kRadius * kLoad, 0.0),
                               SlidingFriction::feedback(model, 4.0, false));
  SolveReport report;
  const auto samples = run_all(system, tight_run(1.0, 0.1), &report);
  ASSERT_TRUE(report.ok());
  EXPECT_TRUE(report.breakaway_times.empty());  // 0.01 < mu(R) throughout
  for (const auto &s : samples) EXPECT_NEAR(s.roughness / model.exact_roughness(4.0, s.t), 1.0, 1e-6);
}

TEST(PinOnDisk, ThesisTorqueRampOrdersPeakForceAndBreakAwayByMu0) {
  // The thesis's three runs: mu0 = 0.15, 0.55, 0.95, everything else fixed; T_app from eq. 4.11
  // for each (100 mm/s at 2 s), ramped over 2 s and held. Peak force (= T_app / r, > 20 % apart) and
  // break-away order by mu0. The time to equilibrium does not: the speed lags the torque by only
  // m / (alpha W) = 1.5 ms, so all three settle within 20 ms of the ramp end (claim 2 is shown with the
  // speed drive below).
  std::vector<PinOnDiskSummary> summaries;
  for (const double mu0 : {0.15, 0.55, 0.95}) {
    auto p = thesis_parameters(0.0, 2.0);
    p.applied_torque = thesis_torque_for_speed(p, mu0, kAlpha, 0.0, 0.1, 2.0);
    const PinOnDiskSystem system(p, SlidingFriction::constant(mu0, kAlpha));
    SolveReport report;
    const auto samples = run_all(system, tight_run(3.0, 1e-4), &report);
    ASSERT_TRUE(report.ok());
    summaries.push_back(summarise(samples));
    EXPECT_NEAR(summaries.back().final_speed, 0.1, 1e-6);
    EXPECT_NEAR(summaries.back().peak_friction_force, p.applied_torque / kRadius, 1e-9);
    EXPECT_NEAR(summaries.back().steady_time, 2.0, 0.02) << mu0;
  }
  for (std::size_t i = 1; i < summaries.size(); ++i) {
    EXPECT_GT(summaries[i].peak_friction_force, 1.2 * summaries[i - 1].peak_friction_force);
    EXPECT_GT(summaries[i].breakaway_time, summaries[i - 1].breakaway_time);
  }
}

TEST(PinOnDisk, TorqueDriveHoldsTheFrictionForceAtTheAppliedTorqueWhateverTheLaw) {
  // Why claim 3 cannot show in the force under the thesis's torque drive: once the pin slides at
  // a steady speed, F = T_app / r however far mu has run in (here mu(R) falls 0.85 -> 0.4 and the
  // speed rises instead).
  runin::tribo::FeedbackCoefficients k{0.2, 0.2, 1.0, 1.0, 50.0, 50.0};
  const runin::tribo::FeedbackModel model(k, runin::tribo::FeedbackKind::dry);
  auto p = thesis_parameters(0.0, 2.0);
  p.applied_torque = thesis_torque_for_speed(p, 0.85, kAlpha, 0.0, 0.1, 2.0);
  const PinOnDiskSystem system(p, SlidingFriction::feedback(model, 4.0, true, kAlpha));
  SolveReport report;
  const auto samples = run_all(system, tight_run(3.0, 1e-3), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  for (const auto &s : samples) EXPECT_LE(s.friction_force, p.applied_torque / kRadius * (1 + 1e-9)) << s.t;
  EXPECT_NEAR(samples.back().friction_force, p.applied_torque / kRadius, 1e-6 * p.applied_torque / kRadius);
  EXPECT_LT(samples.back().mu_law, 0.5);
}

namespace {
// inputs/pin_on_disk_runin.toml: speed drive 0.1 m/s after a 2 s ramp, dry feedback law
// mu = 0.04 R + 0.01 / R, R* = 1 um (mu* = 0.05), A = B = 10 /m, + 0.68 V.
runin::tribo::FeedbackModel runin_law() {
  return runin::tribo::FeedbackModel({0.04, 0.01, 1.0, 1.0, 10.0, 10.0}, runin::tribo::FeedbackKind::dry);
}
PinOnDiskParameters speed_drive() {
  auto p = thesis_parameters(0.0, 2.0);
  p.drive = PinDrive::Speed;
  p.sliding_speed = 0.1;
  return p;
}
}  // namespace

TEST(PinOnDisk, SpeedDriveFrictionIsTheLawAlongTheRampDistance) {
  // V = V1 t / t_r on the ramp, so s = V1 t^2 / (2 t_r), then s = V1 (t - t_r / 2); F = (mu(R(s)) + alpha V) W
  // with R(s) the closed form of dR/ds = -A K1 R + B K2 / R.
  const auto law = runin_law();
  const double r0 = SlidingFriction::feedback_roughness_for(law, 0.95);
  EXPECT_NEAR(law.mu(r0), 0.95, 1e-12);
  const PinOnDiskSystem system(speed_drive(), SlidingFriction::feedback(law, r0, true, kAlpha));
  SolveReport report;
  const auto samples = run_all(system, tight_run(4.0, 1e-2), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.breakaway_times.size(), 1u);
  EXPECT_EQ(report.breakaway_times[0], 0.0);
  EXPECT_NEAR(samples.front().friction_force, 0.95 * kLoad, 1e-12);  // mu0 W at the start
  for (const auto &s : samples) {
    const double v = 0.1 * std::min(s.t / 2.0, 1.0);
    const double dist = s.t <= 2.0 ? 0.1 * s.t * s.t / 4.0 : 0.1 * (s.t - 1.0);
    EXPECT_NEAR(s.speed, v, 1e-12);
    EXPECT_NEAR(s.distance, dist, 1e-8) << s.t;
    EXPECT_NEAR(s.roughness / law.exact_roughness(r0, s.distance), 1.0, 1e-6) << s.t;
    EXPECT_NEAR(s.friction_force, (law.mu(s.roughness) + kAlpha * v) * kLoad, 1e-12);
  }
}

TEST(PinOnDisk, ThesisClaims2And3UnderTheSpeedDriveWithTheRunInLaw) {
  // Only mu0 changes (through R0, mu(R0) = mu0). Claim 2: peak force > 1.2 x the next lower mu0's, time
  // to equilibrium (force and speed in a 2 % band of their final values, 2 ms grid) > 1.1 x. Claim 3:
  // the start (mu0 W) > 1.2 x the steady (mu* + alpha V1) W. Measured: doc/validation.md.
  std::vector<PinOnDiskSummary> runs;
  for (const double mu0 : {0.95, 0.55, 0.15}) {
    const auto law = runin_law();
    const PinOnDiskSystem system(speed_drive(),
                                 SlidingFriction::feedback(law, SlidingFriction::feedback_roughness_for(law, mu0), true, kAlpha));
    SolveReport report;
    const auto samples = run_all(system, tight_run(8.0, 2e-3), &report);
    ASSERT_TRUE(report.ok()) << report.message;
    runs.push_back(summarise(samples));
    const auto &r = runs.back();
    std::printf("claims: mu0 %.2f peak %.6g N start %.6g N steady %.6g N equilibrium %.6g s\n", mu0,
                r.peak_friction_force, r.start_friction_force, r.steady_friction_force, r.steady_time);
    ASSERT_GT(r.steady_time, 2.0) << mu0;  // after the ramp: not an artefact of its end
    EXPECT_NEAR(r.start_friction_force, mu0 * kLoad, 1e-12);
    EXPECT_GT(r.start_friction_force, 1.2 * r.steady_friction_force) << mu0;
  }
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_GT(runs[i - 1].peak_friction_force, 1.2 * runs[i].peak_friction_force);
    EXPECT_GT(runs[i - 1].steady_time, 1.1 * runs[i].steady_time);
  }
}

TEST(PinOnDisk, FrictionlessPinSlidesFromTheStart) {
  // mu0 = 0: no static limit, so the ramp moves the pin at once:
  // m dV/dt = T_app t / (r t_ramp)  =>  V = T_app t^2 / (2 m r t_ramp).
  const double torque = 1e-3, ramp = 2.0;
  const PinOnDiskSystem system(thesis_parameters(torque, ramp), SlidingFriction::constant(0.0));
  SolveReport report;
  const auto samples = run_all(system, tight_run(1.0, 0.25), &report);
  ASSERT_TRUE(report.ok()) << report.message;
  ASSERT_EQ(report.breakaway_times.size(), 1u);
  EXPECT_EQ(report.breakaway_times[0], 0.0);
  const auto &last = samples.back();
  EXPECT_NEAR(last.speed / (torque * 1.0 / (2.0 * kMass * kRadius * ramp)), 1.0, 1e-8);
}
