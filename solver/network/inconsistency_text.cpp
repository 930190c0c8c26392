#include "solver/network/inconsistency_text.h"

#include "solver/network/detail/text.h"

namespace gesmi {
namespace {

using detail::fixed;
using detail::format_interval;
using detail::format_time;

const char* const kAxisNames[] = {"north", "east", "down"};

const Detection* detection_of(const MissionNetwork& net, std::size_t mark) {
  for (const Detection& d : net.detections)
    if (d.mark == mark) return &d;
  return nullptr;
}

const Anchor* anchor_of(const MissionNetwork& net, std::size_t row) {
  for (const Anchor& a : net.anchors)
    if (a.fix.source_index == row) return &a;
  return nullptr;
}

std::string detection_head(const Detection& det, const std::string& mine) {
  return "detection " + std::to_string(det.mark) + " at t = " + format_time(det.time) + " (mine " + mine + ", range " +
         fixed(det.measured_range, 2) + " m, " + (det.plane.side == SonarSide::starboard ? "starboard" : "port") + ")";
}

// A constraint as the evolution message names it, with its time.
std::string named(const MissionNetwork& net, const ConstraintRef& c) {
  if (c.kind == ConstraintRef::Kind::gps_fix) {
    const Anchor* a = anchor_of(net, c.row);
    return "GPS fix " + std::to_string(c.row) + (a ? " at t = " + format_time(a->fix.time) : std::string());
  }
  const Detection* d = detection_of(net, c.row);
  return d ? detection_head(*d, d->mine >= 0 ? std::to_string(d->mine) : "?") : "mark " + std::to_string(c.row);
}

std::string evolution(const Inconsistency& inc, const MissionNetwork& net) {
  std::string what = "dead reckoning cannot join the " + std::string(kAxisNames[inc.axis]) +
                     " positions allowed before and after t = " + format_time(inc.time);
  if (inc.before || inc.after)
    what += ": between " + (inc.before ? named(net, *inc.before) : std::string("the start")) + " and " +
            (inc.after ? named(net, *inc.after) : std::string("the end"));
  if (inc.axis == 2) what += "; the barometer bounds the depth there";
  return what + " (one of them, or the DVL/gyrocompass bounds, is wrong)";
}

std::string fix(const Inconsistency& inc) {
  return "GPS fix " + std::to_string(inc.source->row) + " at t = " + format_time(inc.time) + " (north " +
         format_interval(inc.fix_box[0]) + ", east " + format_interval(inc.fix_box[1]) + ") is outside the tube there (north " +
         format_interval(inc.tube[0]) + ", east " + format_interval(inc.tube[1]) + ")";
}

std::string detection(const Inconsistency& inc, const MissionNetwork& net) {
  const Detection* det = detection_of(net, inc.source->row);
  if (!det) return "mark " + std::to_string(inc.source->row) + " at t = " + format_time(inc.time) + " cannot be explained";
  if (inc.mine < 0) {
    std::string distances;
    for (const auto& [mine, distance] : inc.candidate_distances)
      distances += (distances.empty() ? "" : ", ") + std::string("mine ") + std::to_string(mine) + " " + format_interval(distance);
    return detection_head(*det, "?") + ": no mine can explain it (distances from the tube, m: " + distances + ")";
  }
  const std::string head =
      detection_head(*det, det->mine >= 0 ? std::to_string(det->mine) : "? -> " + std::to_string(inc.mine));
  const Interval distance = box_distance(inc.tube, inc.mine_box);
  if (!distance.intersects(det->range))
    return head + ": range " + format_interval(det->range) + " m cannot be reached, the distance from the tube to mine " +
           std::to_string(inc.mine) + " is within " + format_interval(distance) + " m";
  return head + ": mine " + std::to_string(inc.mine) + " cannot lie in the " + (det->plane.side == SonarSide::starboard ? "starboard" : "port") +
         " sonar plane below the robot at that range (tube north " + format_interval(inc.tube[0]) + ", east " +
         format_interval(inc.tube[1]) + "; mine box north " + format_interval(inc.mine_box[0]) + ", east " +
         format_interval(inc.mine_box[1]) + ")";
}

}  // namespace

std::string describe(const Inconsistency& inc, const MissionNetwork& net) {
  switch (inc.kind) {
    case Inconsistency::Kind::evolution: return evolution(inc, net);
    case Inconsistency::Kind::fix: return fix(inc);
    case Inconsistency::Kind::detection: return detection(inc, net);
  }
  return "inconsistent data";
}

std::string describe(const ConstraintRef& c) {
  return (c.kind == ConstraintRef::Kind::mark ? "mark " : "GPS fix ") + std::to_string(c.row);
}

std::string describe_diagnosis(const std::vector<ConstraintRef>& explaining) {
  if (explaining.empty()) return "; no single mark or fix explains it (try --max-outliers 2)";
  std::string names;
  for (const ConstraintRef& c : explaining) names += (names.empty() ? "" : " or ") + describe(c);
  return "; removing " + names + " restores consistency";
}

}  // namespace gesmi
