#include "io/plot/plot_envelope.h"

#include <algorithm>
#include <cmath>

#include "io/plot/canvas.h"
#include "io/plot/tube_runs.h"

namespace gesmi::io {
namespace {

struct Bounds {
  double east_lo = 1e300, east_hi = -1e300, north_lo = 1e300, north_hi = -1e300;
  void add(const Interval& north, const Interval& east) {
    if (!north.is_bounded() || !east.is_bounded()) return;
    east_lo = std::min(east_lo, east.lo());
    east_hi = std::max(east_hi, east.hi());
    north_lo = std::min(north_lo, north.lo());
    north_hi = std::max(north_hi, north.hi());
  }
  bool valid() const { return east_lo <= east_hi && north_lo <= north_hi; }
};

}  // namespace

void write_envelope_png(const EnvelopePicture& pic, const std::string& path) {
  const TubeDomains& d = *pic.domains;
  Bounds b;
  for (std::size_t k = 0; k < d.size(); ++k) b.add(d.px[k], d.py[k]);
  for (const Vec3I& m : d.mines) b.add(m[0], m[1]);
  if (!b.valid()) b = Bounds{-1.0, 1.0, -1.0, 1.0};
  // Same scale on both axes, a margin of 5 %.
  const double span = std::max(b.east_hi - b.east_lo, b.north_hi - b.north_lo) * 1.05 + 1.0;
  const double ce = 0.5 * (b.east_lo + b.east_hi), cn = 0.5 * (b.north_lo + b.north_hi);
  const int size = 1000;
  Canvas canvas(size + 110, size + 110);
  const DataFrame f{ce - span / 2, ce + span / 2, cn - span / 2, cn + span / 2, 80, 30, size, size - 20, false};
  const Rgb tube{0.72, 0.72, 0.72}, mine{0.0, 0.0, 0.0}, truth{0.1, 0.3, 0.9}, fix{0.85, 0.1, 0.1};

  // The tube: a rectangle per run of boxes (tube_runs.h), not per sample.
  for (const PixelBox& r : tube_runs(f, d)) canvas.fill_rect(r.x0, r.y0, r.width(), r.height(), tube);
  if (pic.mission && pic.mission->has_truth()) {
    const Mission& m = *pic.mission;
    const std::size_t step = std::max<std::size_t>(1, m.size() / 5000);
    for (std::size_t k = step; k < m.size(); k += step)
      canvas.line(f.px(m.truth_y[k - step]), f.py(m.truth_x[k - step]), f.px(m.truth_y[k]), f.py(m.truth_x[k]), truth, 1.0);
  }
  for (std::size_t i = 0; i < d.mines.size(); ++i) {
    const Vec3I& m = d.mines[i];
    if (!m[0].is_bounded() || !m[1].is_bounded()) continue;
    const double x0 = f.px(m[1].lo()), x1 = f.px(m[1].hi()), y0 = f.py(m[0].hi()), y1 = f.py(m[0].lo());
    canvas.stroke_rect(x0, y0, x1 - x0, y1 - y0, mine, 2.0);
    canvas.text(x1 + 4, y0 + 10, "m" + std::to_string(i), 12, mine);
  }
  if (pic.mission) {
    const auto& tm = pic.mission->truth_mines;
    for (std::size_t i = 0; i + 2 < tm.size(); i += 3) canvas.dot(f.px(tm[i + 1]), f.py(tm[i]), 3.0, truth);
  }
  for (const Vec3I& g : pic.fix_boxes) {
    if (!g[0].is_bounded() || !g[1].is_bounded()) continue;
    canvas.dot(f.px(g[1].mid()), f.py(g[0].mid()), 5.0, fix);
  }
  canvas.axes(f, "east (m)", "north (m)");
  canvas.text(f.left, 20, pic.title, 14, Rgb{0, 0, 0});
  canvas.text(f.left + f.width - 420, 20, "grey: envelope   black: mine boxes   blue: truth   red: GPS", 11,
              Rgb{0.3, 0.3, 0.3});
  canvas.save_png(path);
}

}  // namespace gesmi::io
