#include "io/plot/tube_runs.h"

#include <algorithm>
#include <optional>

namespace gesmi::io {

std::vector<PixelBox> tube_runs(const DataFrame& f, const TubeDomains& d) {
  std::vector<PixelBox> runs;
  std::optional<PixelBox> run;
  double narrowest = 0.0, lowest = 0.0;  // the smallest width and height of the run's boxes
  const auto flush = [&] {
    if (run) runs.push_back(*run);
    run.reset();
  };
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (!d.px[k].is_bounded() || !d.py[k].is_bounded()) {
      flush();
      continue;
    }
    const PixelBox b{f.px(d.py[k].lo()), f.px(d.py[k].hi()), f.py(d.px[k].hi()), f.py(d.px[k].lo())};
    if (run) {
      const PixelBox h{std::min(run->x0, b.x0), std::max(run->x1, b.x1), std::min(run->y0, b.y0), std::max(run->y1, b.y1)};
      const double w = std::min(narrowest, b.width()), t = std::min(lowest, b.height());
      if (h.width() <= w + 1.0 && h.height() <= t + 1.0) {
        *run = h;
        narrowest = w;
        lowest = t;
        continue;
      }
      flush();
    }
    run = b;
    narrowest = b.width();
    lowest = b.height();
  }
  flush();
  return runs;
}

}  // namespace gesmi::io
