#pragma once
// An expression flattened into a tape in topological order (children before
// parents, shared sub-expressions once): the forward pass evaluates it on a box,
// the backward pass (HC4-revise) narrows the box with the reverse operators.

#include <span>
#include <vector>

#include "solver/ctc/expr.h"

namespace gesmi {

class ExprTape {
 public:
  struct Entry {
    ExprOp op;
    int a = -1, b = -1;  // operand positions in the tape
    Interval constant;
    int index = 0;       // variable index, or exponent for pow
  };

  explicit ExprTape(const Expr& e);

  std::size_t size() const { return entries_.size(); }
  int variable_count() const { return variable_count_; }

  /// values[i] = interval value of entry i on the box; the last entry is the root.
  void forward(const Box& box, std::span<Interval> values) const;
  /// Narrows the entries from the root down and then the box. values must hold a
  /// forward pass whose root was intersected with the constraint's image.
  /// Returns false (box left empty) when some domain became empty.
  bool backward(std::span<Interval> values, Box& box) const;

 private:
  std::vector<Entry> entries_;
  int variable_count_ = 0;
};

}  // namespace gesmi
