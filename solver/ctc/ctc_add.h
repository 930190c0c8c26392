#pragma once
// CtcAdd: the constraint s = a + b on three variables of a box, contracted with
// the three projections s = a + b, a = s - b, b = s - a (seed 001, III-A). Tighter
// than forward-backward on the expression s - (a + b) = 0, which rounds twice.

#include "solver/ctc/ctc.h"
#include "solver/interval/interval_reverse.h"

namespace gesmi {

class CtcAdd {
 public:
  CtcAdd(int sum, int a, int b) : sum_(sum), a_(a), b_(b) {}
  void contract(Box& box) const {
    Interval& s = box[static_cast<std::size_t>(sum_)];
    Interval& a = box[static_cast<std::size_t>(a_)];
    Interval& b = box[static_cast<std::size_t>(b_)];
    if (!s.intersect_with(a + b) || !bwd_add(s, a, b)) set_empty(box);
  }

 private:
  int sum_, a_, b_;
};

}  // namespace gesmi
