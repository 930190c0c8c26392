#pragma once
// The reconstructed waterfall picture (seed 001, Fig. 8): one column per mine,
// time downwards, slant range across; feasible zones shaded, detections as dots,
// and optional time windows to look at again (missed-mine candidates).

#include <string>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/waterfall/waterfall.h"

namespace gesmi::io {

struct WaterfallMark {
  double time, range;
  int mine;
};
struct WaterfallWindow {
  int mine;
  double t_start, t_end, range_lo, range_hi;
};

struct WaterfallPicture {
  const Waterfall* waterfall = nullptr;
  std::vector<double> time;  // the step times
  std::vector<WaterfallMark> marks;
  std::vector<WaterfallWindow> windows;  // highlighted
  double max_range = 75.0;
  std::string title;
};

void write_waterfall_png(const WaterfallPicture& picture, const std::string& path);

}  // namespace gesmi::io
