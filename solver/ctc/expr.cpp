#include "solver/ctc/expr.h"

#include <algorithm>

#include "solver/ctc/expr_tape.h"

namespace gesmi {

Expr Expr::var(int index) {
  auto node = std::make_shared<Node>(Node{ExprOp::variable, nullptr, nullptr, Interval(), index});
  return Expr(node);
}

Expr Expr::constant(const Interval& value) {
  auto node = std::make_shared<Node>(Node{ExprOp::constant, nullptr, nullptr, value, 0});
  return Expr(node);
}

Expr Expr::make(ExprOp op, const Expr& a) {
  return Expr(std::make_shared<Node>(Node{op, a.node_, nullptr, Interval(), 0}));
}

Expr Expr::make(ExprOp op, const Expr& a, const Expr& b) {
  return Expr(std::make_shared<Node>(Node{op, a.node_, b.node_, Interval(), 0}));
}

Expr Expr::make_pow(const Expr& a, int n) {
  return Expr(std::make_shared<Node>(Node{ExprOp::pow, a.node_, nullptr, Interval(), n}));
}

int Expr::variable_count() const {
  const ExprTape tape(*this);
  return tape.variable_count();
}

Interval eval(const Expr& e, const Box& box) {
  const ExprTape tape(e);
  std::vector<Interval> values(tape.size());
  tape.forward(box, values);
  return values.back();
}

}  // namespace gesmi
