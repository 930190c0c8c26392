#include "solver/ctc/ctc_fwd_bwd.h"

#include "solver/ctc/expr_tape.h"

namespace gesmi {

CtcFwdBwd::CtcFwdBwd(const Expr& f, const Interval& image)
    : tape_(std::make_shared<const ExprTape>(f)), image_(image), values_(tape_->size()) {}

void CtcFwdBwd::contract(Box& box) const {
  if (is_empty(box)) {
    normalize_empty(box);
    return;
  }
  tape_->forward(box, values_);
  if (!values_.back().intersect_with(image_)) {
    set_empty(box);
    return;
  }
  tape_->backward(values_, box);
}

}  // namespace gesmi
