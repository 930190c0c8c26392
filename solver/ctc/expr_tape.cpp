#include "solver/ctc/expr_tape.h"

#include <unordered_map>

#include "solver/ctc/ctc.h"
#include "solver/interval/interval_reverse.h"

namespace gesmi {
namespace {

using NodePtr = const Expr::Node*;

int append(NodePtr node, std::vector<ExprTape::Entry>& entries, std::unordered_map<NodePtr, int>& seen) {
  if (auto it = seen.find(node); it != seen.end()) return it->second;
  ExprTape::Entry entry{node->op, -1, -1, node->value, node->index};
  if (node->a) entry.a = append(node->a.get(), entries, seen);
  if (node->b) entry.b = append(node->b.get(), entries, seen);
  entries.push_back(entry);
  const int position = static_cast<int>(entries.size()) - 1;
  seen.emplace(node, position);
  return position;
}

Interval forward_op(const ExprTape::Entry& e, const Interval& a, const Interval& b) {
  switch (e.op) {
    case ExprOp::add: return a + b;
    case ExprOp::sub: return a - b;
    case ExprOp::mul: return a * b;
    case ExprOp::div: return a / b;
    case ExprOp::neg: return -a;
    case ExprOp::sqr: return sqr(a);
    case ExprOp::sqrt: return sqrt(a);
    case ExprOp::pow: return pow(a, e.index);
    case ExprOp::exp: return exp(a);
    case ExprOp::log: return log(a);
    case ExprOp::sin: return sin(a);
    case ExprOp::cos: return cos(a);
    case ExprOp::tan: return tan(a);
    case ExprOp::atan: return atan(a);
    case ExprOp::atan2: return atan2(a, b);
    case ExprOp::abs: return abs(a);
    case ExprOp::min: return min(a, b);
    case ExprOp::max: return max(a, b);
    case ExprOp::variable:
    case ExprOp::constant: break;
  }
  return Interval::entire();
}

// Narrows the operands a, b of an entry whose value is y.
bool backward_op(const ExprTape::Entry& e, const Interval& y, Interval& a, Interval& b) {
  switch (e.op) {
    case ExprOp::add: return bwd_add(y, a, b);
    case ExprOp::sub: return bwd_sub(y, a, b);
    case ExprOp::mul: return bwd_mul(y, a, b);
    case ExprOp::div: return bwd_div(y, a, b);
    case ExprOp::neg: return bwd_neg(y, a);
    case ExprOp::sqr: return bwd_sqr(y, a);
    case ExprOp::sqrt: return bwd_sqrt(y, a);
    case ExprOp::pow: return bwd_pow(y, a, e.index);
    case ExprOp::exp: return bwd_exp(y, a);
    case ExprOp::log: return bwd_log(y, a);
    case ExprOp::sin: return bwd_sin(y, a);
    case ExprOp::cos: return bwd_cos(y, a);
    case ExprOp::tan: return bwd_tan(y, a);
    case ExprOp::atan: return bwd_atan(y, a);
    case ExprOp::atan2: return bwd_atan2(y, a, b);
    case ExprOp::abs: return bwd_abs(y, a);
    case ExprOp::min: return bwd_min(y, a, b);
    case ExprOp::max: return bwd_max(y, a, b);
    case ExprOp::variable:
    case ExprOp::constant: break;
  }
  return true;
}

}  // namespace

ExprTape::ExprTape(const Expr& e) {
  std::unordered_map<NodePtr, int> seen;
  append(e.node().get(), entries_, seen);
  for (const Entry& entry : entries_)
    if (entry.op == ExprOp::variable) variable_count_ = std::max(variable_count_, entry.index + 1);
}

void ExprTape::forward(const Box& box, std::span<Interval> values) const {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    if (e.op == ExprOp::variable) {
      values[i] = box[static_cast<std::size_t>(e.index)];
    } else if (e.op == ExprOp::constant) {
      values[i] = e.constant;
    } else {
      const Interval none = Interval::entire();
      values[i] = forward_op(e, values[static_cast<std::size_t>(e.a)], e.b >= 0 ? values[static_cast<std::size_t>(e.b)] : none);
    }
  }
}

bool ExprTape::backward(std::span<Interval> values, Box& box) const {
  for (std::size_t i = entries_.size(); i-- > 0;) {
    const Entry& e = entries_[i];
    if (values[i].is_empty()) {
      set_empty(box);
      return false;
    }
    if (e.op == ExprOp::variable) {
      Interval& x = box[static_cast<std::size_t>(e.index)];
      if (!x.intersect_with(values[i])) {
        set_empty(box);
        return false;
      }
      continue;
    }
    if (e.op == ExprOp::constant) continue;
    Interval unused;
    Interval& a = values[static_cast<std::size_t>(e.a)];
    Interval& b = e.b >= 0 ? values[static_cast<std::size_t>(e.b)] : unused;
    if (!backward_op(e, values[i], a, b)) {
      set_empty(box);
      return false;
    }
  }
  return true;
}

}  // namespace gesmi
