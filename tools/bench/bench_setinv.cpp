// Set inversion: GOMNE on the 24-sensor belt with seven outliers (seed 004, target
// <= 1 s), bearing start-up in the warehouse (seed 003, target <= 50 ms), the
// triangle room (seed 002) and the appendix example, each with and without
// contractors before bisection, and seed 004's Example 2 (`gesmi estimate`, q = 0..6).
// Counters: boxes examined, inner and boundary boxes.

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "io/localization/estimation_scenario.h"
#include "io/localization/localization_scenario.h"
#include "solver/setinv/estimation_problem.h"
#include "solver/setinv/invert.h"
#include "solver/setinv/localization/localization_problem.h"

namespace {

using namespace gesmi;

std::filesystem::path missions() { return std::filesystem::path(GESMI_SOURCE_DIR) / "missions"; }

LocalizationProblem scenario(const std::string& name, bool contractors) {
  LocalizationProblem p = io::read_localization_scenario((missions() / "localization" / name).string());
  p.use_contractors = contractors;
  return p;
}

void solve(benchmark::State& state, const std::string& name, bool contractors) {
  const LocalizationProblem p = scenario(name, contractors);
  LocalizationResult r;
  for (auto _ : state) {
    r = localize(p);
    benchmark::DoNotOptimize(r.hypotheses.data());
  }
  std::size_t examined = r.paving.report.boxes_visited;
  if (r.gomne) {
    examined = 0;
    for (const GomneStep& s : r.gomne->steps) examined += s.boxes_visited;
    state.counters["q_star"] = r.gomne->q_star;
  }
  state.counters["examined"] = static_cast<double>(examined);
  state.counters["inner"] = static_cast<double>(r.paving.inner.size());
  state.counters["boundary"] = static_cast<double>(r.paving.boundary.size());
  state.counters["hypotheses"] = static_cast<double>(r.hypotheses.size());
  state.counters["truth"] = r.truth_enclosed;
}

void BM_Belt24Gomne(benchmark::State& s) { solve(s, "belt24_outliers.yaml", true); }
void BM_Belt24GomneNoContractor(benchmark::State& s) { solve(s, "belt24_outliers.yaml", false); }
void BM_WarehouseP04(benchmark::State& s) { solve(s, "warehouse_p04.yaml", true); }
void BM_WarehouseP04NoContractor(benchmark::State& s) { solve(s, "warehouse_p04.yaml", false); }
void BM_WarehouseP01(benchmark::State& s) { solve(s, "warehouse_p01.yaml", true); }
void BM_WarehouseP04Outliers(benchmark::State& s) { solve(s, "warehouse_p04_outliers.yaml", true); }
void BM_Triangle(benchmark::State& s) { solve(s, "triangle_two_hypotheses.yaml", true); }
void BM_TriangleNoContractor(benchmark::State& s) { solve(s, "triangle_two_hypotheses.yaml", false); }

BENCHMARK(BM_Belt24Gomne)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Belt24GomneNoContractor)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_WarehouseP04)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WarehouseP04NoContractor)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WarehouseP01)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WarehouseP04Outliers)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Triangle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TriangleNoContractor)->Unit(benchmark::kMillisecond);

// Seed 004, Example 2: j^{-1}(q) split by outlier set for q = 0..6, at epsilon 0.005.
void BM_Seed004Example2(benchmark::State& state) {
  const EstimationProblem p = io::read_estimation_scenario((missions() / "setinv/seed004_example2.yaml").string());
  EstimationResult r;
  for (auto _ : state) {
    r = estimate(p);
    benchmark::DoNotOptimize(r.levels.data());
  }
  std::size_t inner = 0, boundary = 0, proved = 0;
  for (const EstimationLevel& level : r.levels)
    for (const OutlierSetPaving& set : level.sets) {
      inner += set.inner.size();
      boundary += set.boundary.size();
      proved += !set.inner.empty();
    }
  state.counters["examined"] = static_cast<double>(r.boxes_examined());
  state.counters["inner"] = static_cast<double>(inner);        // summed over the sets: a box may
  state.counters["boundary"] = static_cast<double>(boundary);  // be a boundary box of several
  state.counters["proved_sets"] = static_cast<double>(proved);
  state.counters["q_star"] = r.q_star().value_or(-1);
  state.counters["limit_hit"] = r.box_limit_hit() || r.time_limit_hit();
}
BENCHMARK(BM_Seed004Example2)->Unit(benchmark::kMillisecond);

// Seed 002, appendix A: the unit disk minus the ellipse 2x² + y² < 1.
struct DiskMinusEllipse {
  std::size_t output_count() const { return 2; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    y[0] = sqr(p[0]) + sqr(p[1]) - 1.0;
    y[1] = 1.0 - 2.0 * sqr(p[0]) - sqr(p[1]);
  }
};

void BM_AppendixSivia(benchmark::State& state) {
  SiviaOptions options;
  options.epsilon = 1.0 / static_cast<double>(state.range(0));
  const Box prior{Interval(-2.5, 2.5), Interval(-2.0, 2.0)};
  const Box image{Interval::neg_reals(), Interval::neg_reals()};
  SiviaResult r;
  for (auto _ : state) r = invert(DiskMinusEllipse{}, image, prior, options);
  state.counters["inner_area"] = r.inner.volume();
  state.counters["boundary_area"] = r.boundary.volume();
  state.counters["exact_area"] = std::numbers::pi - std::numbers::pi / std::sqrt(2.0);
  state.counters["inner"] = static_cast<double>(r.inner.size());
  state.counters["boundary"] = static_cast<double>(r.boundary.size());
  state.counters["examined"] = static_cast<double>(r.report.boxes_visited);
}
BENCHMARK(BM_AppendixSivia)->Arg(10)->Arg(50)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
