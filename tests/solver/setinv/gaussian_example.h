#pragma once
// Seed 004, Example 2, shared by the set-inversion tests: the Gaussian density at
// t_i = 1..6 with interval data, on the frame [-2, 8] x [0, 3], and phi at a point
// computed in plain doubles (the formula written again, not the interval code).

#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "solver/interval/box.h"
#include "solver/setinv/datum_tests.h"
#include "solver/setinv/paving.h"

namespace gesmi::test {

struct GaussianDensity {
  std::size_t output_count() const { return 6; }
  template <class T>
  void operator()(std::span<const T> p, std::span<T> y) const {
    for (std::size_t i = 0; i < 6; ++i) {
      const double t = static_cast<double>(i + 1);
      y[i] = exp(-sqr(t - p[0]) / (2.0 * p[1])) / sqrt(2.0 * std::numbers::pi * p[1]);
    }
  }
};

inline const Box& gaussian_data() {
  static const Box y{Interval(0, 0.2), Interval(0.3, 2), Interval(0.3, 2),
                     Interval(0.1, 0.2), Interval(0.4, 2), Interval(-1, 0.1)};
  return y;
}
inline const Box& gaussian_frame() {
  static const Box frame{Interval(-2, 8), Interval(0, 3)};
  return frame;
}

/// phi(p): the data whose bounds the density at p misses (p2 > 0).
inline std::vector<std::size_t> gaussian_phi(double p1, double p2) {
  static const double lo[6] = {0, 0.3, 0.3, 0.1, 0.4, -1}, hi[6] = {0.2, 2, 2, 0.2, 2, 0.1};
  std::vector<std::size_t> phi;
  for (std::size_t i = 0; i < 6; ++i) {
    const double t = static_cast<double>(i + 1);
    const double f = std::exp(-(t - p1) * (t - p1) / (2.0 * p2)) / std::sqrt(2.0 * std::numbers::pi * p2);
    if (f < lo[i] || f > hi[i]) phi.push_back(i);
  }
  return phi;
}

/// Whether the point (x, y) lies in the first two components of the box.
inline bool point_in(std::span<const Interval> box, double x, double y) {
  return box[0].contains(x) && box[1].contains(y);
}

/// Whether the point (x, y) lies in a box of the paving.
inline bool in_paving(const Paving& paving, double x, double y) {
  for (std::size_t i = 0; i < paving.size(); ++i)
    if (point_in(paving.box(i), x, y)) return true;
  return false;
}

}  // namespace gesmi::test
