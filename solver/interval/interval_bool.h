#pragma once
// Interval Booleans and Kearfott's chi function (seed 000, section 2).
//
// An IBool is one of {false}, {true} or {false, true} (unknown): the image of a
// test evaluated on a box. chi(a, b, c) is b when a <= 0 and c when a > 0; on
// intervals it returns b, c or their hull, so branching models can be evaluated
// on points and boxes with one piece of code.

#include <cstdint>

#include "solver/interval/interval.h"

namespace gesmi {

class IBool {
 public:
  enum class Value : std::uint8_t { no, yes, maybe, empty };
  constexpr IBool(bool b) : v_(b ? Value::yes : Value::no) {}  // NOLINT: a bool is a degenerate IBool
  constexpr explicit IBool(Value v) : v_(v) {}
  static constexpr IBool maybe() { return IBool(Value::maybe); }
  static constexpr IBool empty() { return IBool(Value::empty); }

  constexpr Value value() const { return v_; }
  constexpr bool is_true() const { return v_ == Value::yes; }
  constexpr bool is_false() const { return v_ == Value::no; }
  constexpr bool is_maybe() const { return v_ == Value::maybe; }
  constexpr bool is_empty() const { return v_ == Value::empty; }
  /// True when the value true is still possible.
  constexpr bool may_be_true() const { return v_ == Value::yes || v_ == Value::maybe; }
  constexpr bool may_be_false() const { return v_ == Value::no || v_ == Value::maybe; }

  friend constexpr bool operator==(IBool a, IBool b) { return a.v_ == b.v_; }

 private:
  Value v_;
};

/// Union of the sets of values.
constexpr IBool hull(IBool a, IBool b) {
  if (a.is_empty()) return b;
  if (b.is_empty()) return a;
  return a == b ? a : IBool::maybe();
}
constexpr IBool operator!(IBool a) {
  if (a.is_empty() || a.is_maybe()) return a;
  return IBool(!a.is_true());
}
constexpr IBool operator&&(IBool a, IBool b) {
  if (a.is_empty() || b.is_empty()) return IBool::empty();
  if (a.is_false() || b.is_false()) return IBool(false);
  if (a.is_true() && b.is_true()) return IBool(true);
  return IBool::maybe();
}
constexpr IBool operator||(IBool a, IBool b) { return !(!a && !b); }

// Comparisons of intervals: certain when every pair of points agrees.
constexpr IBool leq(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return IBool::empty();
  if (x.hi() <= y.lo()) return IBool(true);
  if (x.lo() > y.hi()) return IBool(false);
  return IBool::maybe();
}
constexpr IBool less(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return IBool::empty();
  if (x.hi() < y.lo()) return IBool(true);
  if (x.lo() >= y.hi()) return IBool(false);
  return IBool::maybe();
}
constexpr IBool geq(const Interval& x, const Interval& y) { return leq(y, x); }
constexpr IBool greater(const Interval& x, const Interval& y) { return less(y, x); }
constexpr IBool member(const Interval& x, const Interval& y) {  // x in y for every point of x
  if (x.is_empty() || y.is_empty()) return IBool::empty();
  if (y.is_superset(x)) return IBool(true);
  if (!x.intersects(y)) return IBool(false);
  return IBool::maybe();
}

// Point versions, so that templated models compile for double.
constexpr bool leq(double x, double y) { return x <= y; }
constexpr bool less(double x, double y) { return x < y; }
constexpr bool geq(double x, double y) { return x >= y; }
constexpr bool greater(double x, double y) { return x > y; }

/// Kearfott's chi: b if a <= 0, c if a > 0.
constexpr double chi(double a, double b, double c) { return a <= 0.0 ? b : c; }
constexpr Interval chi(const Interval& a, const Interval& b, const Interval& c) {
  if (a.is_empty()) return Interval::empty();
  if (a.hi() <= 0.0) return b;
  if (a.lo() > 0.0) return c;
  return hull(b, c);
}
/// chi on Booleans: b if a is true, c if a is false, the hull when unknown.
constexpr IBool chi(IBool a, IBool b, IBool c) {
  if (a.is_empty()) return IBool::empty();
  if (a.is_true()) return b;
  if (a.is_false()) return c;
  return hull(b, c);
}
constexpr Interval select(IBool a, const Interval& b, const Interval& c) {
  if (a.is_empty()) return Interval::empty();
  if (a.is_true()) return b;
  if (a.is_false()) return c;
  return hull(b, c);
}
constexpr double select(bool a, double b, double c) { return a ? b : c; }

}  // namespace gesmi
