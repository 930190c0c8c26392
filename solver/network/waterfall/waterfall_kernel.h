#pragma once
// The waterfall's cells (sonar_ranges.h) computed in the upward rounding mode
// (waterfall_kernel.cpp, compiled with -frounding-math, as the chain sweeps and the
// sensor kernel): the same operations in the same order as sonar_ranges() and
// SonarPlane::contract, each bound rounded by the hardware instead of by a
// round-to-nearest result and an error test. Directed rounding gives one result for
// each operation, so the cells are those of sonar_ranges() (docs/intervals.md,
// section 9.2; tests/solver/network/waterfall/waterfall_kernel_test.cpp).
//
// What the kernel does not take goes back to the caller, which uses sonar_ranges():
// steps whose angle boxes are too wide for the narrow sin/cos form or whose boxes are
// not finite and moderate (prepare_kernel_step), mines likewise (kernel_takes), and
// pairs where the contractor's stopping test (a change below a micrometre, decided in
// round-to-nearest) cannot be settled from the two directed roundings (`undecided`).

#include <cstdint>
#include <span>

#include "solver/interval/box.h"
#include "solver/mission/sensor_model.h"

namespace gesmi {

/// One step's boxes for the kernel, prepared in round-to-nearest mode.
struct KernelStep {
  double p_lo[3], p_hi[3];  // position box
  double altitude_lo, altitude_hi, frame_slack;
  // Roll, pitch, heading: narrow_angle() (euler.h) of each box.
  double radius[3], sin_lo[3], sin_hi[3], cos_lo[3], cos_hi[3];
};

struct KernelMine {
  double lo[3], hi[3];
};

/// The step's boxes as the kernel wants them; false when it does not take them (an
/// angle box wider than 0.05 rad, a box that is not finite or exceeds kKernelMagnitude).
bool prepare_kernel_step(const Vec3I& position, const Interval& roll, const Interval& pitch, const Interval& heading,
                         const Interval& altitude, double frame_slack, KernelStep& out);
/// Whether the kernel takes this mine box (finite bounds within kKernelMagnitude).
bool kernel_takes(const Vec3I& mine);
/// Bound on the magnitudes the kernel takes: their squares and sums stay finite.
inline constexpr double kKernelMagnitude = 1e100;

struct SonarGeometry {
  double along_tolerance = 0.0, depth_band = 0.0, max_range = 0.0;
  SonarSide sonar_side = SonarSide::both;
};

/// Mine `mine` seen from kernel step `step` (indices into the spans given with it).
struct KernelPair {
  std::uint32_t step, mine;
};

enum class KernelVerdict : std::uint8_t { none, ranges, undecided };

/// A pair's cell: none (the mine cannot appear), the ranges [lo, hi], or undecided
/// (compute it with sonar_ranges()).
struct KernelCell {
  double lo, hi;
  KernelVerdict verdict;
};

/// cells[j] for pairs[j], in the upward rounding mode (the caller's mode is restored).
void kernel_sonar_ranges(const SonarGeometry& geometry, std::span<const KernelStep> steps,
                         std::span<const KernelMine> mines, std::span<const KernelPair> pairs,
                         std::span<KernelCell> cells);

}  // namespace gesmi
