#pragma once
// Parameter estimation with outliers (seed 004, section IV, Example 2): the
// parameters p in a prior box, a model f with one output per datum, interval data
// Y_i. For each number q of outliers asked for, the set j^{-1}(q) of the p
// consistent with exactly n - q data, split by outlier set: SIVIA(q), the
// refinement of phi (outlier_refinement.h) and the sets of size q of the partition
// (outlier_set_pavings.h). One hypothesis per outlier set of size q.

#include <string>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/outlier_set_pavings.h"

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
  std::size_t max_boxes = 10'000'000;

  /// Empty when consistent; otherwise the reason.
  std::string validate() const;
};

struct EstimationLevel {
  int q = 0;
  std::vector<OutlierSetPaving> sets;  // the outlier sets of exactly q data, by size then lexicographically
  std::size_t boxes_examined = 0;      // by SIVIA(q) and the refinement
  bool limit_hit = false;
  double seconds = 0.0;
  /// j^{-1}(q) proved non-empty: some set has an inner box.
  bool proved_nonempty() const;
};

struct EstimationResult {
  std::vector<EstimationLevel> levels;
  double seconds = 0.0;
};

EstimationResult estimate(const EstimationProblem& problem);

/// The model's output for datum i at a point p (plain doubles).
double model_output(const EstimationProblem& problem, std::size_t i, std::span<const double> p);

}  // namespace gesmi
