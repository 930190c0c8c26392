#include "solver/network/outliers/relaxed_enclosure.h"

#include <algorithm>
#include <array>

#include "solver/network/outliers/outlier_solver.h"
#include "solver/network/reduced_network.h"
#include "solver/network/outliers/subsets.h"
#include "solver/tube/chain_sweep.h"

namespace gesmi {
namespace {

using Point = std::pair<double, double>;  // a bound at the event before, and at the event after

// Points no other point dominates from below (a' <= a and b' <= b): the only ones
// whose chain projection can give the smallest lower bound somewhere between.
std::vector<Point> lower_frontier(std::vector<Point> points) {
  std::sort(points.begin(), points.end());
  std::vector<Point> frontier;
  for (const Point& p : points)
    if (frontier.empty() || p.second < frontier.back().second) frontier.push_back(p);
  return frontier;
}

// The event boxes of every consistent removal set, per axis: boxes[axis][set][event].
using EventBoxes = std::array<std::vector<std::vector<Interval>>, 3>;

// Lowers out (a lower bound; raises it for an upper bound) over samples
// [write_from, last] to the bound that the chain from `prior` gives on [first, last]
// with the half-lines `before` at `first` and `after` at `last` (either may be the
// whole line: an open end of the mission).
void project(std::span<const Interval> prior, std::span<const Interval> increments, std::size_t first,
             std::size_t last, std::size_t write_from, const Interval& before, const Interval& after,
             std::vector<Interval>& scratch, std::vector<Interval>& scratch_increments, std::vector<double>& out,
             bool lower) {
  scratch.assign(prior.begin() + static_cast<std::ptrdiff_t>(first), prior.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  scratch_increments.assign(increments.begin() + static_cast<std::ptrdiff_t>(first),
                            increments.begin() + static_cast<std::ptrdiff_t>(last));
  if (!scratch.front().intersect_with(before) || !scratch.back().intersect_with(after)) return;
  if (!chain_forward(scratch, scratch_increments).consistent()) return;
  if (!chain_backward(scratch, scratch_increments).consistent()) return;
  for (std::size_t k = write_from; k <= last; ++k) {
    const Interval& x = scratch[k - first];
    out[k] = lower ? std::min(out[k], x.lo()) : std::max(out[k], x.hi());
  }
}

// The tube on every sample: per axis, the hull over removal sets of the chain
// projection between their event boxes.
void rebuild_tube(const std::array<std::span<const Interval>, 3>& priors,
                  const std::array<std::span<const Interval>, 3>& increments, const std::vector<std::size_t>& events,
                  const EventBoxes& boxes, std::array<std::vector<Interval>*, 3> tube) {
  const std::size_t n = priors[0].size();
  std::vector<Interval> scratch, scratch_increments;
  for (int axis = 0; axis < 3; ++axis) {
    const auto& sets = boxes[static_cast<std::size_t>(axis)];
    std::vector<double> lo(n, kInf), hi(n, -kInf);
    for (const bool lower : {true, false}) {
      std::vector<double>& out = lower ? lo : hi;
      // A bound as a half-line, and its sign flipped for the upper bounds so that one
      // frontier routine serves both.
      const auto half_line = [&](double bound) { return lower ? Interval(bound, kInf) : Interval(-kInf, bound); };
      const auto key = [&](const Interval& x) { return lower ? x.lo() : -x.hi(); };
      const auto unkey = [&](double v) { return lower ? v : -v; };
      // Each sample is written by one segment: [0, first event], then (event, next event].
      const auto segment = [&](std::size_t first, std::size_t last, int before, int after) {
        const std::size_t write_from = before >= 0 ? first + 1 : first;
        std::vector<Point> points;
        for (const auto& set : sets)
          points.emplace_back(before >= 0 ? key(set[static_cast<std::size_t>(before)]) : -kInf,
                              after >= 0 ? key(set[static_cast<std::size_t>(after)]) : -kInf);
        for (const Point& p : lower_frontier(std::move(points)))
          project(priors[static_cast<std::size_t>(axis)], increments[static_cast<std::size_t>(axis)], first, last, write_from,
                  before >= 0 ? half_line(unkey(p.first)) : Interval::entire(),
                  after >= 0 ? half_line(unkey(p.second)) : Interval::entire(), scratch, scratch_increments, out, lower);
      };
      if (events.empty()) {
        segment(0, n - 1, -1, -1);
        continue;
      }
      segment(0, events.front(), -1, 0);
      for (std::size_t i = 0; i + 1 < events.size(); ++i)
        segment(events[i], events[i + 1], static_cast<int>(i), static_cast<int>(i + 1));
      if (events.back() + 1 < n) segment(events.back(), n - 1, static_cast<int>(events.size() - 1), -1);
    }
    std::vector<Interval>& axis_tube = *tube[static_cast<std::size_t>(axis)];
    axis_tube.resize(n);
    for (std::size_t k = 0; k < n; ++k) axis_tube[k] = lo[k] <= hi[k] ? Interval(lo[k], hi[k]) : Interval::empty();
  }
}

}  // namespace

RelaxedStats relaxed_enclosure(const MissionNetwork& net, const TubeDomains& sensor,
                               const std::vector<std::size_t>& removable, std::size_t q, const SolverOptions& options,
                               TubeDomains& domains) {
  RelaxedStats stats;
  ReducedNetwork reduced;
  if (!build_reduced_network(net, sensor, reduced)) return stats;
  const std::size_t m = net.detections.size();
  EventBoxes boxes;
  std::vector<Vec3I> mines;
  std::vector<std::uint64_t> candidates(m, 0);
  TubeDomains trial;
  for_each_subset(removable, q, [&](const std::vector<std::size_t>& removed) {
    ++stats.removal_sets;
    const MissionNetwork sub = without_constraints(reduced.net, removed);
    trial = reduced.domains;
    add_network_priors(trial, sub);
    if (!solve(sub, trial, options).consistent()) return;
    ++stats.consistent_sets;
    boxes[0].push_back(trial.px);
    boxes[1].push_back(trial.py);
    boxes[2].push_back(trial.pz);
    if (mines.empty()) {
      mines = trial.mines;
    } else {
      for (std::size_t i = 0; i < mines.size(); ++i)
        for (int c = 0; c < 3; ++c) mines[i][c] = hull(mines[i][c], trial.mines[i][c]);
    }
    for (std::size_t j = 0, kept = 0; j < m; ++j) {
      if (std::binary_search(removed.begin(), removed.end(), j))
        candidates[j] |= net.detections[j].allowed;
      else
        candidates[j] |= trial.candidates[kept++];
    }
  });
  if (stats.consistent_sets == 0) return stats;

  domains = TubeDomains{};
  const std::array<std::span<const Interval>, 3> priors = {sensor.px, sensor.py, reduced.depth};
  const std::array<std::span<const Interval>, 3> increments = {sensor.dx, sensor.dy, reduced.depth_increments};
  rebuild_tube(priors, increments, reduced.events, boxes, {&domains.px, &domains.py, &domains.pz});
  // Increments: the sensors' boxes, narrowed by the tube at both ends.
  const std::size_t steps = sensor.dx.size();
  domains.dx.resize(steps);
  domains.dy.resize(steps);
  domains.dz.resize(steps);
  for (std::size_t k = 0; k < steps; ++k) {
    domains.dx[k] = intersect(sensor.dx[k], domains.px[k + 1] - domains.px[k]);
    domains.dy[k] = intersect(sensor.dy[k], domains.py[k + 1] - domains.py[k]);
    domains.dz[k] = intersect(reduced.depth_increments[k], domains.pz[k + 1] - domains.pz[k]);
  }
  domains.mines = std::move(mines);
  domains.candidates = std::move(candidates);
  return stats;
}

}  // namespace gesmi
