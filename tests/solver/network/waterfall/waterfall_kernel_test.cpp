// The waterfall's kernel (solver/network/waterfall/waterfall_kernel.h) against the portable
// interval computation it replaces (sonar_ranges(): SonarPlane's rough test and
// contractor): on random and adversarial pairs placed at the edges of the sonar's
// geometry (the along-track tolerance, the range, the depth band, the side), and on
// every (step, mine) of simulated missions, a cell the kernel rejects must be empty for
// the portable computation too, and a cell it keeps must have the same bounds. The
// portable cells are checked against long-double configurations in
// waterfall_soundness_test.cpp.

#include "solver/network/waterfall/waterfall_kernel.h"

#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <numbers>
#include <random>

#include "solver/mission/frame_scale.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/network/waterfall/sonar_ranges.h"
#include "solver/network/waterfall/waterfall.h"
#include "solver/sim/simulator.h"
#include "solver/solve/solve_mission.h"

namespace gesmi {
namespace {

struct KernelCase {
  Vec3I p, m;
  Interval roll, pitch, heading, altitude;
  double slack = 0.0;
  SonarGeometry g;
};

class Cases {
 public:
  explicit Cases(std::uint64_t seed) : rng_(seed) {}

  // A mine placed where the geometry holds or nearly: its body-frame offset at the edge
  // of the along-track tolerance, the range or the side, its depth at the edge of the
  // band, then often moved a little; boxes from points to metres wide.
  KernelCase next() {
    KernelCase c;
    c.g.along_tolerance = pick({0.0, 0.05, 1.0, 2.5});
    c.g.depth_band = pick({0.0, 0.25, 0.75, 2.0});
    c.g.max_range = pick({20.0, 75.0, 150.0});
    c.g.sonar_side = pick({SonarSide::both, SonarSide::starboard, SonarSide::port});
    const double roll = unit(-0.3, 0.3), pitch = unit(-0.3, 0.3), heading = unit(-3.2, 3.2);
    c.roll = Interval::around(roll, angle_radius());
    c.pitch = Interval::around(pitch, angle_radius());
    c.heading = Interval::around(heading, angle_radius());
    c.slack = pick({0.0, 1e-9 * unit(0, 1), 0.05 * unit(0, 1), 0.5 * unit(0, 1)});
    // The body-frame offset e_b = R^T (p - m): along, across (sign: side), down <= 0.
    const double along = edge(c.g.along_tolerance, 3.0);
    const double range = edge(c.g.max_range, c.g.max_range);
    const double down = -range * unit(0.05, 0.95);
    const double side = rng_() % 2 ? 1.0 : -1.0;
    const double rest = std::max(0.0, range * range - along * along - down * down);
    const double across = rng_() % 8 == 0 ? edge(0.0, 2.0) : -side * std::sqrt(rest);
    const Attitude<double> a = make_attitude(roll, pitch, heading);
    const Vec3d e = body_to_world(a, Vec3d(along, across, down));
    const double p[3] = {unit(-1000, 1000), unit(-1000, 1000), unit(0, 100)};
    // e.z = -(altitude + s), |s| <= band: the altitude at the band's edge, or off it.
    c.altitude = Interval::around(-e[2] - edge(c.g.depth_band, 3.0), pick({0.0, 0.01, 0.3}) * unit(0, 1));
    const double move = pick({0.0, 0.0, 1e-9, 1e-3, 0.5, 5.0});
    for (int i = 0; i < 3; ++i) {
      c.p[i] = box(p[i]);
      c.m[i] = box(p[i] - e[i] + move * unit(-1, 1));
    }
    return c;
  }

