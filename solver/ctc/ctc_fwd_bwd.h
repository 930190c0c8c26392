#pragma once
// CtcFwdBwd: forward-backward contractor (HC4-revise) for a constraint f(x) in Y,
// with f an Expr. The forward pass evaluates f on the box, the image is
// intersected with Y, and the backward pass narrows every sub-expression and
// variable with the reverse operators.

#include <memory>
#include <vector>

#include "solver/ctc/ctc.h"
#include "solver/ctc/expr.h"

namespace gesmi {

class ExprTape;

class CtcFwdBwd {
 public:
  /// Constraint f(x) in image (an equation when image is a point).
  CtcFwdBwd(const Expr& f, const Interval& image);
  void contract(Box& box) const;

 private:
  std::shared_ptr<const ExprTape> tape_;
  Interval image_;
  // Scratch for the node values, sized once: contract() allocates nothing.
  // A contractor instance is therefore not shared between threads.
  mutable std::vector<Interval> values_;
};

}  // namespace gesmi
