// The envelope picture's runs (io/plot/tube_runs.h): every box of the tube lies in
// the rectangle of its run, every rectangle is within a pixel of each of its boxes,
// and a densely sampled track takes several times fewer rectangles than samples.

#include "io/plot/tube_runs.h"

#include <gtest/gtest.h>

#include <cmath>

namespace gesmi::io {
namespace {

// A tube along a spiral, 0.2 m per sample, boxes 8 to 12 m wide, a gap of unbounded
// boxes in the middle.
TubeDomains spiral(std::size_t n) {
  TubeDomains d;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = 0.2 * static_cast<double>(k), angle = s / 150.0, radius = 50.0 + s / 40.0;
    const double half = 4.0 + 2.0 * std::sin(s / 30.0);
    const bool gap = k > n / 2 && k < n / 2 + 50;
    d.px.push_back(gap ? Interval::entire() : Interval::around(radius * std::cos(angle), half));
    d.py.push_back(gap ? Interval::entire() : Interval::around(radius * std::sin(angle), half * 0.7));
  }
  return d;
}

TEST(TubeRuns, CoverEveryBoxAndAddAtMostAPixel) {
  const TubeDomains d = spiral(20000);
  const DataFrame f{-200.0, 200.0, -200.0, 200.0, 80, 30, 1000, 1000, false};
  const std::vector<PixelBox> runs = tube_runs(f, d);
  std::size_t r = 0, boxes = 0;
  bool in_gap = false;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (!d.px[k].is_bounded()) {
      in_gap = true;
      continue;
    }
    const PixelBox b{f.px(d.py[k].lo()), f.px(d.py[k].hi()), f.py(d.px[k].hi()), f.py(d.px[k].lo())};
    // The run holding box k: the current one, or the next (runs are in track order).
    const auto holds = [&](const PixelBox& run) {
      return run.x0 <= b.x0 && b.x1 <= run.x1 && run.y0 <= b.y0 && b.y1 <= run.y1;
    };
    if (in_gap || !holds(runs[r])) ++r;
    in_gap = false;
    ASSERT_LT(r, runs.size()) << "box " << k << " is in no run";
    ASSERT_TRUE(holds(runs[r])) << "box " << k << " outside its run";
    EXPECT_LE(runs[r].width(), b.width() + 1.0 + 1e-9) << k;
    EXPECT_LE(runs[r].height(), b.height() + 1.0 + 1e-9) << k;
    ++boxes;
  }
  EXPECT_EQ(r + 1, runs.size());
  // 0.2 m per sample at 0.4 m per pixel: a box moves half a pixel, so a run holds at
  // least two, and more where the track turns along an axis.
  EXPECT_LT(runs.size() * 3, boxes) << runs.size() << " rectangles for " << boxes << " boxes";
}

}  // namespace
}  // namespace gesmi::io
