// The bias-and-noise relaxation (solver/structured/) on a reference-like mission read
// with bias-noise errors (59,995 steps, the simulator's seed 1): the argument is the
// bias share in percent, of the data and of the model alike. Counters: the widest
// north or east box of the per-sample tube before and after, and the linear programs.

#include <benchmark/benchmark.h>

#include <algorithm>

#include "solver/network/sensors/step_regimes.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"
#include "solver/structured/structured_relaxation.h"

namespace {

using namespace gesmi;

double widest_box(const std::vector<Interval>& north, const std::vector<Interval>& east) {
  double w = 0.0;
  for (std::size_t k = 0; k < north.size(); ++k) w = std::max({w, north[k].width(), east[k].width()});
  return w;
}

void BM_StructuredRelaxation(benchmark::State& state) {
  const double share = static_cast<double>(state.range(0)) / 100.0;
  SimulationOptions o;
  o.seed = 1;
  o.errors = SimulatedErrors::bias_noise;
  o.bias_share = share;
  const Mission m = simulate_mission(o);
  SolveOptions options;
  options.waterfall = false;
  const MissionSolution tube = solve_mission(m, options);
  const StepRegimes regimes = classify_steps(m, m.model);
  const StructuredErrors errors = split_by_bias_share(m.model, share);
  StructuredBounds b;
  for (auto _ : state) b = relax_structured(m, regimes, errors, tube.domains);
  state.counters["steps"] = static_cast<double>(m.size());
  state.counters["tube_m"] = widest_box(tube.domains.px, tube.domains.py);
  state.counters["relaxed_m"] = widest_box(b.north, b.east);
  state.counters["lps"] = static_cast<double>(b.linear_programs);
}
BENCHMARK(BM_StructuredRelaxation)
    ->Arg(0)
    ->Arg(50)
    ->Arg(90)
    ->Arg(100)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace
