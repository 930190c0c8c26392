// The mission solver on simulated reference-like missions: cold propagation to the
// fixpoint (60,000 steps, 6 mines), its scaling with mission length, the sensor
// enclosures (build), the warm rerun after one added detection, the association of
// marks without numbers and the outlier-tolerant solve.
// Targets: cold <= 20 ms; 10^7 steps <= 5 s; warm <= 2 ms; association of
// 12 marks <= 1 s; Q = 2 outlier solve <= 10 x cold.

#include <benchmark/benchmark.h>

#include <map>

#include "io/geodesy.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/incremental_solver.h"
#include "solver/network/outliers/outlier_solver.h"
#include "solver/network/waterfall/waterfall.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace {

using namespace gesmi;


// A simulated mission with its network and sensor domains, built once per setup.
struct Problem {
  Mission mission;
  MissionNetwork network;
  TubeDomains sensor;
  explicit Problem(const SimulationOptions& o) : mission(simulate_mission(o)) {
    network = build_network(mission, mission.model, gps_fixes(mission));
    sensor = sensor_domains(mission, mission.model);
  }
  TubeDomains initial() const {
    TubeDomains d = sensor;
    add_network_priors(d, network);
    return d;
  }
};

const Problem& reference(int variant = 0) {
  static std::map<int, Problem> cache;
  auto it = cache.find(variant);
  if (it == cache.end()) {
    SimulationOptions o;
    o.seed = 1;
    if (variant == 1) o.unassociated = 1.0;
    if (variant == 2) o.outliers = 1;
    if (variant == 3) o.outliers = 2;
    it = cache.emplace(variant, Problem(o)).first;
  }
  return it->second;
}

void BM_ColdSolve(benchmark::State& state) {
  const Problem& p = reference();
  int sweeps = 0;
  for (auto _ : state) {
    state.PauseTiming();
    TubeDomains d = p.initial();
    state.ResumeTiming();
    sweeps = solve(p.network, d).sweeps;
    benchmark::DoNotOptimize(d.px.data());
  }
  state.counters["steps"] = static_cast<double>(p.mission.size());
  state.counters["sweeps"] = sweeps;
}
BENCHMARK(BM_ColdSolve)->Unit(benchmark::kMillisecond);

void BM_SensorEnclosures(benchmark::State& state) {
  // Arg: the step model (0 trapezoid, 1 rate-hull, 2 sample).
  Mission m = reference().mission;
  m.model.step_model = static_cast<StepModel>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(sensor_domains(m, m.model).dx.data());
  state.counters["steps"] = static_cast<double>(m.size());
}
// Process CPU time: the build runs on every core (solver/network/step_chunks.h).
BENCHMARK(BM_SensorEnclosures)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void BM_ClassifySteps(benchmark::State& state) {
  // The step regimes and the readings' check (step_regimes.h) over the reference mission.
  const Mission& m = reference().mission;
  std::size_t fallback = 0;
  for (auto _ : state) fallback = classify_steps(m, m.model).report().fallback_steps;
  state.counters["steps"] = static_cast<double>(m.size());
  state.counters["fallback_steps"] = static_cast<double>(fallback);
}
BENCHMARK(BM_ClassifySteps)->Unit(benchmark::kMillisecond);

// The mission as a reader gives it: fixes in latitude/longitude and the local frame's
// margins that io/ sets (docs/model.md, "The local frame's north" and "scale").
Mission with_local_frame(Mission m) {
  io::set_geodetic_gps(m);
  io::fill_local_gps(m, "reference");
  return m;
}

// The whole library solve (solve_mission: sensor enclosures, network, propagation; no
// waterfall). Arg 0: the simulator's mission, whose headings are in the local frame (no
// frame margin, one pass); arg 1: with the frame margins io/ sets, so that the solve runs
// its two passes.
void BM_SolveMission(benchmark::State& state) {
  Mission m = reference().mission;
  if (state.range(0) == 1) m = with_local_frame(std::move(m));
  SolveOptions options;
  options.waterfall = false;
  options.diagnose = false;
  for (auto _ : state) benchmark::DoNotOptimize(solve_mission(m, options).domains.px.data());
  state.counters["steps"] = static_cast<double>(m.size());
}
BENCHMARK(BM_SolveMission)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// The reconstructed waterfall of a solved reference mission (6 mines, 60,000 steps): what
// solve_mission adds after propagation, with the frame's margins over the tube.
void BM_Waterfall(benchmark::State& state) {
  const Mission m = with_local_frame(reference().mission);
  SolveOptions options;
  options.waterfall = false;
  const MissionSolution solved = solve_mission(m, options);
  const double max_speed = speed_bound(m);
  for (auto _ : state) benchmark::DoNotOptimize(compute_waterfall(m, m.model, solved.domains, nullptr, max_speed).lower.data());
  state.counters["steps"] = static_cast<double>(m.size());
}
BENCHMARK(BM_Waterfall)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

