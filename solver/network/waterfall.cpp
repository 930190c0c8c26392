#include "solver/network/waterfall.h"

#include <algorithm>
#include <limits>

#include "solver/network/sonar_plane.h"
#include "solver/network/sensor_boxes.h"
#include "solver/network/step_chunks.h"

namespace gesmi {
namespace {

// Range interval for one side, or empty.
Interval feasible_ranges(SonarPlane plane, const Vec3I& position, const Vec3I& mine, Interval range, SonarSide side) {
  plane.side = side;
  Vec3I q = position, m = mine;
  if (!plane.contract(q, m, range)) return Interval::empty();
  return range;
}

bool same(const Interval& a, const Interval& b) { return a.lo() == b.lo() && a.hi() == b.hi(); }

// The step's position boxes and its neighbours' are those of `before`.
bool same_positions(const TubeDomains& d, const TubeDomains& before, std::size_t k) {
  for (std::size_t j = k == 0 ? 0 : k - 1; j <= std::min(k + 1, d.size() - 1); ++j)
    if (!same(d.px[j], before.px[j]) || !same(d.py[j], before.py[j]) || !same(d.pz[j], before.pz[j])) return false;
  return true;
}

}  // namespace

Waterfall compute_waterfall(const Mission& mission, const SensorModel& model, const TubeDomains& domains,
                            const WaterfallBefore* before, std::optional<double> max_speed) {
  // The tube holds the truth, so the frame's margins over it hold too.
  const std::vector<double> margins = max_speed ? heading_margins_over(mission, domains, *max_speed)
                                                : heading_margins_over(mission, domains);
  const SensorBoxes boxes(mission, model, HeadingFrame{mission.heading_frame_margin, margins});
  Waterfall w;
  w.steps = domains.size();
  w.mines = domains.mines.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  w.lower.assign(w.steps * w.mines, nan);
  w.upper.assign(w.steps * w.mines, nan);
  const Interval swath(0.0, model.sonar_max_range);
  // The mines whose box has not changed since `before`, if any.
  std::vector<char> mine_kept(w.mines, 0);
  if (before && before->waterfall.steps == w.steps && before->waterfall.mines == w.mines &&
      before->domains.size() == w.steps && before->domains.mines.size() == w.mines)
    for (std::size_t i = 0; i < w.mines; ++i)
      mine_kept[i] = same(domains.mines[i][0], before->domains.mines[i][0]) &&
                     same(domains.mines[i][1], before->domains.mines[i][1]) &&
                     same(domains.mines[i][2], before->domains.mines[i][2]);
  const bool any_kept = std::find(mine_kept.begin(), mine_kept.end(), 1) != mine_kept.end();
  // Steps [first, last): each chunk writes its own rows.
  const auto rows = [&](std::size_t, std::size_t first, std::size_t last) {
    std::vector<std::size_t> near;
    for (std::size_t k = first; k < last; ++k) {
      const Vec3I p = domains.position(k);
      const bool kept_step = any_kept && same_positions(domains, before->domains, k);
      near.clear();
      for (std::size_t i = 0; i < w.mines; ++i) {
        if (kept_step && mine_kept[i]) {
          w.lower[k * w.mines + i] = before->waterfall.lower[k * w.mines + i];
          w.upper[k * w.mines + i] = before->waterfall.upper[k * w.mines + i];
        } else if (!boxes_beyond(p, domains.mines[i], model.sonar_max_range)) {
          near.push_back(i);
        }
      }
      if (near.empty()) continue;  // no attitude to build where no mine is in reach
      SonarPlane plane;
      plane.attitude = make_attitude(boxes.roll(k), boxes.pitch(k), boxes.heading(k));
      plane.altitude = boxes.altitude(k);
      plane.along_tolerance = model.along_track_tolerance;
      plane.depth_band = model.mine_depth_band;
      for (const std::size_t i : near) {
        const Vec3I& m = domains.mines[i];
        const Vec3I rough = plane.rough_body_offset(p, m);
        if (!plane.may_hold(rough, SonarSide::starboard) && !plane.may_hold(rough, SonarSide::port)) continue;
        // The interval test where the cheap one could not decide.
        const Interval distance = box_distance(p, m);
        if (!distance.intersects(swath)) continue;
        const Interval reach = intersect(distance, swath);
        Interval ranges = Interval::empty();
        for (const SonarSide side : {SonarSide::starboard, SonarSide::port}) {
          if (model.sonar_side != SonarSide::both && model.sonar_side != side) continue;
          if (!plane.may_hold(rough, side)) continue;  // out of the plane, or on the other side
          ranges = hull(ranges, feasible_ranges(plane, p, m, reach, side));
        }
        if (ranges.is_empty()) continue;
        w.lower[k * w.mines + i] = ranges.lo();
        w.upper[k * w.mines + i] = ranges.hi();
      }
    }
  };
  for_step_chunks(w.steps, step_chunk_count(w.steps), rows);
  return w;
}

}  // namespace gesmi
