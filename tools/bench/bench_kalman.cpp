// The Kalman smoother baseline on the reference-like mission (60,000 steps, 6 mines),
// linearised until converged (its default tolerance), from its default start (a coarse
// chain's solution) and, as argument 1, from the dead reckoning (docs/comparison.md,
// "Where the linearisations start").
// Target: <= 100 ms.

#include <benchmark/benchmark.h>

#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"

namespace {

void BM_KalmanSmoother(benchmark::State& state) {
  gesmi::SimulationOptions o;
  o.seed = 1;
  const gesmi::Mission m = gesmi::simulate_mission(o);
  const std::vector<gesmi::PositionFix> fixes = gesmi::gps_fixes(m);
  gesmi::KalmanOptions options;
  if (state.range(0) == 1) options.start = gesmi::KalmanStart::dead_reckoning;
  int passes = 0, coarse_passes = 0;
  for (auto _ : state) {
    const gesmi::KalmanResult r = gesmi::kalman_smooth(m, m.model, fixes, options);
    passes = r.iterations;
    coarse_passes = r.coarse_iterations;
    benchmark::DoNotOptimize(r.mean.data());
  }
  state.SetLabel(gesmi::kalman_start_name(options.start));
  state.counters["passes"] = passes;  // linearisations until converged
  state.counters["coarse_passes"] = coarse_passes;
  state.counters["steps"] = static_cast<double>(m.size());
  state.counters["mines"] = m.mine_count;
}
BENCHMARK(BM_KalmanSmoother)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
