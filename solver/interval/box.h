#pragma once
// Intervals inside Eigen: Interval is registered as an Eigen scalar so that small
// fixed-size vectors and matrices of intervals (rotations, 3-D increments) use
// Eigen's products. Only +, - and products are meaningful on interval matrices:
// no decompositions, norms or comparisons. Time series do not use Eigen: they are
// flat arrays of Interval (docs/architecture.md).

#include <Eigen/Core>
#include <vector>

#include "solver/interval/interval.h"

namespace gesmi {

// Functions Eigen looks up in the scalar's namespace.
inline const Interval& conj(const Interval& x) { return x; }
inline const Interval& real(const Interval& x) { return x; }
inline Interval imag(const Interval&) { return Interval(0.0); }
inline Interval abs2(const Interval& x) { return sqr(x); }

template <class T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <class T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
using Vec2I = Vec2<Interval>;
using Vec3I = Vec3<Interval>;
using Mat3I = Mat3<Interval>;
using Vec2d = Vec2<double>;
using Vec3d = Vec3<double>;
using Mat3d = Mat3<double>;

/// A box of any dimension: the domains of a small problem (tens of variables).
using Box = std::vector<Interval>;

/// A box is empty when any of its components is.
inline bool is_empty(const Box& box) {
  for (const Interval& x : box)
    if (x.is_empty()) return true;
  return false;
}
/// Makes every component empty when one is (the normal form of an empty box).
inline void normalize_empty(Box& box) {
  if (is_empty(box))
    for (Interval& x : box) x = Interval::empty();
}
/// Largest component width (0 for an empty box).
inline double max_width(const Box& box) {
  double w = 0.0;
  for (const Interval& x : box)
    if (!x.is_empty()) w = std::max(w, x.width());
  return w;
}

}  // namespace gesmi

namespace Eigen {

template <>
struct NumTraits<gesmi::Interval> : GenericNumTraits<gesmi::Interval> {
  using Real = gesmi::Interval;
  using NonInteger = gesmi::Interval;
  using Nested = gesmi::Interval;
  using Literal = gesmi::Interval;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 2,
    AddCost = 4,
    MulCost = 8,
  };
  static inline Real epsilon() { return gesmi::Interval(std::numeric_limits<double>::epsilon()); }
  static inline Real dummy_precision() { return gesmi::Interval(1e-12); }
  static inline int digits10() { return std::numeric_limits<double>::digits10; }
};

// Eigen's squaredNorm and norm square through abs2_impl, whose default is x * x;
// sqr is tighter on intervals that contain 0 (x * x of [-1, 3] is [-3, 9]).
namespace internal {
template <>
struct abs2_impl<gesmi::Interval> {
  static gesmi::Interval run(const gesmi::Interval& x) { return gesmi::sqr(x); }
};
}  // namespace internal

template <class BinaryOp>
struct ScalarBinaryOpTraits<gesmi::Interval, double, BinaryOp> {
  using ReturnType = gesmi::Interval;
};
template <class BinaryOp>
struct ScalarBinaryOpTraits<double, gesmi::Interval, BinaryOp> {
  using ReturnType = gesmi::Interval;
};

}  // namespace Eigen
