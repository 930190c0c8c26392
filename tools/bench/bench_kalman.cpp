// The Kalman smoother baseline on the reference-like mission (60,000 steps, 6 mines),
// linearised until converged (its default tolerance).
// Target (issue: Kalman baseline): <= 100 ms.

#include <benchmark/benchmark.h>

#include "solver/kalman/kalman_smoother.h"
#include "solver/sim/simulator.h"

namespace {

void BM_KalmanSmoother(benchmark::State& state) {
  gesmi::SimulationOptions o;
  o.seed = 1;
  const gesmi::Mission m = gesmi::simulate_mission(o);
  const std::vector<gesmi::PositionFix> fixes = gesmi::gps_fixes(m);
  int passes = 0;
  for (auto _ : state) {
    const gesmi::KalmanResult r = gesmi::kalman_smooth(m, m.model, fixes);
    passes = r.iterations;
    benchmark::DoNotOptimize(r.mean.data());
  }
  state.counters["passes"] = passes;  // linearisations until converged
  state.counters["steps"] = static_cast<double>(m.size());
  state.counters["mines"] = m.mine_count;
}
BENCHMARK(BM_KalmanSmoother)->Unit(benchmark::kMillisecond);

}  // namespace
