// The blind zone of the sonar model (range_model.h): a wall is heard from the blind
// distance b on. Points against dense sampling of [ab] ∩ cone; boxes against the
// points they hold, wall by wall and through the min over a room.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "solver/setinv/localization/range_model.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {

constexpr int kSamples = 20000;

// What sampling the segment sees from s: the nearest point of [ab] ∩ cone at
// distance >= b and the farthest point of [ab] ∩ cone (inf and -1 when none).
struct Sampled {
  double nearest_heard = kInf;
  double farthest = -1.0;
};

Sampled sample(double sx, double sy, double axis, double gamma, const Segment& w, double blind) {
  Sampled out;
  const double face = (w.ax - sx) * (w.by - sy) - (w.ay - sy) * (w.bx - sx);
  if (face <= 0.0) return out;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    const double mx = w.ax + t * (w.bx - w.ax), my = w.ay + t * (w.by - w.ay);
    const double off = std::remainder(std::atan2(my - sy, mx - sx) - axis, 2 * std::numbers::pi);
    if (std::abs(off) > gamma) continue;
    const double d = std::hypot(mx - sx, my - sy);
    out.farthest = std::max(out.farthest, d);
    if (d >= blind) out.nearest_heard = std::min(out.nearest_heard, d);
  }
  return out;
}

Vec2T<double> unit(double angle) { return {std::cos(angle), std::sin(angle)}; }

TEST(RangeBlindZone, PointRemotenessIsTheNearestHeardPointOfRaySampling) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-3, 3), angle(-std::numbers::pi, std::numbers::pi), unit01(0, 1);
  int beyond = 0, at_blind = 0, unheard = 0;  // the three cases of the definition
  for (int trial = 0; trial < 4000; ++trial) {
    const Segment w{u(rng), u(rng), u(rng), u(rng)};
    const double sx = u(rng), sy = u(rng), axis = angle(rng), gamma = 11.3 * kRadiansPerDegree;
    const double plain = remoteness(Vec2T<double>{sx, sy}, unit(axis - gamma), unit(axis + gamma), w, 0.0);
    const Sampled all = sample(sx, sy, axis, gamma, w, 0.0);
    if (all.farthest < 0.0) {  // nothing in the cone: nothing heard, whatever b
      EXPECT_TRUE(std::isinf(remoteness(Vec2T<double>{sx, sy}, unit(axis - gamma), unit(axis + gamma), w, 3.0 * unit01(rng))));
      continue;
    }
    // Blind distances around the wall's distances, so that every case occurs.
    const double blind = 1.4 * all.farthest * unit01(rng) + 1e-3;
    const double r = remoteness(Vec2T<double>{sx, sy}, unit(axis - gamma), unit(axis + gamma), w, blind);
    const Sampled b = sample(sx, sy, axis, gamma, w, blind);
    const double step = std::hypot(w.bx - w.ax, w.by - w.ay) / kSamples;
    if (b.farthest >= blind + step) {
      // Heard: within a sample step of the nearest heard sample, never beyond it.
      ASSERT_TRUE(std::isfinite(r)) << trial;
      EXPECT_LE(r, b.nearest_heard + 1e-9) << trial;
      EXPECT_GE(r, b.nearest_heard - step - 1e-9) << trial;
      EXPECT_GE(r, blind) << trial;
      (plain >= blind ? beyond : at_blind) += 1;
    } else if (b.farthest < blind - step) {
      EXPECT_TRUE(std::isinf(r)) << trial << " r=" << r << " farthest=" << b.farthest << " blind=" << blind;
      ++unheard;
    }
  }
  EXPECT_GT(beyond, 50);
  EXPECT_GT(at_blind, 50);
  EXPECT_GT(unheard, 50);
}

TEST(RangeBlindZone, ZeroBlindDistanceIsTheSeedModel) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 3), angle(-std::numbers::pi, std::numbers::pi);
  for (int trial = 0; trial < 300; ++trial) {
    const Segment w{u(rng), u(rng), u(rng), u(rng)};
    const Vec2T<double> s{u(rng), u(rng)};
    const double axis = angle(rng), gamma = 11.3 * kRadiansPerDegree;
    const double plain = remoteness(s, unit(axis - gamma), unit(axis + gamma), w, 0.0);
    const double tiny = remoteness(s, unit(axis - gamma), unit(axis + gamma), w, 1e-300);
    EXPECT_EQ(plain, tiny) << trial;
  }
}

