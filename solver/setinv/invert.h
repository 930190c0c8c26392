#pragma once
// The generic entry point: inner and boundary subpavings of {p ∈ priors | f(p) ∈ Y}
// for any model templated on the number type (solver/setinv/datum_tests.h), or of
// {p | every datum holds} for any DatumTests, with an optional contractor.

#include <span>
#include <vector>

#include "solver/setinv/datum_tests.h"
#include "solver/setinv/sivia.h"

namespace gesmi {

/// SIVIA test "every datum holds": true when all are certainly true, false as soon
/// as one is certainly false.
template <DatumTests Data>
class AllDataHold {
 public:
  explicit AllDataHold(Data& data) : data_(data), values_(data.datum_count(), IBool::maybe()) {}
  IBool operator()(const Box& box, int depth) {
    data_.evaluate(box, depth, values_, 0);
    const DatumCounts c = count_data(values_);
    if (c.no > 0) return false;
    if (c.yes == static_cast<int>(values_.size())) return true;
    return IBool::maybe();
  }

 private:
  Data& data_;
  std::vector<IBool> values_;
};

template <DatumTests Data, Contractor Ctc = CtcNone>
SiviaResult invert_data(Data& data, std::span<const Box> priors, const SiviaOptions& options, const Ctc& ctc = {}) {
  AllDataHold<Data> test(data);
  return sivia(test, priors, options, ctc);
}

template <PointAndBoxModel Model, Contractor Ctc = CtcNone>
SiviaResult invert(const Model& f, const Box& image, const Box& prior, const SiviaOptions& options, const Ctc& ctc = {}) {
  ImageInBox<Model> data(f, image);
  return invert_data(data, std::span<const Box>(&prior, 1), options, ctc);
}

}  // namespace gesmi
