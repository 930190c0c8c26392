#include "solver/network/waterfall.h"

#include <limits>

#include "solver/network/sonar_plane.h"
#include "solver/network/sensor_boxes.h"

namespace gesmi {
namespace {

// Range interval for one side, or empty.
Interval feasible_ranges(SonarPlane plane, const Vec3I& position, const Vec3I& mine, Interval range, SonarSide side) {
  plane.side = side;
  Vec3I q = position, m = mine;
  if (!plane.contract(q, m, range)) return Interval::empty();
  return range;
}

}  // namespace

Waterfall compute_waterfall(const Mission& mission, const SensorModel& model, const TubeDomains& domains) {
  // The tube holds the truth, so the frame's margins over it hold too.
  const std::vector<double> margins = heading_margins_over(mission, domains);
  const SensorBoxes boxes(mission, model, HeadingFrame{mission.heading_frame_margin, margins});
  Waterfall w;
  w.steps = domains.size();
  w.mines = domains.mines.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  w.lower.assign(w.steps * w.mines, nan);
  w.upper.assign(w.steps * w.mines, nan);
  const Interval swath(0.0, model.sonar_max_range);
  for (std::size_t k = 0; k < w.steps; ++k) {
    const Vec3I p = domains.position(k);
    SonarPlane plane;
    plane.attitude = make_attitude(boxes.roll(k), boxes.pitch(k), boxes.heading(k));
    plane.altitude = boxes.altitude(k);
    plane.along_tolerance = model.along_track_tolerance;
    plane.depth_band = model.mine_depth_band;
    for (std::size_t i = 0; i < w.mines; ++i) {
      const Vec3I& m = domains.mines[i];
      // Cheap rejection: the boxes are farther apart than the sonar reaches.
      const Interval distance = box_distance(p, m);
      if (!distance.intersects(swath)) continue;
      const Interval reach = intersect(distance, swath);
      Interval ranges = Interval::empty();
      for (const SonarSide side : {SonarSide::starboard, SonarSide::port}) {
        if (model.sonar_side != SonarSide::both && model.sonar_side != side) continue;
        ranges = hull(ranges, feasible_ranges(plane, p, m, reach, side));
      }
      if (ranges.is_empty()) continue;
      w.lower[k * w.mines + i] = ranges.lo();
      w.upper[k * w.mines + i] = ranges.hi();
    }
  }
  return w;
}

}  // namespace gesmi
