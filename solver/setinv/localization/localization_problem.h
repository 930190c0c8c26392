#pragma once
// Static localization of a robot (x, y, theta) from range and bearing measurements:
// the problem as plain data (built by io/ from a scenario file), and `localize`,
// which runs SIVIA(q) for a fixed number of outliers (seeds 000, 002, 003) or GOMNE
// for the minimal one (seed 004), refines the pavings until the outlier set phi is
// known on each box (outlier_refinement.h), then splits the result by outlier set
// (outlier_set_pavings.h) and into hypotheses (hypotheses.h), each with the data it
// treats as outliers and its association of measurements with walls and landmarks.
// localization_safety adds Remark 6's safety of each datum.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/setinv/components.h"
#include "solver/setinv/outliers/datum_safety.h"
#include "solver/setinv/outliers/gomne.h"
#include "solver/setinv/localization/localization_map.h"
#include "solver/setinv/outliers/outlier_set_pavings.h"
#include "solver/setinv/outliers/outlier_sets.h"

namespace gesmi {

/// Prior constraint a x + b y <= c on the position (seed 004, Remark 4).
struct HalfPlane {
  double a = 0, b = 0, c = 0;
};

enum class OutlierPolicy {
  fixed,    // SIVIA(q) with q = outliers (q = 0: every measurement holds)
  minimal,  // GOMNE: smallest q with a non-empty inner set, plus extra_outliers
};

struct LocalizationProblem {
  std::string name;
  LocalizationMap map;
  std::vector<RangeSensor> range_sensors;
  std::vector<BearingSensor> bearing_sensors;
  std::vector<RangeMeasurement> ranges;
  std::vector<BearingMeasurement> bearings;
  /// Per datum (ranges first, then bearings): its number in the scenario's list of
  /// measurements, from 1 (empty: i + 1). Outputs for people name data by it.
  std::vector<std::size_t> file_numbers;
  std::vector<Box> priors;             // boxes (x, y, theta), theta in radians
  std::vector<HalfPlane> constraints;  // all must hold
  double epsilon = 0.02;               // SIVIA accuracy (GOMNE's epsilon0)
  /// Weight of theta in box widths (metres per radian): larger bisects theta earlier
  /// and makes theta's accuracy epsilon / theta_scale.
  double theta_scale = 1.0;
  double epsilon_min = 1e-4;           // GOMNE's Remark 3 floor
  OutlierPolicy policy = OutlierPolicy::fixed;
  int outliers = 0;                    // q for the fixed policy
  int extra_outliers = 0;              // n_u of Remark 2 for the minimal policy
  int max_outliers = -1;               // GOMNE's largest q (-1: all data)
  std::size_t max_boxes = 50'000'000;
  double max_seconds = 600.0;
  std::optional<Pose<double>> truth;   // for checks and pictures only
  /// Contract boxes before testing them (CtcRangeRelaxed); off only to measure its effect.
  bool use_contractors = true;

  std::size_t datum_count() const { return ranges.size() + bearings.size(); }
  /// Datum i's number in the scenario file (from 1).
  std::size_t file_number(std::size_t i) const { return i < file_numbers.size() ? file_numbers[i] : i + 1; }
  /// Empty when consistent (indices, counts, widths); otherwise the reason.
  std::string validate() const;
};

struct LocalizationHypothesis {
  PavingComponent component;
  ComponentOutliers outliers;          // data indices: ranges first, then bearings
  std::vector<int> range_walls;        // per range measurement: wall index, -1 none, kNoWallInRange
  std::vector<int> bearing_landmarks;  // per bearing measurement: landmark, -1 none
  bool contains_truth = false;
};

struct LocalizationResult {
  /// SIVIA's (or GOMNE's) pavings refined where phi was undetermined; the report is
  /// SIVIA's. Hypotheses index these boxes.
  SiviaResult paving;
  int q = 0;                           // the number of outliers the pavings allow
  int q_lower = 0;                     // every S_k with k < q_lower was proved empty
  double epsilon = 0.0;                // accuracy of the pavings
  std::size_t refinement_boxes = 0;    // boxes evaluated to refine phi
  bool refinement_limit_hit = false;   // the refinement stopped at max_boxes or max_seconds
  OutlierPartition outlier_sets;       // S_q split by outlier set, with its ambiguous boxes
  std::vector<DatumSafety> safety;     // per datum (Remark 6), when localization_safety ran
  bool found = false;                  // inner set non-empty (minimal) / set non-empty (fixed)
  std::optional<GomneResult> gomne;    // the run's steps (without its paving) for the minimal policy
  std::vector<LocalizationHypothesis> hypotheses;
  bool truth_enclosed = false;         // the true pose lies in inner ∪ boundary
  double seconds = 0.0;
  /// Some search (SIVIA, GOMNE or the refinement) stopped at max_boxes or max_seconds:
  /// boxes were kept unbisected (still an enclosure).
  bool limit_hit() const { return paving.report.limit_hit() || (gomne && gomne->limit_hit) || refinement_limit_hit; }
};

LocalizationResult localize(const LocalizationProblem& problem,
                            const std::function<void(const SiviaProgress&)>& progress = {});

/// Remark 6 of seed 004 for every datum (ranges first, then bearings): S^(i) is the
/// q-outlier set of the problem without datum i, at the result's q and epsilon, with
/// the contractors; the estimate is result's refined paving. One SIVIA per datum.
std::vector<DatumSafety> localization_safety(const LocalizationProblem& problem, const LocalizationResult& result);

/// Does the box hold the pose (theta compared modulo 2 pi)?
bool box_holds_pose(std::span<const Interval> box, const Pose<double>& pose);

}  // namespace gesmi
