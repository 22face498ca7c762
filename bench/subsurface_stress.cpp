// Wall time of the subsurface stress field (src/tribo/subsurface_stress.h):
// "the stress field for a 512-node contact on a 64 x 64 subsurface grid takes < 50 ms".
//   build/bench/subsurface_stress --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Cases (Hertz pressure, q = mu p, nu = 0.3, every component of the tensor at every grid point):
//   Line:         2-D Flamant strip tier, 512 nodes, 64 x 64 (x, z) grid (journal bearing / piston ring).
//   Axisymmetric: 3-D Boussinesq/Cerruti tier, 512 rings resampled on 64 x 64 patches, section y = 0 on the
//                 64 patch-centre abscissae x 64 depths (the pin; includes the resampling).
//   Hamilton:     the closed form on the same 64 x 64 section, for scale.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "tribo/subsurface_stress.h"

using namespace runin::tribo;

namespace {

double hertz(double r) { return r < 1.0 ? std::sqrt(1.0 - r * r) : 0.0; }

void Line(benchmark::State &state)
{
  const double mu = state.range(0) / 10.0;
  std::vector<double> nodes, p, q;
  for (int j = 0; j < 512; ++j) {
    nodes.push_back(-1.0 + (j + 0.5) / 256.0);
    p.push_back(hertz(std::abs(nodes.back())));
    q.push_back(mu * p.back());
  }
  const LineTraction t = LineTraction::from_nodes(nodes, p, q);
  const std::vector<double> x = cell_centres(-2.0, 2.0, 64), z = uniform_points(0.0, 2.0, 64);
  for (auto _ : state) benchmark::DoNotOptimize(line_traction_field(t, 0.3, x, z));
}

void Axisymmetric(benchmark::State &state)
{
  const double mu = state.range(0) / 10.0;
  const double h = 1.5 / 512;    // 512 rings to 1.5 a, 341 of them loaded
  std::vector<double> rings;
  for (int i = 0; i < 512; ++i) rings.push_back(hertz((i + 0.5) * h));
  const std::vector<double> z = uniform_points(0.0, 1.5, 64);
  for (auto _ : state) benchmark::DoNotOptimize(axisymmetric_section(rings, h, mu, 0.3, 1.5, 64, z));
}

void Hamilton(benchmark::State &state)
{
  const SlidingHertzSphere c{1.0, 1.0, 0.3, state.range(0) / 10.0};
  const std::vector<double> x = cell_centres(-1.5, 1.5, 64), z = uniform_points(0.0, 1.5, 64);
  for (auto _ : state) benchmark::DoNotOptimize(hamilton_field(c, x, z));
}

}  // namespace

BENCHMARK(Line)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Axisymmetric)->Arg(0)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Hamilton)->Arg(3)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
