#pragma once
// The propagation steps over a mission network, shared by the full forward-backward
// solve and the work-list rerun: the evolution chains, the fixes between samples,
// the detections (with the disjunction of unassociated marks), and the one-line
// explanation of the first domain that became empty. Implementation detail of
// solver/network.

#include <array>
#include <bit>
#include <optional>
#include <string>
#include <vector>

#include "solver/network/mission_network.h"
#include "solver/network/mission_solver.h"
#include "solver/tube/chain_sweep.h"
#include "solver/tube/steps_to_sweep.h"

namespace gesmi::detail {


inline double largest_move(const Vec3I& before, const Vec3I& after) {
  double move = 0.0;
  for (int i = 0; i < 3; ++i) move = std::max({move, after[i].lo() - before[i].lo(), before[i].hi() - after[i].hi()});
  return move;
}

class MissionPropagation {
 public:
  MissionPropagation(const MissionNetwork& net, TubeDomains& d) : net_(net), d_(d) {}

  // One forward-backward sweep; returns the largest bound move, or nullopt and
  // sets the inconsistency when a domain became empty. The chains' steps that nothing
  // narrowed since the last sweep are left out (steps_to_sweep.h): the same bounds.
  std::optional<double> sweep(std::optional<Inconsistency>& failure);

  std::array<std::vector<Interval>*, 3> positions() { return {&d_.px, &d_.py, &d_.pz}; }
  std::array<std::vector<Interval>*, 3> increments() { return {&d_.dx, &d_.dy, &d_.dz}; }

  // The three chains swept in one direction, over the steps to sweep.
  bool chains(bool forward, double& move, std::optional<Inconsistency>& failure);

  // The chain emptied p(k) (forward: coming from k - 1; backward: from k + 1): the
  // constraints on either side of that step cannot be joined by dead reckoning.
  // Name the nearest fix or detection on each side: they, or the navigation bounds
  // between them, are what to check.
  Inconsistency evolution_failure(int axis, std::size_t k, bool forward);

  // Every fix between samples, then every detection.
  bool sparse(double& move, std::optional<Inconsistency>& failure);

  // A fix between two samples (on a sample it is part of the prior and never lost).
  bool anchor(const Anchor& a, double& move, std::optional<Inconsistency>& failure);

  // Spreads a change at sample k along the three chains, forward and backward,
  // while the domains keep shrinking by more than stop_below; [first, last] is the
  // range of samples that changed.
  bool spread(std::size_t k, double stop_below, std::size_t& first, std::size_t& last,
              std::optional<Inconsistency>& failure);

  // One detection: with a single candidate mine, the mark contractor on the tube at
  // the mark time and that mine's box; with several (an unassociated mark), the
  // disjunction: each candidate is tried on copies, those that empty are dropped,
  // and the tube keeps the hull of what the others allow (mine boxes are narrowed
  // only once a single candidate is left).
  bool detection(std::size_t j, double& move, std::optional<Inconsistency>& failure);

  Inconsistency unexplained_failure(const Detection& det, const Vec3I& q) const;

  Inconsistency detection_failure(const Detection& det, int mine, const Vec3I& q, const Vec3I& m) const;

 private:
  // A fix or detection narrowed the tube at this time: the chains' steps that read it.
  void narrowed_at(const TimeLocation& at);

  const MissionNetwork& net_;
  TubeDomains& d_;
  // The steps the next sweeps must take; made by the first sweep (the work-list rerun
  // spreads instead, and drops them).
  std::optional<StepsToSweep> steps_;
};

}  // namespace gesmi::detail