 private:
  double unit(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  template <class T>
  T pick(std::initializer_list<T> values) {
    return values.begin()[rng_() % values.size()];
  }
  // Near the edge +-x: x times 1 + a tiny, small or large relative change, or anywhere
  // within +-spread.
  double edge(double x, double spread) {
    const double sign = rng_() % 2 ? 1.0 : -1.0;
    switch (rng_() % 4) {
      case 0: return sign * x * (1.0 + unit(-1e-12, 1e-12));
      case 1: return sign * x * (1.0 + unit(-1e-6, 1e-6));
      case 2: return sign * x + unit(-0.1, 0.1);
      default: return unit(-spread, spread);
    }
  }
  double angle_radius() { return pick({0.0, 1e-6, 1e-3, 0.02, 0.05, 0.05, 0.06}) * unit(0.5, 1.0); }
  Interval box(double centre) {
    const double w = pick({0.0, 1e-6, 0.01, 1.0, 8.0});
    return Interval(centre - w * unit(0, 1), centre + w * unit(0, 1));
  }

  std::mt19937_64 rng_;
};

SonarPlane plane_of(const KernelCase& c) {
  SonarPlane plane;
  plane.attitude = make_attitude(c.roll, c.pitch, c.heading);
  plane.altitude = c.altitude;
  plane.along_tolerance = c.g.along_tolerance;
  plane.depth_band = c.g.depth_band;
  plane.frame_slack = c.slack;
  return plane;
}

bool same_bounds(const Interval& x, double lo, double hi) { return x.lo() == lo && x.hi() == hi; }

TEST(WaterfallKernel, KeepsWhatThePortableCellsKeepWithTheSameBounds) {
  Cases cases(13);
  int refused = 0, undecided = 0, kept = 0, rough_rejected = 0, contractor_rejected = 0;
  int failures = 0, lost = 0;  // cells that differ; of them, rejected by the kernel only
  for (int n = 0; n < 300000; ++n) {
    const KernelCase c = cases.next();
    KernelStep step;
    if (!prepare_kernel_step(c.p, c.roll, c.pitch, c.heading, c.altitude, c.slack, step) || !kernel_takes(c.m)) {
      ++refused;
      continue;
    }
    const KernelMine mine{{c.m[0].lo(), c.m[1].lo(), c.m[2].lo()}, {c.m[0].hi(), c.m[1].hi(), c.m[2].hi()}};
    const KernelPair pair{0, 0};
    KernelCell cell{};
    kernel_sonar_ranges(c.g, {&step, 1}, {&mine, 1}, {&pair, 1}, {&cell, 1});
    const SonarPlane plane = plane_of(c);
    const Interval portable = sonar_ranges(plane, c.p, c.m, c.g.sonar_side, c.g.max_range);
    if (cell.verdict == KernelVerdict::undecided) {
      ++undecided;
      continue;
    }
    const bool agree = cell.verdict == KernelVerdict::none ? portable.is_empty()
                                                           : same_bounds(portable, cell.lo, cell.hi);
    lost += cell.verdict == KernelVerdict::none && !portable.is_empty();
    if (!agree && failures++ < 5)
      ADD_FAILURE() << "case " << n << ": kernel " << (cell.verdict == KernelVerdict::none ? "none" : "ranges") << " ["
                    << cell.lo << ", " << cell.hi << "], portable [" << portable.lo() << ", " << portable.hi() << "]";
    if (!portable.is_empty()) {
      ++kept;
    } else {
      const Vec3I rough = plane.rough_body_offset(c.p, c.m);
      const bool passes = plane.may_hold(rough, SonarSide::starboard) || plane.may_hold(rough, SonarSide::port);
      ++(passes ? contractor_rejected : rough_rejected);
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_EQ(lost, 0);
  std::printf("waterfall kernel: %d cells kept, %d rejected by the rough test, %d by the contractor or range, "
              "%d refused, %d undecided\n", kept, rough_rejected, contractor_rejected, refused, undecided);
  // Every outcome must be well represented for the comparison to mean something.
  EXPECT_GT(kept, 30000);
  EXPECT_GT(rough_rejected, 30000);
  EXPECT_GT(contractor_rejected, 3000);
  EXPECT_GT(refused, 1000);  // angle boxes wider than 0.05 rad
  EXPECT_LT(undecided, 10);
}

// The portable cell of every (step, mine) of a solved mission, with the plane
// compute_waterfall builds there: the near-pair filter is checked too.
Waterfall portable_waterfall(const Mission& m, const TubeDomains& d) {
  const FrameMarginValues margins = frame_margins_over(m, d);
  const SensorBoxes boxes(m, m.model, margins.view(m));
  Waterfall w;
  w.steps = d.size();
  w.mines = d.mines.size();
  for (std::size_t k = 0; k < d.size(); ++k) {
    SonarPlane plane;
    plane.attitude = make_attitude(boxes.roll(k), boxes.pitch(k), boxes.heading(k));
    plane.altitude = boxes.altitude(k);
    plane.along_tolerance = m.model.along_track_tolerance;
    plane.depth_band = m.model.mine_depth_band;
    plane.frame_slack = sonar_frame_slack(boxes.frame_scale(k), m.model.sonar_max_range);
    for (std::size_t i = 0; i < d.mines.size(); ++i) {
      const Interval r = sonar_ranges(plane, d.position(k), d.mines[i], m.model.sonar_side, m.model.sonar_max_range);
      if (!r.is_empty()) w.add(k, i, r.lo(), r.hi());
    }
  }
  return w;
}

void expect_same(const Waterfall& kernel, const Waterfall& portable) {
  ASSERT_EQ(kernel.step, portable.step);
  ASSERT_EQ(kernel.mine, portable.mine);
  EXPECT_EQ(kernel.lower, portable.lower);
  EXPECT_EQ(kernel.upper, portable.upper);
}

TEST(WaterfallKernel, MissionWaterfallsAreThePortableOnes) {
  for (const std::uint64_t seed : {2u, 3u}) {
    SCOPED_TRACE(seed);
    SimulationOptions o;
    o.seed = seed;
    o.duration = 1500.0;
    o.missed = 0.3;
    Mission m = simulate_mission(o);
    if (seed == 3) {  // per-sample margins over the tube, the scale's moving the sonar's reach
      m.heading_frame_margin = 1e-3;
      m.frame_scale_margin = 1e-3;
    }
    const MissionSolution s = solve_mission(m);
    ASSERT_TRUE(s.report.consistent);
    const Waterfall kernel = compute_waterfall(m, m.model, s.domains);
    ASSERT_GT(kernel.cells(), 500u);
    expect_same(kernel, portable_waterfall(m, s.domains));
    // What the kernel does not take goes the portable way: an unbounded mine box, and
    // angle boxes too wide for the narrow sin/cos form (every step).
    TubeDomains unbounded = s.domains;
    unbounded.mines[1][0] = Interval(unbounded.mines[1][0].lo(), kInf);
    expect_same(compute_waterfall(m, m.model, unbounded), portable_waterfall(m, unbounded));
    Mission wide = m;
    wide.model.heading = 0.06;
    expect_same(compute_waterfall(wide, wide.model, s.domains), portable_waterfall(wide, s.domains));
    // Boxes of 20 cm around the truth: cells as far as the swath reaches, where the
    // filter on the boxes' distance decides which steps are computed (seed 3: with the
    // zone's margins, then each step's own).
    TubeDomains tight = s.domains;
    for (std::size_t k = 0; k < tight.size(); ++k) {
      tight.px[k] = Interval::around(m.truth_x[k], 0.1);
      tight.py[k] = Interval::around(m.truth_y[k], 0.1);
      tight.pz[k] = Interval::around(m.truth_z[k], 0.1);
    }
    for (std::size_t i = 0; i < tight.mines.size(); ++i)
      for (int c = 0; c < 3; ++c) tight.mines[i][c] = Interval::around(m.truth_mines[3 * i + static_cast<std::size_t>(c)], 0.1);
    const Waterfall tight_kernel = compute_waterfall(m, m.model, tight);
    double farthest = 0.0;
    for (std::size_t c = 0; c < tight_kernel.cells(); ++c) farthest = std::max(farthest, tight_kernel.lower[c]);
    EXPECT_GT(farthest, 0.85 * m.model.sonar_max_range);
    expect_same(tight_kernel, portable_waterfall(m, tight));
    // And a swath that ends just beyond where a mine passes (60.6 m off the track lines):
    // its cells within a metre of the end.
    Mission short_swath = m;
    short_swath.model.sonar_max_range = 61.0;
    const Waterfall edge = compute_waterfall(short_swath, short_swath.model, tight);
    std::size_t near_the_end = 0;
    for (std::size_t c = 0; c < edge.cells(); ++c) near_the_end += edge.lower[c] > 60.0;
    EXPECT_GT(near_the_end, 10u);
    expect_same(edge, portable_waterfall(short_swath, tight));
    // Each mine alone, so that no other mine's reach marks its steps.
    for (std::size_t i = 0; i < tight.mines.size(); ++i) {
      TubeDomains alone = tight;
      alone.mines = {tight.mines[i]};
      expect_same(compute_waterfall(short_swath, short_swath.model, alone), portable_waterfall(short_swath, alone));
    }
  }
}

TEST(WaterfallKernel, RestoresTheRoundingMode) {
  Cases cases(5);
  const KernelCase c = cases.next();
  KernelStep step;
  ASSERT_TRUE(prepare_kernel_step(c.p, c.roll, c.pitch, c.heading, c.altitude, c.slack, step));
  const KernelMine mine{{c.m[0].lo(), c.m[1].lo(), c.m[2].lo()}, {c.m[0].hi(), c.m[1].hi(), c.m[2].hi()}};
  const KernelPair pair{0, 0};
  KernelCell cell{};
  ASSERT_EQ(std::fegetround(), FE_TONEAREST);
  kernel_sonar_ranges(c.g, {&step, 1}, {&mine, 1}, {&pair, 1}, {&cell, 1});
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

}  // namespace
}  // namespace gesmi
