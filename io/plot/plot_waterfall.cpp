#include "io/plot/plot_waterfall.h"

#include <algorithm>
#include <cmath>

#include "io/plot/canvas.h"

namespace gesmi::io {

void write_waterfall_png(const WaterfallPicture& pic, const std::string& path) {
  const Waterfall& w = *pic.waterfall;
  const std::size_t columns = std::max<std::size_t>(w.mines, 1);
  const int column_width = 170, gap = 30, height = 1100, top = 50, left = 80;
  Canvas canvas(left + static_cast<int>(columns) * (column_width + gap) + 20, top + height + 60);
  const double t0 = pic.time.empty() ? 0.0 : pic.time.front();
  const double t1 = pic.time.empty() ? 1.0 : std::max(pic.time.back(), t0 + 1e-9);
  const Rgb zone{0.35, 0.35, 0.35}, dot{0, 0, 0}, window{0.9, 0.45, 0.0};
  for (std::size_t i = 0; i < w.mines; ++i) {
    const DataFrame f{0.0, pic.max_range, t0, t1, static_cast<double>(left + static_cast<int>(i) * (column_width + gap)),
                      static_cast<double>(top), static_cast<double>(column_width), static_cast<double>(height), true};
    // One pixel row covers several steps: shade the hull of their feasible ranges.
    const auto rows = static_cast<std::size_t>(height);
    std::size_t c = 0;  // the next cell, in step order
    for (std::size_t row = 0; row < rows && c < w.cells(); ++row) {
      const double row_end = t0 + (t1 - t0) * static_cast<double>(row + 1) / static_cast<double>(rows);
      double lo = 1e300, hi = -1e300;
      for (; c < w.cells() && pic.time[static_cast<std::size_t>(w.step[c])] <= row_end; ++c) {
        if (static_cast<std::size_t>(w.mine[c]) != i) continue;
        lo = std::min(lo, w.lower[c]);
        hi = std::max(hi, w.upper[c]);
      }
      if (lo > hi) continue;
      const double x0 = f.px(std::max(lo, 0.0)), x1 = f.px(std::min(hi, pic.max_range));
      canvas.fill_rect(x0, f.top + static_cast<double>(row), std::max(x1 - x0, 1.0), 1.0, zone);
    }
    for (const WaterfallWindow& ww : pic.windows) {
      if (ww.mine != static_cast<int>(i)) continue;
      const double y0 = f.py(ww.t_start), y1 = f.py(ww.t_end);
      canvas.stroke_rect(f.px(ww.range_lo) - 2, y0 - 2, f.px(ww.range_hi) - f.px(ww.range_lo) + 4, y1 - y0 + 4, window, 1.5);
    }
    for (const WaterfallMark& m : pic.marks)
      if (m.mine == static_cast<int>(i)) canvas.dot(f.px(m.range), f.py(m.time), 4.0, dot);
    canvas.axes(f, "range (m)", i == 0 ? "time (s)" : "");
    canvas.text(f.left + f.width / 2, top - 10, "mine " + std::to_string(i), 13, Rgb{0, 0, 0}, true);
  }
  canvas.text(left, 20, pic.title, 14, Rgb{0, 0, 0});
  canvas.save_png(path);
}

}  // namespace gesmi::io
