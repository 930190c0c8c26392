#pragma once
// Options, progress and report of SIVIA (solver/setinv/sivia.h).

#include <cstddef>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "solver/setinv/paving.h"

namespace gesmi {

struct SiviaProgress {
  std::size_t boxes_visited = 0;
  std::size_t inner_boxes = 0;
  std::size_t boundary_boxes = 0;
  double seconds = 0.0;
};

struct SiviaOptions {
  /// A box whose (scaled) width is below epsilon is not bisected: it goes to the
  /// boundary subpaving when its test is undetermined (seed 000, Table 1, step 2).
  double epsilon = 0.01;
  /// Optional weight of each dimension in the width and in the choice of the
  /// dimension to bisect (e.g. metres against radians); empty means all 1.
  std::vector<double> scale;
  /// Dimension holding an angle of the given period (theta), or -1. A prior wider
  /// than one period is cut to one period; components connect across the period.
  int periodic_dimension = -1;
  double period = 2.0 * std::numbers::pi;
  /// Limits: boxes examined and wall time. When one is hit, the boxes still open
  /// are put in the boundary subpaving unbisected (the result stays an enclosure)
  /// and the report says which limit was hit.
  std::size_t max_boxes = std::numeric_limits<std::size_t>::max();
  double max_seconds = std::numeric_limits<double>::infinity();
  /// Called every progress_every boxes examined; the solver never prints.
  std::function<void(const SiviaProgress&)> progress;
  std::size_t progress_every = std::size_t{1} << 16;

  /// Empty when usable for boxes of dimension dim; otherwise the reason.
  std::string validate(std::size_t dim) const;
};

struct SiviaReport {
  std::size_t boxes_visited = 0;    // boxes whose test was evaluated
  std::size_t boxes_contracted = 0; // boxes narrowed by the contractor
  int max_depth = 0;
  /// Undetermined boxes kept in the boundary subpaving because they are narrower
  /// than epsilon, and those still wider whose widest side doubles cannot split (its
  /// midpoint is one of its bounds). With none of the first kind, a smaller epsilon
  /// gives the same result.
  std::size_t boxes_at_epsilon = 0;
  std::size_t boxes_unsplittable = 0;
  bool box_limit_hit = false;
  bool time_limit_hit = false;
  double seconds = 0.0;
  bool limit_hit() const { return box_limit_hit || time_limit_hit; }
};

struct SiviaResult {
  Paving inner;     // boxes proved inside the solution set
  Paving boundary;  // undetermined boxes; inner ∪ boundary encloses the set
  SiviaReport report;
};

}  // namespace gesmi
