#pragma once
// Outlier-tolerant solve (seed 001 section VII, after seed 004's GOMNE). The
// removable constraints are the detections and the GPS fixes (or the detections
// only, when the fixes are trusted). Two enclosures, named apart because they
// promise different things:
//
//  - relaxed (the default, `--max-outliers Q`): every trajectory and mine position
//    consistent with all the data but at most Q removable constraints, the
//    q-relaxed set S_Q of seed 004. It contains the truth whenever at most Q of
//    those inputs are wrong, however many that is below Q (relaxed_enclosure.h).
//  - minimal (`--minimal-outliers Q`): the hull, over every set of q* removed
//    constraints that restores consistency, q* minimal, of the solve without them.
//    It contains the truth only if exactly q* inputs are wrong: when more are wrong
//    than the data reveal, a correct constraint can be the one dropped. Conditional.
//
// Both report q* (raised from 0, hypotheses screened on the reduced network and
// confirmed by full solves) and the constraints removed in every q* hypothesis.

#include <vector>

#include "solver/network/mission_solver.h"

namespace gesmi {

enum class OutlierMode { relaxed, minimal };

struct OutlierOptions {
  int max_outliers = 0;
  SolverOptions solver;
  OutlierMode mode = OutlierMode::relaxed;
  bool trust_fixes = false;  // GPS fixes are never outliers: only detections are removable
  std::string validate() const;
};

struct OutlierReport {
  int minimal_outliers = -1;  // q*, or -1 when no q <= max_outliers restores consistency
  /// Each consistent hypothesis at q*: the removed constraints (network detection
  /// index j, or detections.size() + anchor index for a fix).
  std::vector<std::vector<std::size_t>> hypotheses;
  std::vector<char> detection_outlier;  // per network detection: removed in every hypothesis
  std::vector<char> fix_outlier;        // per anchor
  SolverReport first_solve;  // the solve with all the data (its inconsistency, if any)
  int hypotheses_screened = 0, full_solves = 0;
  /// Relaxed mode: removal sets of size Q examined, and those consistent.
  std::size_t removal_sets = 0, consistent_removal_sets = 0;
  bool consistent() const { return minimal_outliers >= 0; }
};

/// sensor: sensor_domains() of the mission. domains receives the enclosure of the
/// chosen mode; when no q <= max_outliers restores consistency it holds the failed
/// solve with all the data.
OutlierReport solve_with_outliers(const MissionNetwork& network, const TubeDomains& sensor, TubeDomains& domains,
                                  const OutlierOptions& options);

/// The network without the constraints of `removed` (sorted ids, as in hypotheses).
MissionNetwork without_constraints(const MissionNetwork& network, const std::vector<std::size_t>& removed);

}  // namespace gesmi
