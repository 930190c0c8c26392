#pragma once
// Sensor errors as a bias that stays the same over the mission plus a noise. With a bias
// share F of a channel's bound B, its reading error is b + n(k) with |b| <= F B and
// |n(k)| <= (1 - F) B:
//  - heading: psi_read = psi + beta + n, |beta| <= F heading;
//  - DVL, per body axis a: v_read = v + s_a v + o_a + n, |s_a| <= F dvl_relative,
//    |o_a| <= F dvl_absolute (a scale of the true speed and an offset).
// Written on the reading, v = v_read - (s_a v_read + o_a) - n', and n' = n - s_a (v_read - v)
// carries the scale's share of the error too: |n'| <= (1 - F + F dvl_relative) B.
// The other channels keep their per-sample bounds.

#include <array>
#include <cstddef>

#include "solver/mission/sensor_model.h"

namespace gesmi {

/// The global unknowns' order: the heading bias beta, then the DVL scale biases s_x,
/// s_y, s_z and offset biases o_x, o_y, o_z.
inline constexpr std::size_t kBiasTerms = 7;
enum BiasTerm : std::size_t { kHeadingBias = 0, kScaleBias = 1, kOffsetBias = 4 };

struct StructuredErrors {
  /// The largest |bias| of each global unknown, in BiasTerm order (rad, 1, m/s).
  std::array<double, kBiasTerms> bias_bound{};
  /// The model with the noise's bounds: what is left of each structured bound per sample.
  SensorModel noise;
};

/// The split of every structured channel's bound by one bias share F in [0, 1]; each
/// part rounded up, so that the bias and the noise together cover the whole bound.
/// std::invalid_argument for a share outside [0, 1].
StructuredErrors split_by_bias_share(const SensorModel& model, double share);

}  // namespace gesmi
