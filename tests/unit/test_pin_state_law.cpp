// Pin-on-disk with a per-node state law: the operator splitting at the output interval (mu_eff held
// over an interval, node states advanced by the distance slid in it, CVODE restarted) converges to the
// monolithic solution at first order in the interval.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "continuum/node_state_law.h"
#include "continuum/pin_on_disk.h"
#include "continuum/pin_state_law.h"
#include "continuum/state_law_splitting.h"

using namespace runin;
using namespace runin::coupling;

namespace {

constexpr double kH0 = 1e-6, kC = 200.0;  // saturation depth, 1/m
double mu_of(double h) { return 0.3 - 1e5 * h; }  // 0.3 -> 0.2 over the run-in
double rate_of(double h) { return kC * (kH0 - h); }

std::shared_ptr<const StateLaw> make_law() {
  const std::vector<double> p = {1e6, 1e8};
  std::vector<double> h;
  for (int j = 0; j <= 4; ++j) h.push_back(kH0 * j / 4.0);
  std::array<StateFieldTable, state_field_count> fields;
  for (std::size_t f = 0; f < state_field_count; ++f) {
    fields[f].mean.assign(p.size(), std::vector<double>(h.size(), 0.0));
    for (auto &row : fields[f].mean)
      for (std::size_t j = 0; j < h.size(); ++j) {
        const auto field = static_cast<StateField>(f);
        row[j] = field == StateField::MuBody ? mu_of(h[j]) : field == StateField::WearRate ? rate_of(h[j]) : 0.0;
      }
  }
  return std::make_shared<const StateLaw>(p, h, fields);
}

continuum::PinOnDiskParameters parameters() {
  continuum::PinOnDiskParameters p;
  p.mass = 1.0;
  p.track_radius = 0.05;
  p.normal_load = 10.0;
  p.applied_torque = 0.2;  // 4 N drive against 3 N -> 2 N of friction
  p.ramp_time = 0.0;
  return p;
}

// Final speed with the splitting at `interval`.
double split_speed(double interval, double t_end) {
  auto state = std::make_shared<continuum::StateLawFriction>();
  state->law = make_law();
  state->path = "synthetic";
  const std::vector<double> p = {1e7}, area = {1e-6};
  continuum::NodeStateLaw nodes(state->law, OutOfRange::Error, 1);
  state->held_static = nodes.peak_mu(p, area);
  state->held_kinetic = nodes.mu_effective(p, area);
  const continuum::PinOnDiskSystem system(parameters(), continuum::SlidingFriction::state_law(state));
  continuum::PinOnDiskRun run;
  run.t_end = t_end;
  run.output_interval = interval;
  double slid = 0.0, speed = 0.0;
  bool changed = false;
  const auto report = continuum::simulate(
      system, run,
      [&](const continuum::PinOnDiskSample &s) {
        if (s.distance > slid) {
          nodes.advance(p, s.distance - slid);
          slid = s.distance;
          state->held_kinetic = nodes.mu_effective(p, area);
          changed = true;
        }
        speed = s.speed;
      },
      [&] {
        const bool was = changed;
        changed = false;
        return was;
      });
  EXPECT_TRUE(report.ok()) << report.message;
  return speed;
}

// Monolithic reference: y = (V, s, h), m dV/dt = T/r - mu(h) W, ds/dt = V, dh/dt = w(h) V; RK4 at a fine step.
double monolithic_speed(double t_end) {
  const auto p = parameters();
  auto f = [&](const std::array<double, 3> &y) {
    return std::array<double, 3>{(p.applied_torque / p.track_radius - mu_of(y[2]) * p.normal_load) / p.mass, y[0],
                                 rate_of(y[2]) * y[0]};
  };
  std::array<double, 3> y{0.0, 0.0, 0.0};
  const int n = 200000;
  const double dt = t_end / n;
  for (int i = 0; i < n; ++i) {
    const auto k1 = f(y);
    std::array<double, 3> y2, y3, y4;
    for (int j = 0; j < 3; ++j) y2[j] = y[j] + 0.5 * dt * k1[j];
    const auto k2 = f(y2);
    for (int j = 0; j < 3; ++j) y3[j] = y[j] + 0.5 * dt * k2[j];
    const auto k3 = f(y3);
    for (int j = 0; j < 3; ++j) y4[j] = y[j] + dt * k3[j];
    const auto k4 = f(y4);
    for (int j = 0; j < 3; ++j) y[j] += dt / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return y[0];
}

}  // namespace

TEST(PinStateLaw, SplittingAtTheOutputIntervalConvergesAtFirstOrder) {
  const double t_end = 0.2;
  const double reference = monolithic_speed(t_end);
  // The run-in is over s ~ 1/c = 5 mm: V reaches ~0.05 m/s by then.
  std::vector<double> error;
  for (double interval : {0.02, 0.01, 0.005, 0.0025}) error.push_back(std::abs(split_speed(interval, t_end) - reference));
  for (std::size_t i = 0; i + 1 < error.size(); ++i) {
    const double ratio = error[i] / error[i + 1];
    EXPECT_GT(ratio, 1.6) << "halving " << i;
    EXPECT_LT(ratio, 2.5) << "halving " << i;
  }
  EXPECT_LT(error.back() / reference, 1e-2);  // 0.46 % at 2.5 ms (1.9 % at 20 ms)
}

// The library's pin slow system through the splitting driver (continuum::PinStateLaw, continuum::split_run): a flat
// pin carries one uniform pressure on every ring, so its split is the one-node split above, ring by ring.
namespace {
continuum::PinStateLawSettings flat_pin(double radius) {
  continuum::PinStateLawSettings s;
  s.flat_radius = radius;
  s.tip.rings = 16;
  s.tip.effective_modulus = 1e11;
  s.load = parameters().normal_load;
  s.track_radius = parameters().track_radius;
  return s;
}

struct DriverRun {
  continuum::SplitReport report;
  double speed = 0.0;
};

DriverRun driver_speed(double radius, double interval, double t_end) {
  auto state = std::make_shared<continuum::StateLawFriction>();
  state->law = make_law();
  state->path = "synthetic";
  continuum::PinStateLaw pin(flat_pin(radius), *state);
  const continuum::PinOnDiskSystem system(parameters(), continuum::SlidingFriction::state_law(state));
  continuum::PinOnDiskRun run;
  run.t_end = t_end;
  run.output_interval = interval;
  DriverRun out;
  out.report = continuum::split_run<continuum::PinOnDiskSample>(
      pin, [&](const auto &on_sample, const auto &refresh) { return continuum::simulate(system, run, on_sample, refresh); },
      [&](const continuum::PinOnDiskSample &s) { out.speed = s.speed; });
  return out;
}
}  // namespace

TEST(PinStateLaw, TheDriverWithTheFlatPinIsTheOneNodeSplit) {
  const double radius = std::sqrt(1e-6 / M_PI);  // 10 N on 1 mm^2: 1e7 Pa, inside the law's grid
  for (double interval : {0.02, 0.005}) {
    const auto run = driver_speed(radius, interval, 0.2);
    ASSERT_TRUE(run.report.ok()) << run.report.message;
    EXPECT_GT(run.report.slow_steps, 0);
    EXPECT_NEAR(run.speed, split_speed(interval, 0.2), 1e-12) << interval;
  }
}

TEST(PinStateLaw, APressureBelowTheLawIsAStatusAtTheStart) {
  const auto run = driver_speed(0.1, 0.01, 0.1);  // 10 N on 314 cm^2: 318 Pa, below the grid's 1e6 Pa
  EXPECT_EQ(run.report.status, continuum::SplitStatus::LawOutOfRange);
  EXPECT_EQ(run.report.time, 0.0);
  EXPECT_NE(run.report.message.find("outside the law's range"), std::string::npos) << run.report.message;
}
