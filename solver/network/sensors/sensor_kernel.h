#pragma once
// The sensor enclosures of the trapezoid and sample step models, computed in blocks of
// samples in the upward rounding mode (sensor_kernel.cpp, compiled with -frounding-math,
// as the chain sweeps): branch-free interval products on flat arrays that the compiler
// vectorises over samples, one libm sin and cos per angle and sample (the narrow-angle
// form of sin_cos in euler.h). Same enclosures as SensorBoxes, without a heading frame
// margin, to within rounding (tests/solver/network/sensors/sensor_kernel_test.cpp).
//
// Samples or steps the kernel does not take are returned to the caller, which computes
// them with SensorBoxes: an angle box wider than the narrow-angle form allows (0.05 rad)
// or a reading that is not finite, the trapezoid steps whose rate hull must be
// intersected too (SensorBoxes::step_increment: max_jerk dt > 6 max_acceleration), and
// the steps of another regime than the submerged one (step_regimes.h).

#include <cstddef>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/mission/mission.h"
#include "solver/network/sensors/step_regimes.h"

namespace gesmi {

/// World-frame velocity boxes R v of consecutive samples, one array per bound:
/// component i of sample j lies in [-neg_lo[i][j], hi[i][j]].
struct WorldVelocityBoxes {
  std::vector<double> neg_lo[3], hi[3];
  /// Samples (mission indices) the kernel left to SensorBoxes; their entries are
  /// meaningless.
  std::vector<std::size_t> skipped;
};

/// The boxes R v of samples [first, last) of the mission, without heading frame margin.
void world_velocity_boxes(const Mission& mission, const SensorModel& model, std::size_t first, std::size_t last,
                          WorldVelocityBoxes& out);

/// Where the step enclosures go, indexed by the mission's step index k (the arrays cover
/// every step): the increments and their sensitivities to a heading turn
/// (SensorBoxes::StepTurn), rounded up to float.
struct StepIncrementArrays {
  Interval* dx;
  Interval* dy;
  Interval* dz;
  float* turn_north;
  float* turn_east;
};

/// The increments of steps [first, last) under the model's step model (trapezoid or
/// sample; not rate_hull), without heading frame margin. Returns the steps it left to
/// SensorBoxes, in increasing order; their entries in `out` are meaningless.
std::vector<std::size_t> kernel_step_increments(const Mission& mission, const SensorModel& model, std::size_t first,
                                                std::size_t last, const StepIncrementArrays& out,
                                                const StepRegimes& regimes);

/// The depth box of every sample, bit for bit SensorBoxes::depth's (the same correctly
/// rounded bounds, from the upward rounding mode instead of software rounding): the
/// reading ± the sample's own half-width, or ± (depth_absolute + depth_relative |depth|).
/// `out` holds mission.size() boxes.
void depth_boxes(const Mission& mission, const SensorModel& model, Interval* out);

}  // namespace gesmi
