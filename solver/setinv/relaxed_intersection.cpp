#include "solver/setinv/relaxed_intersection.h"

#include <algorithm>

namespace gesmi {

Interval relaxed_intersection(std::span<const Interval> intervals, int q, std::vector<std::pair<double, int>>& scratch) {
  const int needed = static_cast<int>(intervals.size()) - q;
  if (needed <= 0) return Interval::entire();
  scratch.clear();
  for (const Interval& x : intervals) {
    if (x.is_empty()) continue;
    scratch.emplace_back(x.lo(), -1);  // openings sort before closings at the same abscissa
    scratch.emplace_back(x.hi(), +1);
  }
  std::sort(scratch.begin(), scratch.end());
  int count = 0;
  double lo = kInf, hi = -kInf;
  for (const auto& [x, kind] : scratch) {
    if (kind < 0) {
      if (++count >= needed) lo = std::min(lo, x);
    } else {
      if (count >= needed) hi = std::max(hi, x);
      --count;
    }
  }
  return lo <= hi ? Interval(lo, hi) : Interval::empty();
}

}  // namespace gesmi
