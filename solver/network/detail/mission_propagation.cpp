#include "solver/network/detail/mission_propagation.h"

namespace gesmi::detail {

std::optional<double> MissionPropagation::sweep(std::optional<Inconsistency>& failure) {
  if (!steps_) steps_.emplace(d_.px.size());
  double move = 0.0;
  if (!chains(true, move, failure) || !sparse(move, failure) || !chains(false, move, failure) ||
      !sparse(move, failure))
    return std::nullopt;
  return move;
}

bool MissionPropagation::chains(bool forward, double& move, std::optional<Inconsistency>& failure) {
  const std::array<std::span<Interval>, 3> p{d_.px, d_.py, d_.pz};
  const ChainsSweepResult r =
      forward ? chains_forward(p,
                               {std::span<const Interval>(d_.dx), std::span<const Interval>(d_.dy),
                                std::span<const Interval>(d_.dz)},
                               *steps_)
              : chains_backward(p, {std::span<Interval>(d_.dx), std::span<Interval>(d_.dy), std::span<Interval>(d_.dz)},
                                *steps_);
  if (!r.consistent()) {
    failure = evolution_failure(r.chain, r.sweep.first_empty, forward);
    return false;
  }
  move = std::max(move, r.sweep.max_shrink);
  return true;
}

Inconsistency MissionPropagation::evolution_failure(int axis, std::size_t k, bool forward) {
  Inconsistency inc;
  inc.kind = Inconsistency::Kind::evolution;
  inc.step = k;
  inc.time = net_.time[k];
  inc.axis = axis;
  // The nearest fix or detection on each side of the step: they, or the navigation
  // bounds between them, are what to check.
  const std::size_t boundary = forward ? k : k + 1;  // constraints at >= boundary are "after"
  double before_time = -kInf, after_time = kInf;
  const auto consider = [&](std::size_t at_k, double t, ConstraintRef ref) {
    if (at_k < boundary && t > before_time) {
      before_time = t;
      inc.before = ref;
    } else if (at_k >= boundary && t < after_time) {
      after_time = t;
      inc.after = ref;
    }
  };
  for (const Anchor& a : net_.anchors) consider(a.at.k, a.fix.time, ConstraintRef::gps_fix(a.fix.source_index));
  for (const Detection& d : net_.detections) consider(d.at.k, d.time, ConstraintRef::mark(d.mark));
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
    inc.source = ConstraintRef::gps_fix(a.fix.source_index);
    inc.fix_box = a.fix.box;
    inc.tube = before;
    failure = inc;
    return false;
  }
  narrowed_at(a.at);
  move = std::max(move, largest_move(before, q));
  return true;
}

void MissionPropagation::narrowed_at(const TimeLocation& at) {
  if (!steps_) return;
  steps_->narrowed(at.k);
  if (!at.on_grid) steps_->narrowed(at.k + 1);
}

bool MissionPropagation::spread(std::size_t k, double stop_below, std::size_t& first, std::size_t& last, std::optional<Inconsistency>& failure) {
  steps_.reset();  // (spreads narrow without marking: a later sweep takes every step)
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
  narrowed_at(det.at);
  move = std::max(move, largest_move(q_before, q));
  return true;
}

Inconsistency MissionPropagation::unexplained_failure(const Detection& det, const Vec3I& q) const {
  Inconsistency inc;
  inc.kind = Inconsistency::Kind::detection;
  inc.step = det.at.k;
  inc.time = det.time;
  inc.source = ConstraintRef::mark(det.mark);
  inc.tube = q;
  for (int i = 0; i < net_.mine_count; ++i)
    if (det.allowed >> i & 1) inc.candidate_distances.emplace_back(i, box_distance(q, d_.mines[static_cast<std::size_t>(i)]));
  return inc;
}

Inconsistency MissionPropagation::detection_failure(const Detection& det, int mine, const Vec3I& q, const Vec3I& m) const {
  Inconsistency inc;
  inc.kind = Inconsistency::Kind::detection;
  inc.step = det.at.k;
  inc.time = det.time;
  inc.source = ConstraintRef::mark(det.mark);
  inc.mine = mine;
  inc.tube = q;
  inc.mine_box = m;
  return inc;
}
}  // namespace gesmi::detail