// Cold propagation on missions of 10^5, 10^6 and 10^7 steps (the survey repeated).
void BM_ColdSolveScaling(benchmark::State& state) {
  SimulationOptions o;
  o.seed = 2;
  o.duration = static_cast<double>(state.range(0)) / 10.0;
  const Problem p(o);
  const std::size_t bytes_per_step = 6 * sizeof(Interval);
  for (auto _ : state) {
    state.PauseTiming();
    TubeDomains d = p.initial();
    state.ResumeTiming();
    benchmark::DoNotOptimize(solve(p.network, d).sweeps);
  }
  state.counters["steps"] = static_cast<double>(p.mission.size());
  state.counters["ns_per_step"] =
      benchmark::Counter(static_cast<double>(p.mission.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["domain_bytes_per_step"] = static_cast<double>(bytes_per_step);
}
BENCHMARK(BM_ColdSolveScaling)->Arg(100000)->Arg(1000000)->Arg(10000000)->Unit(benchmark::kMillisecond)->Iterations(2);

void BM_WarmRerunOneDetection(benchmark::State& state) {
  const Problem& p = reference();
  // The solved domains without the last detection, then that detection added.
  MissionNetwork before = p.network;
  before.detections.pop_back();
  TubeDomains solved = p.sensor;
  add_network_priors(solved, before);
  solve(before, solved);
  solved.candidates.push_back(p.network.detections.back().allowed);
  const std::vector<std::size_t> added = {p.network.detections.size() - 1};
  std::size_t items = 0;
  for (auto _ : state) {
    state.PauseTiming();
    TubeDomains d = solved;
    state.ResumeTiming();
    items = propagate_from(p.network, d, added).work_items;
  }
  state.counters["work_items"] = static_cast<double>(items);
}
BENCHMARK(BM_WarmRerunOneDetection)->Unit(benchmark::kMicrosecond);

void BM_AssociationWithoutNumbers(benchmark::State& state) {
  const Problem& p = reference(1);
  for (auto _ : state) {
    state.PauseTiming();
    TubeDomains d = p.initial();
    state.ResumeTiming();
    benchmark::DoNotOptimize(solve(p.network, d).sweeps);
  }
  state.counters["marks"] = static_cast<double>(p.mission.mark_count());
}
BENCHMARK(BM_AssociationWithoutNumbers)->Unit(benchmark::kMillisecond);

void BM_OutlierTolerantSolveQ2(benchmark::State& state) {
  const Problem& p = reference(2);
  OutlierReport r;
  for (auto _ : state) {
    TubeDomains d;
    r = solve_with_outliers(p.network, p.sensor, d, {2, {}, OutlierMode::minimal});
  }
  state.counters["q_star"] = r.minimal_outliers;
  state.counters["full_solves"] = r.full_solves;
  state.counters["screened"] = r.hypotheses_screened;
}
BENCHMARK(BM_OutlierTolerantSolveQ2)->Unit(benchmark::kMillisecond);

// --max-outliers 2 (the q-relaxed set S_2) against the cold propagation: on the
// mission without outliers (every removal set is consistent: the most work) and with
// two corrupted marks; fixes trusted or not. Target: <= 50 x a cold propagation.
void BM_RelaxedOutlierSolveQ2(benchmark::State& state) {
  const Problem& p = reference(static_cast<int>(state.range(0)));
  OutlierOptions o;
  o.max_outliers = 2;
  o.trust_fixes = state.range(1) != 0;
  OutlierReport r;
  for (auto _ : state) {
    TubeDomains d;
    r = solve_with_outliers(p.network, p.sensor, d, o);
    benchmark::DoNotOptimize(d.px.data());
  }
  state.counters["q_star"] = r.minimal_outliers;
  state.counters["removal_sets"] = static_cast<double>(r.removal_sets);
  state.counters["consistent_sets"] = static_cast<double>(r.consistent_removal_sets);
}
BENCHMARK(BM_RelaxedOutlierSolveQ2)->ArgsProduct({{0, 3}, {0, 1}})->Unit(benchmark::kMillisecond);

}  // namespace
