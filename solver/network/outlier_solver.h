#pragma once
// Outlier-tolerant solve (seed 001 section VII, after seed 004's GOMNE): when the
// data are inconsistent, raise q from 0 until removing some q of the detections and
// GPS fixes restores consistency (q <= max_outliers). The result encloses every
// trajectory and mine position consistent with all the data but q* of them, q*
// minimal: the hull, over every set of q* removed constraints that restores
// consistency, of the solve without them.
//
// Hypotheses are screened on the reduced network (reduced_network.h), which can
// only prove inconsistency; the survivors get a full solve.

#include <vector>

#include "solver/network/mission_solver.h"

namespace gesmi {

struct OutlierOptions {
  int max_outliers = 0;
  SolverOptions solver;
  std::string validate() const;
};

struct OutlierReport {
  int minimal_outliers = -1;  // q*, or -1 when no q <= max_outliers restores consistency
  /// Each consistent hypothesis: the removed constraints (network detection index j,
  /// or detections.size() + anchor index for a fix).
  std::vector<std::vector<std::size_t>> hypotheses;
  std::vector<char> detection_outlier;  // per network detection: removed in every hypothesis
  std::vector<char> fix_outlier;        // per anchor
  SolverReport first_solve;  // the solve with all the data (its inconsistency, if any)
  int hypotheses_screened = 0, full_solves = 0;
  bool consistent() const { return minimal_outliers >= 0; }
};

/// sensor: sensor_domains() of the mission. domains receives the result (the hull);
/// when no hypothesis works it holds the failed solve with all the data.
OutlierReport solve_with_outliers(const MissionNetwork& network, const TubeDomains& sensor, TubeDomains& domains,
                                  const OutlierOptions& options);

}  // namespace gesmi
