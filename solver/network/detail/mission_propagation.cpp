#include "solver/network/detail/mission_propagation.h"

namespace gesmi::detail {

std::optional<double> MissionPropagation::sweep(std::optional<Inconsistency>& failure) {
  double move = 0.0;
  if (!chains(true, move, failure) || !sparse(move, failure) || !chains(false, move, failure) ||
      !sparse(move, failure))
    return std::nullopt;
  return move;
}

bool MissionPropagation::chains(bool forward, double& move, std::optional<Inconsistency>& failure) {
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Interval>& p = *positions()[axis];
    std::vector<Interval>& inc = *increments()[axis];
    const SweepResult r = forward ? chain_forward(p, inc) : chain_backward(p, inc);
    if (!r.consistent()) {
      failure = evolution_failure(axis, r.first_empty, forward);
      return false;
    }
    move = std::max(move, r.max_shrink);
  }
  return true;
}

Inconsistency MissionPropagation::evolution_failure(int axis, std::size_t k, bool forward) {
  Inconsistency inc;
  inc.kind = Inconsistency::Kind::evolution;
  inc.step = k;
  inc.time = net_.time[k];
  const std::size_t boundary = forward ? k : k + 1;  // constraints at >= boundary are "after"
  std::string before, after;
  double before_time = -kInf, after_time = kInf;
  const auto consider = [&](std::size_t at_k, double t, const std::string& name) {
    if (at_k < boundary && t > before_time) {
      before_time = t;
      before = name;
    } else if (at_k >= boundary && t < after_time) {
      after_time = t;
      after = name;
    }
  };
  for (const Anchor& a : net_.anchors)
    consider(a.at.k, a.fix.time, "GPS fix " + std::to_string(a.fix.source_index) + " at t = " + format_time(a.fix.time));
  for (const Detection& d : net_.detections)
    consider(d.at.k, d.time, detection_head(d, d.mine >= 0 ? std::to_string(d.mine) : "?"));
  std::string what = "dead reckoning cannot join the " + std::string(kAxisNames[axis]) + " positions allowed before and after t = " +
                     format_time(inc.time);
  if (!before.empty() || !after.empty())
    what += ": between " + (before.empty() ? std::string("the start") : before) + " and " +
            (after.empty() ? std::string("the end") : after);
  if (axis == 2) what += "; the barometer bounds the depth there";
  what += " (one of them, or the DVL/gyrocompass bounds, is wrong)";
  inc.message = what;
  return inc;
}

bool MissionPropagation::sparse(double& move, std::optional<Inconsistency>& failure) {
  for (const Anchor& a : net_.anchors)
    if (!anchor(a, move, failure)) return false;
  for (std::size_t j = 0; j < net_.detections.size(); ++j)
    if (!detection(j, move, failure)) return false;
  return true;
}

bool MissionPropagation::anchor(const Anchor& a, double& move, std::optional<Inconsistency>& failure) {
  if (a.at.on_grid) return true;
  Vec3I q = a.at.position(d_);
  const Vec3I before = q;
  bool ok = true;
  for (int i = 0; ok && i < 3; ++i) ok = q[i].intersect_with(a.fix.box[i]);
  if (!ok || !a.at.narrow(d_, q)) {
    Inconsistency inc;
    inc.kind = Inconsistency::Kind::fix;
    inc.step = a.at.k;
    inc.time = a.fix.time;
    inc.source = a.fix.source_index;
    inc.message = "GPS fix " + std::to_string(a.fix.source_index) + " at t = " + format_time(a.fix.time) +
                  " (north " + format_interval(a.fix.box[0]) + ", east " + format_interval(a.fix.box[1]) +
                  ") is outside the tube there (north " + format_interval(before[0]) + ", east " +
                  format_interval(before[1]) + ")";
    failure = inc;
    return false;
  }
  move = std::max(move, largest_move(before, q));
  return true;
}

bool MissionPropagation::spread(std::size_t k, double stop_below, std::size_t& first, std::size_t& last, std::optional<Inconsistency>& failure) {
  first = last = k;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Interval>& p = *positions()[axis];
    std::vector<Interval>& inc = *increments()[axis];
    const SweepResult f = chain_forward_from(p, inc, k, stop_below);
    if (!f.consistent()) {
      failure = evolution_failure(axis, f.first_empty, true);
      return false;
    }
    const SweepResult b = chain_backward_from(p, inc, k, stop_below);
    if (!b.consistent()) {
      failure = evolution_failure(axis, b.first_empty, false);
      return false;
    }
    last = std::max(last, f.last);
    first = std::min(first, b.last);
  }
  return true;
}

