#pragma once
// All the data of a localization problem as one DatumTests: the range measurements
// first, then the bearing measurements, with a shared false budget.

#include <optional>
#include <span>
#include <vector>

#include "solver/setinv/localization/bearing_data.h"
#include "solver/setinv/localization/range_data.h"

namespace gesmi {

class LocalizationData {
 public:
  LocalizationData(RangeData ranges, BearingData bearings) : ranges_(std::move(ranges)), bearings_(std::move(bearings)) {}

  std::size_t datum_count() const { return ranges_.datum_count() + bearings_.datum_count(); }
  void evaluate(const Box& box, int depth, std::span<IBool> out, int false_budget) {
    const std::size_t n = ranges_.datum_count();
    if (n > 0) ranges_.evaluate(box, depth, out.first(n), false_budget);
    int falses = 0;
    for (std::size_t i = 0; i < n; ++i) falses += out[i].is_false();
    if (bearings_.datum_count() > 0) bearings_.evaluate(box, depth, out.subspan(n), false_budget - falses);
  }
  const RangeData& ranges() const { return ranges_; }
  const BearingData& bearings() const { return bearings_; }

 private:
  RangeData ranges_;
  BearingData bearings_;
};

}  // namespace gesmi
