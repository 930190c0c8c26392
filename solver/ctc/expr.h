#pragma once
// Expressions over the variables of a box, built with ordinary operators:
//   Expr x = Expr::var(0), y = Expr::var(1);
//   Expr d = sqrt(sqr(x - 40.0) + sqr(y - 60.0));
// They are compiled into a flat tape by CtcFwdBwd (forward-backward contraction,
// HC4-revise) and can be evaluated on intervals with eval().

#include <memory>
#include <vector>

#include "solver/interval/box.h"

namespace gesmi {

enum class ExprOp {
  variable, constant, add, sub, mul, div, neg, sqr, sqrt, pow, exp, log, sin, cos, tan, atan, atan2, abs, min, max
};

class Expr {
 public:
  struct Node {
    ExprOp op;
    std::shared_ptr<const Node> a, b;
    Interval value;      // constant
    int index = 0;       // variable index, or exponent for pow
  };

  static Expr var(int index);
  static Expr constant(const Interval& value);
  Expr(double value) : Expr(constant(Interval(value))) {}  // NOLINT: lets 2.0 * x compile
  Expr(const Interval& value) : Expr(constant(value)) {}   // NOLINT

  const std::shared_ptr<const Node>& node() const { return node_; }
  /// Largest variable index used, plus one.
  int variable_count() const;

  static Expr make(ExprOp op, const Expr& a);
  static Expr make(ExprOp op, const Expr& a, const Expr& b);
  static Expr make_pow(const Expr& a, int n);

 private:
  explicit Expr(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
  std::shared_ptr<const Node> node_;
};

inline Expr operator+(const Expr& a, const Expr& b) { return Expr::make(ExprOp::add, a, b); }
inline Expr operator-(const Expr& a, const Expr& b) { return Expr::make(ExprOp::sub, a, b); }
inline Expr operator*(const Expr& a, const Expr& b) { return Expr::make(ExprOp::mul, a, b); }
inline Expr operator/(const Expr& a, const Expr& b) { return Expr::make(ExprOp::div, a, b); }
inline Expr operator-(const Expr& a) { return Expr::make(ExprOp::neg, a); }
inline Expr sqr(const Expr& a) { return Expr::make(ExprOp::sqr, a); }
inline Expr sqrt(const Expr& a) { return Expr::make(ExprOp::sqrt, a); }
inline Expr pow(const Expr& a, int n) { return Expr::make_pow(a, n); }
inline Expr exp(const Expr& a) { return Expr::make(ExprOp::exp, a); }
inline Expr log(const Expr& a) { return Expr::make(ExprOp::log, a); }
inline Expr sin(const Expr& a) { return Expr::make(ExprOp::sin, a); }
inline Expr cos(const Expr& a) { return Expr::make(ExprOp::cos, a); }
inline Expr tan(const Expr& a) { return Expr::make(ExprOp::tan, a); }
inline Expr atan(const Expr& a) { return Expr::make(ExprOp::atan, a); }
inline Expr atan2(const Expr& y, const Expr& x) { return Expr::make(ExprOp::atan2, y, x); }
inline Expr abs(const Expr& a) { return Expr::make(ExprOp::abs, a); }
inline Expr min(const Expr& a, const Expr& b) { return Expr::make(ExprOp::min, a, b); }
inline Expr max(const Expr& a, const Expr& b) { return Expr::make(ExprOp::max, a, b); }

/// Interval evaluation of e on a box (natural inclusion function).
Interval eval(const Expr& e, const Box& box);

}  // namespace gesmi