// A box of sensor poses near a wall, and points inside it: the wall's remoteness on
// the box holds the remoteness at every point (inf as an unbounded upper bound).
TEST(RangeBlindZone, BoxRemotenessOfAWallEnclosesEveryPoint) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.5, 1.5), unit01(0, 1), angle(-std::numbers::pi, std::numbers::pi);
  const double gamma = 11.3 * kRadiansPerDegree;
  int changed = 0, checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Segment w{u(rng), u(rng), u(rng), u(rng)};
    const double blind = 1.2 * unit01(rng);
    const double x = u(rng), y = u(rng), th = angle(rng);
    const double wx = 0.3 * unit01(rng), wy = 0.3 * unit01(rng), wt = 0.3 * unit01(rng);
    const Interval X(x, x + wx), Y(y, y + wy), A(th, th + wt);
    const Vec2T<Interval> s{X, Y}, u1{cos(A - gamma), sin(A - gamma)}, u2{cos(A + gamma), sin(A + gamma)};
    const Interval box = remoteness(s, u1, u2, w, blind);
    for (int k = 0; k < 20; ++k) {
      const double px = x + wx * unit01(rng), py = y + wy * unit01(rng), pt = th + wt * unit01(rng);
      const Vec2T<double> sp{px, py};
      const double r = remoteness(sp, unit(pt - gamma), unit(pt + gamma), w, blind);
      changed += r != remoteness(sp, unit(pt - gamma), unit(pt + gamma), w, 0.0);
      ++checked;
      if (std::isinf(r)) {
        EXPECT_EQ(box.hi(), kInf) << trial;
      } else {
        EXPECT_TRUE(box.contains(r)) << trial << " " << r << " not in [" << box.lo() << ", " << box.hi() << "]";
      }
    }
  }
  EXPECT_GT(changed, checked / 50);  // the blind zone decides a fair share of the points
}

TEST(RangeBlindZone, BoxRangeOfASensorInARoomEnclosesEveryPoint) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1.8, 1.5), unit01(0, 1), angle(-std::numbers::pi, std::numbers::pi);
  const std::vector<Segment> walls{{-2, -2, 2, -2}, {2, -2, 2, 2}, {2, 2, -2, 2}, {-2, 2, -2, -2},
                                   {0.2, 0.2, 0.2, 0.4}, {0.2, 0.4, 0.4, 0.4}, {0.4, 0.4, 0.4, 0.2}, {0.4, 0.2, 0.2, 0.2}};
  RangeSensor sensor{"s", 0.2, 0.1, 30 * kRadiansPerDegree, 11.3 * kRadiansPerDegree, 0.02};
  sensor.blind_distance = 0.5;
  int changed = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const double x = u(rng), y = u(rng), th = angle(rng);
    const double wx = 0.3 * unit01(rng), wy = 0.3 * unit01(rng), wt = 0.4 * unit01(rng);
    const Pose<Interval> box{Interval(x, x + wx), Interval(y, y + wy), Interval(th, th + wt)};
    const Interval range = simulated_range(box, sensor, std::span<const Segment>(walls));
    for (int k = 0; k < 20; ++k) {
      const Pose<double> p{x + wx * unit01(rng), y + wy * unit01(rng), th + wt * unit01(rng)};
      const double r = simulated_range(p, sensor, std::span<const Segment>(walls));
      RangeSensor seeing = sensor;
      seeing.blind_distance = 0.0;
      changed += r != simulated_range(p, seeing, std::span<const Segment>(walls));
      if (std::isinf(r)) {
        EXPECT_EQ(range.hi(), kInf) << trial;
      } else {
        EXPECT_TRUE(range.contains(r)) << trial << " " << r << " not in [" << range.lo() << ", " << range.hi() << "]";
      }
    }
  }
  EXPECT_GT(changed, 200);
}

}  // namespace
}  // namespace gesmi
