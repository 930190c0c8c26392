#pragma once
// The horizontal displacement over a run of steps, affine in the biases (structured_errors.h).
//
// With the heading bias beta and the noise n, the heading is psi_read - n - beta, so
// R = Rz(-beta) Q with Q = Rz(psi_read - n) Ry(theta) Rx(phi) (rotations about one axis
// commute), and the world velocity is w = Rz(-beta) (U - sum_a Q e_a (s_a v_a + o_a)),
// U = Q (v_read - n') enclosed by the noise's boxes. A submerged step adds dt/2 (w_k +
// w_k+1) plus the trapezoid's remainder; every other step (surface, readings that
// contradict the jerk bound) adds the per-sample model's increment whole. Summed over
// the run, Y = C - sum_a (K_a s_a + L_a o_a), and
//   Rz(-beta) Y = Y + beta J Y + (cos beta - 1) Y + (sin beta - beta) J Y,  J (n, e) = (e, -n),
// affine in (beta, s, o) around the midpoints of C, K_a, L_a, with every other part
// (the sums' widths, the products of biases, the rotation's higher terms) enclosed in
// an interval rest.

#include <array>
#include <cstddef>

#include "solver/interval/interval.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/structured/structured_errors.h"

namespace gesmi {

/// d in value + sum_t coefficient[t] z_t + rest for every bias z within its bounds,
/// per horizontal axis (0 north, 1 east).
struct AffineDisplacement {
  std::array<double, 2> value{};
  std::array<std::array<double, kBiasTerms>, 2> coefficient{};
  std::array<Interval, 2> rest{Interval(0.0), Interval(0.0)};
};

/// Enclosures of cos(b) - 1 and sin(b) - b for every |b| <= bound: [-bound^2/2, 0] and
/// [-bound^3/6, bound^3/6] (alternating Taylor series), rounded outward.
struct SmallAngleRests {
  Interval cos_minus_one, sin_minus_angle;
};
SmallAngleRests small_angle_rests(double bound);

/// The sums over a run of steps, in either direction, from which its displacement's
/// affine form follows.
class StepSums {
 public:
  /// `noise`: the noise's boxes (StructuredErrors::noise); `whole`: the per-sample
  /// model's boxes with the mission's regimes, for the steps the form does not cover.
  /// All three must outlive this object.
  StepSums(const Mission& mission, const SensorBoxes& noise, const SensorBoxes& whole)
      : mission_(mission), noise_(noise), whole_(whole) {
    clear();
  }

  void clear();
  /// Adds step k (from sample k to k + 1).
  void add_step(std::size_t k);
  /// The displacement over the steps added (p_end - p_start of the run).
  AffineDisplacement form(const std::array<double, kBiasTerms>& bias_bound) const;

 private:
  const Mission& mission_;
  const SensorBoxes& noise_;
  const SensorBoxes& whole_;
  using Pair = std::array<Interval, 2>;  // north, east
  Pair c_;
  std::array<Pair, 3> k_, l_;  // per body axis
  Pair outside_;               // trapezoid rests and whole steps, outside the rotation
};

}  // namespace gesmi
