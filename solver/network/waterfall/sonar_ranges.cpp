#include "solver/network/waterfall/sonar_ranges.h"

namespace gesmi {
namespace {

// Range interval for one side, or empty.
Interval side_ranges(SonarPlane plane, const Vec3I& position, const Vec3I& mine, Interval range, SonarSide side) {
  plane.side = side;
  Vec3I q = position, m = mine;
  if (!plane.contract(q, m, range)) return Interval::empty();
  return range;
}

bool looks_to(SonarSide sonar_side, SonarSide side) { return sonar_side == SonarSide::both || sonar_side == side; }

}  // namespace

Interval sonar_ranges(const SonarPlane& plane, const Vec3I& p, const Vec3I& m, SonarSide sonar_side, double max_range) {
  const Vec3I rough = plane.rough_body_offset(p, m);
  bool any_side = false;
  for (const SonarSide side : {SonarSide::starboard, SonarSide::port})
    any_side = any_side || (looks_to(sonar_side, side) && plane.may_hold(rough, side));
  if (!any_side) return Interval::empty();  // out of the sonar plane, or on a side the sonar does not see
  const Interval swath(0.0, max_range);
  const Interval distance = plane.possible_ranges(p, m);
  if (!distance.intersects(swath)) return Interval::empty();
  const Interval reach = intersect(distance, swath);
  Interval ranges = Interval::empty();
  for (const SonarSide side : {SonarSide::starboard, SonarSide::port})
    if (looks_to(sonar_side, side) && plane.may_hold(rough, side))
      ranges = hull(ranges, side_ranges(plane, p, m, reach, side));
  return ranges;
}

}  // namespace gesmi
