#pragma once
// Paving: a list of non-overlapping boxes of one dimension, stored flat (dim
// intervals per box, one contiguous array) so that adding a box never allocates
// beyond the array's amortised growth. SIVIA returns two of them: the inner and the
// boundary subpavings (seed 000, section 3).

#include <cstddef>
#include <span>
#include <vector>

#include "solver/interval/box.h"

namespace gesmi {

class Paving {
 public:
  Paving() : dim_(0) {}
  explicit Paving(std::size_t dim) : dim_(dim) {}

  std::size_t dim() const { return dim_; }
  std::size_t size() const { return dim_ == 0 ? 0 : data_.size() / dim_; }
  bool empty() const { return data_.empty(); }

  std::span<const Interval> box(std::size_t i) const { return {data_.data() + i * dim_, dim_}; }
  Box box_copy(std::size_t i) const { return Box(box(i).begin(), box(i).end()); }
  void add(std::span<const Interval> box) { data_.insert(data_.end(), box.begin(), box.end()); }
  /// Appends every box of another paving of the same dimension.
  void append(const Paving& other) { data_.insert(data_.end(), other.data_.begin(), other.data_.end()); }
  void reserve(std::size_t boxes) { data_.reserve(boxes * dim_); }
  void clear() { data_.clear(); }

  /// Sum of the box volumes (the boxes do not overlap, so this is the set's volume).
  double volume() const;
  /// Smallest box holding every box (empty box of dim_ empty intervals when empty).
  Box hull() const;
  /// The flat array, box after box: what the writers dump.
  std::span<const Interval> flat() const { return data_; }

 private:
  std::size_t dim_;
  std::vector<Interval> data_;
};

/// Volume of one box (0 for a degenerate or empty one).
double box_volume(std::span<const Interval> box);

}  // namespace gesmi
