// "No allocation per box beyond the paving storage", measured: this test binary
// counts every operator new, and SIVIA's allocations must stay logarithmic in the
// number of boxes (vector growth of the pavings and per-level scratch), not linear.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "solver/setinv/outliers/gomne.h"
#include "solver/setinv/invert.h"
#include "solver/setinv/localization/measurement_simulator.h"
#include "solver/setinv/localization/range_contractor.h"
#include "solver/setinv/localization/range_data.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// The replaced operator new allocates with malloc, so free is the matching release;
// GCC cannot see that pairing.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace gesmi {
namespace {

struct DiskMinusEllipse {
  std::size_t output_count() const { return 2; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    y[0] = sqr(p[0]) + sqr(p[1]) - 1.0;
    y[1] = 1.0 - 2.0 * sqr(p[0]) - sqr(p[1]);
  }
};

TEST(SiviaAllocation, AllocationsGrowWithThePavingsNotWithTheBoxesExamined) {
  SiviaOptions options;
  options.epsilon = 0.001;
  ImageInBox<DiskMinusEllipse> data(DiskMinusEllipse{}, Box{Interval::neg_reals(), Interval::neg_reals()});
  AllDataHold<ImageInBox<DiskMinusEllipse>> test(data);
  const Box prior{Interval(-2.5, 2.5), Interval(-2.0, 2.0)};
  const long before = g_allocations;
  const SiviaResult r = sivia(test, prior, options);
  const long allocations = g_allocations - before;
  EXPECT_GT(r.report.boxes_visited, 50000u);
  // Two pavings of ~13,000 boxes grow by doubling (~2 x 15 allocations), plus one
  // scratch box per level (~25 levels).
  EXPECT_LT(allocations, 120) << r.report.boxes_visited << " boxes examined";
  std::printf("SIVIA: %zu boxes examined, %zu + %zu stored, %ld allocations\n", r.report.boxes_visited, r.inner.size(),
              r.boundary.size(), allocations);
}

TEST(SiviaAllocation, RangeDataAndContractorDoNotAllocatePerBox) {
  // A 12-sensor belt in a square room: SIVIA(q = 1) with the q-relaxed contractor.
  const std::vector<Segment> walls{{0, 0, 6, 0}, {6, 0, 6, 4}, {6, 4, 0, 4}, {0, 4, 0, 0}, {2, 1, 2, 1.5}};
  std::vector<RangeSensor> sensors;
  for (int i = 0; i < 12; ++i) {
    const double a = i * std::numbers::pi / 6;
    sensors.push_back({"s", 0.2 * std::cos(a), 0.2 * std::sin(a), a, 0.2, 0.02});
  }
  LocalizationMap map;
  map.walls = walls;
  MeasurementSimulationOptions sim;
  sim.range_outliers = {4};
  const auto measurements = simulate_ranges(map, sensors, {4.0, 2.5, 0.3}, sim);
  RangeData data(walls, sensors, measurements);
  const CtcRangeRelaxed ctc(walls, sensors, measurements, 1);
  SiviaOptions options;
  options.epsilon = 0.001;
  options.periodic_dimension = 2;
  const Box prior{Interval(-1, 7), Interval(-1, 5), Interval(0, 2 * std::numbers::pi)};
  const long before = g_allocations;
  const SiviaResult r = sivia_q(data, 1, std::span<const Box>(&prior, 1), options, NoPriorConstraint{}, ctc);
  const long allocations = g_allocations - before;
  EXPECT_GT(r.report.boxes_visited, 5000u);
  EXPECT_FALSE(r.inner.empty() && r.boundary.empty());
  EXPECT_LT(allocations, 200) << r.report.boxes_visited << " boxes examined";
  std::printf("SIVIA(q=1), range data + contractor: %zu boxes examined, %ld allocations\n", r.report.boxes_visited,
              allocations);
}

}  // namespace
}  // namespace gesmi
