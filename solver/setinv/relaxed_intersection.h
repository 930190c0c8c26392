#pragma once
// q-relaxed intersection of intervals: the hull of the points that lie in at least
// n - q of n intervals (an empty interval counts as containing nothing). With q = 0
// it is the plain intersection. Used to combine per-datum contractions when up to q
// data may be outliers.

#include <span>
#include <vector>

#include "solver/interval/interval.h"

namespace gesmi {

/// `scratch` is resized to 2 n entries (reuse it to avoid allocating).
Interval relaxed_intersection(std::span<const Interval> intervals, int q, std::vector<std::pair<double, int>>& scratch);

}  // namespace gesmi
