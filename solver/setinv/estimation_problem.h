#pragma once
// Parameter estimation with outliers (seed 004, section IV, Example 2): the
// parameters p in a prior box, a model f with one output per datum, interval data
// Y_i. For each number q of outliers asked for, the set j^{-1}(q) of the p
// consistent with exactly n - q data, split by outlier set: SIVIA(q), the
// refinement of phi (outlier_refinement.h) and the sets of size q of the partition
// (outlier_set_pavings.h). One hypothesis per outlier set of size q.
//
// Limits: max_boxes and max_seconds bound the whole run, every level's SIVIA and
// refinement together. When one is hit, the boxes still open are kept unbisected and
// each remaining level examines its prior box alone and keeps it whole, so every
// level's pavings still enclose j^{-1}(q); the levels say which limit was hit.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/outliers/outlier_set_pavings.h"

namespace gesmi {

enum class EstimationModel {
  /// f_i(p) = exp(-(t_i - p1)^2 / (2 p2)) / sqrt(2 pi p2): Example 2's Gaussian density.
  gaussian_density,
};

struct EstimationProblem {
  std::string name;
  EstimationModel model = EstimationModel::gaussian_density;
  std::vector<double> t;   // the model's abscissa of each datum
  Box data;                // Y_i
  Box prior;               // the frame box
  double epsilon = 0.01;
  std::vector<int> levels;  // the numbers of outliers q to characterise
  /// Boxes examined (SIVIA's and the refinement's) and wall time, for the whole run.
  /// The box limit also bounds memory: every box stored was examined, and keeps the
  /// data it may fail, so memory grows with boxes x data; hence the two ceilings
  /// (measured with 64 data at the default limit: about 140 bytes per box examined).
  std::size_t max_boxes = 2'000'000;
  double max_seconds = 600.0;
  static constexpr std::size_t kMaxData = 64;
  static constexpr std::size_t kMaxBoxesCeiling = 20'000'000;

  /// Empty when consistent; otherwise the reason.
  std::string validate() const;
};

struct EstimationLevel {
  int q = 0;
  std::vector<OutlierSetPaving> sets;  // the outlier sets of exactly q data, lexicographically
  /// Boxes fitting too many sets to list (outlier_set_pavings.h): with the sets'
  /// boxes, they enclose j^{-1}(q).
  Paving unresolved;
  std::size_t boxes_examined = 0;      // by SIVIA(q) and the refinement
  bool box_limit_hit = false;          // a limit left boxes unbisected in this level
  bool time_limit_hit = false;
  double seconds = 0.0;
  bool limit_hit() const { return box_limit_hit || time_limit_hit; }
  /// j^{-1}(q) proved non-empty: some set has an inner box.
  bool proved_nonempty() const;
};

struct EstimationResult {
  std::vector<EstimationLevel> levels;
  double seconds = 0.0;
  std::size_t boxes_examined() const;
  bool box_limit_hit() const;
  bool time_limit_hit() const;
  /// The smallest q asked for with j^{-1}(q) proved non-empty (seed 004's q* when
  /// every smaller q was asked for and is empty); none when no level was proved.
  std::optional<int> q_star() const;
};

/// Where a run is: the level (its place in problem.levels, and its q) and the boxes
/// examined so far over the whole run.
struct EstimationProgress {
  std::size_t level = 0;
  std::size_t level_count = 0;
  int q = 0;
  std::size_t boxes_examined = 0;
};

/// `progress` is called at the start of each level and every 65,536 boxes within it;
/// the solver never prints.
EstimationResult estimate(const EstimationProblem& problem,
                          const std::function<void(const EstimationProgress&)>& progress = {});

/// The model's output for datum i at a point p (plain doubles).
double model_output(const EstimationProblem& problem, std::size_t i, std::span<const double> p);

}  // namespace gesmi
