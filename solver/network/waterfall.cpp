#include "solver/network/waterfall.h"

#include <algorithm>
#include <limits>

#include "solver/mission/frame_scale.h"
#include "solver/network/sonar_plane.h"
#include "solver/network/sensor_boxes.h"
#include "solver/network/step_chunks.h"

namespace gesmi {
namespace {

// Range interval for one side, or empty.
Interval side_ranges(SonarPlane plane, const Vec3I& position, const Vec3I& mine, Interval range, SonarSide side) {
  plane.side = side;
  Vec3I q = position, m = mine;
  if (!plane.contract(q, m, range)) return Interval::empty();
  return range;
}

// The ranges at which a mine can appear from a position box, on the sonar's sides, or
// empty: the interval test where the cheap one could not decide, then the contractor on
// each side whose prior the rough body offset meets.
Interval feasible_ranges(const SonarPlane& plane, const Vec3I& p, const Vec3I& m, SonarSide sonar_side,
                         const Interval& swath) {
  const Vec3I rough = plane.rough_body_offset(p, m);
  if (!plane.may_hold(rough, SonarSide::starboard) && !plane.may_hold(rough, SonarSide::port))
    return Interval::empty();  // out of the sonar plane at this step
  const Interval distance = plane.possible_ranges(p, m);
  if (!distance.intersects(swath)) return Interval::empty();
  const Interval reach = intersect(distance, swath);
  Interval ranges = Interval::empty();
  for (const SonarSide side : {SonarSide::starboard, SonarSide::port}) {
    if (sonar_side != SonarSide::both && sonar_side != side) continue;
    if (!plane.may_hold(rough, side)) continue;  // out of the plane, or on the other side
    ranges = hull(ranges, side_ranges(plane, p, m, reach, side));
  }
  return ranges;
}

bool same(const Interval& a, const Interval& b) { return a.lo() == b.lo() && a.hi() == b.hi(); }

// The step's position boxes and its neighbours' are those of `before`.
bool same_positions(const TubeDomains& d, const TubeDomains& before, std::size_t k) {
  for (std::size_t j = k == 0 ? 0 : k - 1; j <= std::min(k + 1, d.size() - 1); ++j)
    if (!same(d.px[j], before.px[j]) || !same(d.py[j], before.py[j]) || !same(d.pz[j], before.pz[j])) return false;
  return true;
}

}  // namespace

void Waterfall::append(const Waterfall& later) {
  step.insert(step.end(), later.step.begin(), later.step.end());
  mine.insert(mine.end(), later.mine.begin(), later.mine.end());
  lower.insert(lower.end(), later.lower.begin(), later.lower.end());
  upper.insert(upper.end(), later.upper.begin(), later.upper.end());
}

std::size_t Waterfall::first_cell_at(std::size_t k) const {
  const auto it = std::lower_bound(step.begin(), step.end(), static_cast<std::int64_t>(k),
                                   [](std::int32_t s, std::int64_t wanted) { return s < wanted; });
  return static_cast<std::size_t>(it - step.begin());
}

std::optional<std::size_t> Waterfall::cell(std::size_t k, std::size_t i) const {
  for (std::size_t c = first_cell_at(k); c < cells() && static_cast<std::size_t>(step[c]) == k; ++c)
    if (static_cast<std::size_t>(mine[c]) == i) return c;
  return std::nullopt;
}

double Waterfall::lo(std::size_t k, std::size_t i) const {
  const auto c = cell(k, i);
  return c ? lower[*c] : std::numeric_limits<double>::quiet_NaN();
}

double Waterfall::hi(std::size_t k, std::size_t i) const {
  const auto c = cell(k, i);
  return c ? upper[*c] : std::numeric_limits<double>::quiet_NaN();
}

Waterfall compute_waterfall(const Mission& mission, const SensorModel& model, const TubeDomains& domains,
                            const WaterfallBefore* before, std::optional<double> max_speed,
                            const std::function<void(double)>& on_progress) {
  // The tube holds the truth, so the frame's margins over it hold too.
  const FrameMarginValues margins = max_speed ? frame_margins_over(mission, domains, *max_speed)
                                              : frame_margins_over(mission, domains);
  const SensorBoxes boxes(mission, model, margins.view(mission));
  const std::size_t steps = domains.size(), mines = domains.mines.size();
  const Interval swath(0.0, model.sonar_max_range);
  // The mines whose box has not changed since `before`, if any.
  std::vector<char> mine_kept(mines, 0);
  if (before && before->waterfall.steps == steps && before->waterfall.mines == mines &&
      before->domains.size() == steps && before->domains.mines.size() == mines)
    for (std::size_t i = 0; i < mines; ++i)
      mine_kept[i] = same(domains.mines[i][0], before->domains.mines[i][0]) &&
                     same(domains.mines[i][1], before->domains.mines[i][1]) &&
                     same(domains.mines[i][2], before->domains.mines[i][2]);
  const bool any_kept = std::find(mine_kept.begin(), mine_kept.end(), 1) != mine_kept.end();
  // Steps [first, last) of each chunk into their own part, joined in step order.
  const std::size_t chunks = step_chunk_count(steps);
  std::vector<Waterfall> parts(chunks);
  const auto rows = [&](std::size_t chunk, std::size_t first, std::size_t last) {
    Waterfall& part = parts[chunk];
    std::vector<std::size_t> near;
    // This step's cells by mine (empty: none), appended in mine order.
    std::vector<Interval> row(mines);
    std::size_t earlier = any_kept ? before->waterfall.first_cell_at(first) : 0;
    for (std::size_t k = first; k < last; ++k) {
      // The first chunk runs on the calling thread: it reports for all (they keep pace).
      if (chunk == 0 && on_progress && (k - first) % 8192 == 0) on_progress(static_cast<double>(k - first) / static_cast<double>(last - first));
      const Vec3I p = domains.position(k);
      const bool kept_step = any_kept && same_positions(domains, before->domains, k);
      std::fill(row.begin(), row.end(), Interval::empty());
      near.clear();
      const double slack = sonar_frame_slack(boxes.frame_scale(k), model.sonar_max_range);
      // The slack moves each axis of the offset, so the distance by at most sqrt(3) < 2 times it.
      const double reach = add_up(model.sonar_max_range, 2.0 * slack);
      for (std::size_t i = 0; i < mines; ++i)
        if (!(kept_step && mine_kept[i]) && !boxes_beyond(p, domains.mines[i], reach)) near.push_back(i);
      if (kept_step) {
        const Waterfall& w = before->waterfall;
        while (earlier < w.cells() && static_cast<std::size_t>(w.step[earlier]) < k) ++earlier;
        for (std::size_t c = earlier; c < w.cells() && static_cast<std::size_t>(w.step[c]) == k; ++c)
          if (mine_kept[static_cast<std::size_t>(w.mine[c])])
            row[static_cast<std::size_t>(w.mine[c])] = Interval(w.lower[c], w.upper[c]);
      }
      if (!near.empty()) {  // no attitude to build where no mine is in reach
        SonarPlane plane;
        plane.attitude = make_attitude(boxes.roll(k), boxes.pitch(k), boxes.heading(k));
        plane.altitude = boxes.altitude(k);
        plane.along_tolerance = model.along_track_tolerance;
        plane.depth_band = model.mine_depth_band;
        plane.frame_slack = slack;
        for (const std::size_t i : near) row[i] = feasible_ranges(plane, p, domains.mines[i], model.sonar_side, swath);
      }
      for (std::size_t i = 0; i < mines; ++i)
        if (!row[i].is_empty()) part.add(k, i, row[i].lo(), row[i].hi());
    }
  };
  for_step_chunks(steps, chunks, rows);
  Waterfall w;
  w.steps = steps;
  w.mines = mines;
  for (const Waterfall& part : parts) w.append(part);
  return w;
}

}  // namespace gesmi
