#pragma once
// The tube of a picture as rectangles: the hulls of runs of consecutive boxes, a run
// growing while its hull stays within a pixel of every box in it (in width and in
// height). The rectangles cover the tube and add at most a pixel to any of its boxes,
// with one rectangle per pixel of track rather than per sample.

#include <vector>

#include "io/plot/canvas.h"
#include "solver/network/tube_domains.h"

namespace gesmi::io {

/// A rectangle in pixels (y down).
struct PixelBox {
  double x0, x1, y0, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

/// The runs of the tube's north/east boxes in the frame (east along x, north along y);
/// unbounded boxes end a run and are left out.
std::vector<PixelBox> tube_runs(const DataFrame& frame, const TubeDomains& tube);

}  // namespace gesmi::io
