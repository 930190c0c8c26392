#pragma once
// What a mission solve gives back (solve_mission.h): the domains, per mark row the
// candidate mines and the outlier flag, per GPS row the outlier flag, the
// reconstructed waterfall, the report and the timings; and the mark table it was
// computed with, so that a later warm rerun can check that rows were only added.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solver/mission/sensor_model.h"
#include "solver/network/constraint_ref.h"
#include "solver/network/mission_solver.h"
#include "solver/network/sensors/step_regimes.h"
#include "solver/network/tube_domains.h"
#include "solver/network/waterfall/waterfall.h"

namespace gesmi {

enum class SolveMode { cold, warm, outliers, minimal_outliers };

/// "cold", "warm", "outliers", "minimal-outliers".
const char* solve_mode_name(SolveMode mode);

struct SolveReport {
  SolveMode mode = SolveMode::cold;
  bool consistent = true;
  int sweeps = 0;
  bool converged = false;
  /// The first empty domain (inconsistent only), and its wording with the diagnosis.
  std::optional<Inconsistency> inconsistency;
  std::string message;
  /// Cold inconsistent solves: the single marks or fixes whose removal restores
  /// consistency (empty: none does); absent when no diagnosis ran.
  std::optional<std::vector<ConstraintRef>> explained_by;
  /// Outlier modes: q* and the hypotheses at q* (the removed marks and fixes).
  int minimal_outliers = 0;
  std::vector<std::vector<ConstraintRef>> hypotheses;
  std::size_t removal_sets = 0, consistent_removal_sets = 0;
  /// Warm reruns: constraints applied; and why the rerun was solved cold, if it was.
  std::size_t work_items = 0;
  std::optional<std::string> cold_fallback;
  /// The farthest the solved tube reaches from the origin (m) where the frame's margins
  /// were capped at the zone's (infinite where it is unbounded, e.g. no fix bounds it):
  /// the result there assumes the robot stayed in the zone (frame_margins.h); 0 when
  /// the tube stays within it or the mission has no frame.
  double beyond_frame_zone = 0.0;
  /// The steps in the surface regime, and where the readings contradict the model's
  /// bounds (step_regimes.h): those steps fell back to wider bounds.
  StepRegimeReport regimes;
};

struct MissionSolution {
  // What it was computed on.
  std::vector<double> time;
  std::vector<double> mark_time, mark_range;
  std::vector<std::int32_t> mark_mine, mark_side;
  int mine_count = 0;
  SensorModel model;  // the bounds and the step model used
  // The enclosures.
  TubeDomains domains;                     // tube, increments, mine boxes
  std::vector<std::uint64_t> candidates;   // per mark row: candidate mines (bit i: mine i)
  std::vector<std::int32_t> mark_outlier;  // per mark row: 1 when every hypothesis at q* removes it
  std::vector<std::int32_t> gps_outlier;   // per GPS row: the same
  Waterfall waterfall;
  SolveReport report;
  std::map<std::string, double> timings_ms;  // build, propagate, diagnose, waterfall

  std::size_t mark_count() const { return mark_time.size(); }
};

}  // namespace gesmi