bool MissionPropagation::detection(std::size_t j, double& move, std::optional<Inconsistency>& failure) {
  const Detection& det = net_.detections[j];
  std::uint64_t& candidates = d_.candidates[j];
  Vec3I q = det.at.position(d_);
  const Vec3I q_before = q;
  if (std::popcount(candidates) > 1) {
    Vec3I allowed(Interval::empty(), Interval::empty(), Interval::empty());
    std::uint64_t kept = 0;
    for (int i = 0; i < net_.mine_count; ++i) {
      if (!(candidates >> i & 1)) continue;
      Vec3I qi = q, mi = d_.mines[static_cast<std::size_t>(i)];
      if (!det.contract(qi, mi)) continue;
      kept |= std::uint64_t{1} << i;
      for (int c = 0; c < 3; ++c) allowed[c] = hull(allowed[c], qi[c]);
    }
    if (kept == 0) {
      failure = unexplained_failure(det, q);
      return false;
    }
    candidates = kept;
    q = allowed;
  }
  if (std::popcount(candidates) == 1) {
    const int mine = std::countr_zero(candidates);
    Vec3I& m = d_.mines[static_cast<std::size_t>(mine)];
    const Vec3I m_before = m;
    if (!det.contract(q, m)) {
      failure = detection_failure(det, mine, q_before, m_before);
      return false;
    }
    move = std::max(move, largest_move(m_before, m));
  }
  if (!det.at.narrow(d_, q)) {
    const int first = std::countr_zero(candidates);
    failure = detection_failure(det, first, q_before, d_.mines[static_cast<std::size_t>(first)]);
    return false;
  }
  move = std::max(move, largest_move(q_before, q));
  return true;
}

std::string MissionPropagation::detection_head(const Detection& det, const std::string& mine) const {
  return "detection " + std::to_string(det.mark) + " at t = " + format_time(det.time) + " (mine " + mine + ", range " +
         fixed(det.measured_range, 2) + " m, " + (det.side > 0 ? "starboard" : "port") + ")";
}

Inconsistency MissionPropagation::unexplained_failure(const Detection& det, const Vec3I& q) const {
  Inconsistency inc;
  inc.kind = Inconsistency::Kind::detection;
  inc.step = det.at.k;
  inc.time = det.time;
  inc.source = det.mark;
  std::string distances;
  for (int i = 0; i < net_.mine_count; ++i)
    if (det.allowed >> i & 1)
      distances += (distances.empty() ? "" : ", ") + std::string("mine ") + std::to_string(i) + " " +
                   format_interval(box_distance(q, d_.mines[static_cast<std::size_t>(i)]));
  inc.message = detection_head(det, "?") + ": no mine can explain it (distances from the tube, m: " + distances + ")";
  return inc;
}

Inconsistency MissionPropagation::detection_failure(const Detection& det, int mine, const Vec3I& q, const Vec3I& m) const {
  Inconsistency inc;
  inc.kind = Inconsistency::Kind::detection;
  inc.step = det.at.k;
  inc.time = det.time;
  inc.source = det.mark;
  const std::string head = detection_head(det, det.mine >= 0 ? std::to_string(det.mine) : "? -> " + std::to_string(mine));
  const Interval distance = box_distance(q, m);
  std::string why;
  if (!distance.intersects(det.range))
    why = ": range " + format_interval(det.range) + " m cannot be reached, the distance from the tube to mine " +
          std::to_string(mine) + " is within " + format_interval(distance) + " m";
  else
    why = ": mine " + std::to_string(mine) + " cannot lie in the " + (det.side > 0 ? "starboard" : "port") +
          " sonar plane below the robot at that range (tube north " + format_interval(q[0]) + ", east " +
          format_interval(q[1]) + "; mine box north " + format_interval(m[0]) + ", east " + format_interval(m[1]) + ")";
  inc.message = head + why;
  return inc;
}
}  // namespace gesmi::detail
