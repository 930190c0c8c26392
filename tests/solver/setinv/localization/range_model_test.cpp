// The sonar remoteness model (seed 000, Table 2): agreement with brute-force ray
// geometry on points, and the inclusion property on boxes (one templated code).

#include "solver/setinv/localization/range_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "solver/setinv/localization/range_data.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {


// Nearest point of [a b] ∩ cone by dense sampling of the segment; inf when the
// sensor is behind the reflecting face or nothing is in the cone.
double brute_remoteness(double sx, double sy, double axis, double gamma, const Segment& w) {
  const double face = (w.ax - sx) * (w.by - sy) - (w.ay - sy) * (w.bx - sx);
  if (face <= 0.0) return kInf;
  double best = kInf;
  for (int k = 0; k <= 20000; ++k) {
    const double t = k / 20000.0;
    const double mx = w.ax + t * (w.bx - w.ax), my = w.ay + t * (w.by - w.ay);
    const double off = std::remainder(std::atan2(my - sy, mx - sx) - axis, 2 * std::numbers::pi);
    if (std::abs(off) <= gamma) best = std::min(best, std::hypot(mx - sx, my - sy));
  }
  return best;
}

TEST(RangeModel, RemotenessAgreesWithRayGeometryOnPoints) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3), angle(-std::numbers::pi, std::numbers::pi);
  int finite = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Segment w{u(rng), u(rng), u(rng), u(rng)};
    const double sx = u(rng), sy = u(rng), axis = angle(rng), gamma = 11.3 * kRadiansPerDegree;
    const Vec2T<double> s{sx, sy}, u1{std::cos(axis - gamma), std::sin(axis - gamma)},
        u2{std::cos(axis + gamma), std::sin(axis + gamma)};
    const double r = remoteness(s, u1, u2, w, 0.0);
    const double b = brute_remoteness(sx, sy, axis, gamma, w);
    if (std::isinf(b)) {
      EXPECT_TRUE(std::isinf(r)) << trial << " r=" << r;
    } else {
      ++finite;
      // Sampling finds a point at most half a sample step beyond the true minimum.
      EXPECT_LE(r, b + 1e-9) << trial;
      EXPECT_GE(r, b - std::hypot(w.bx - w.ax, w.by - w.ay) / 20000.0 - 1e-9) << trial;
    }
  }
  EXPECT_GT(finite, 40);
}

TEST(RangeModel, DistanceAlongAUnitVectorUsesTheDeterminant) {
  // Seed 000 Example 1 prints <ab, u> in the denominator; the geometry needs
  // det(ab, u): from (0, 1) straight down to the line y = 0 the distance is 1.
  const Segment w{0, 0, 1, 0};
  const double g = 5 * kRadiansPerDegree;
  const Vec2T<double> s{0.5, 1.0}, u1{std::cos(-90 * kRadiansPerDegree - g), std::sin(-90 * kRadiansPerDegree - g)},
      u2{std::cos(-90 * kRadiansPerDegree + g), std::sin(-90 * kRadiansPerDegree + g)};
  EXPECT_NEAR(remoteness(s, u1, u2, w, 0.0), 1.0, 1e-12);
  // Behind the face (below the segment), nothing comes back.
  const Vec2T<double> below{0.5, -1.0};
  EXPECT_TRUE(std::isinf(remoteness(below, Vec2T<double>{-u1.x, -u1.y}, Vec2T<double>{-u2.x, -u2.y}, w, 0.0)));
}

TEST(RangeModel, BoxEvaluationEnclosesEveryPointEvaluation) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-4, 4), unit(0, 1), angle(-std::numbers::pi, std::numbers::pi);
  const std::vector<Segment> walls{{-5, -5, 5, -5}, {5, -5, 5, 5}, {5, 5, -5, 5}, {-5, 5, -5, -5}, {-1, 0, 1, 0.5}};
  const RangeSensor sensor{"s", 0.2, 0.1, 30 * kRadiansPerDegree, 11.3 * kRadiansPerDegree, 0.02};
  for (int trial = 0; trial < 300; ++trial) {
    const double x = u(rng), y = u(rng), th = angle(rng);
    const double wx = 0.3 * unit(rng), wy = 0.3 * unit(rng), wt = 0.4 * unit(rng);
    const Pose<Interval> box{Interval(x, x + wx), Interval(y, y + wy), Interval(th, th + wt)};
    const Interval range = simulated_range(box, sensor, std::span<const Segment>(walls));
    for (int k = 0; k < 20; ++k) {
      const Pose<double> p{x + wx * unit(rng), y + wy * unit(rng), th + wt * unit(rng)};
      const double r = simulated_range(p, sensor, std::span<const Segment>(walls));
      if (std::isinf(r)) {
        EXPECT_EQ(range.hi(), kInf) << trial;
      } else {
        EXPECT_TRUE(range.contains(r)) << trial << " " << r << " not in [" << range.lo() << ", " << range.hi() << "]";
      }
    }
  }
}

TEST(RangeModel, RangeDataPruningKeepsTheVerdictsOfTheFullModel) {
  // The per-level wall pruning must give the same data verdicts as member(f(P), D).
  const std::vector<Segment> walls{{-5, -5, 5, -5}, {5, -5, 5, 5}, {5, 5, -5, 5}, {-5, 5, -5, -5}, {-1, 0, 1, 0.5}};
  std::vector<RangeSensor> sensors;
  for (int i = 0; i < 6; ++i)
    sensors.push_back({"s", 0.2 * std::cos(i * 60 * kRadiansPerDegree), 0.2 * std::sin(i * 60 * kRadiansPerDegree),
                       i * 60 * kRadiansPerDegree, 11.3 * kRadiansPerDegree, 0.02});
  const Pose<double> truth{1.0, -2.0, 0.4};
  std::vector<RangeMeasurement> measurements;
  for (std::size_t i = 0; i < sensors.size(); ++i)
    measurements.push_back({i, simulated_range(truth, sensors[i], std::span<const Segment>(walls))});
  RangeData data(walls, sensors, measurements);
  std::vector<IBool> out(sensors.size(), IBool::maybe());
  // Nested boxes around the truth, one per level: children inherit their father's state.
  for (int depth = 0; depth < 12; ++depth) {
    const double h = 2.0 / (1 << depth);
    const Box box{Interval(1.0 - h, 1.0 + h * 0.7), Interval(-2.0 - h * 0.6, -2.0 + h), Interval(0.4 - h / 4, 0.4 + h / 5)};
    data.evaluate(box, depth, out, 99);
    const Pose<Interval> p{box[0], box[1], box[2]};
    for (std::size_t i = 0; i < sensors.size(); ++i) {
      const IBool full = member(simulated_range(p, sensors[i], std::span<const Segment>(walls)), data.feasible(i));
      EXPECT_FALSE(out[i].is_false()) << depth << " " << i;  // the truth is inside every box
      if (!full.is_maybe()) {
        EXPECT_TRUE(out[i] == full) << depth << " " << i;
      }
    }
  }
  EXPECT_TRUE(out[0].is_true() || out[0].is_maybe());
}

}  // namespace
}  // namespace gesmi
