#pragma once
// One cell of the reconstructed waterfall (waterfall.h) in portable interval arithmetic:
// the slant ranges at which a mine box can appear on the sonar record from a position
// box. The waterfall's kernel (waterfall_kernel.h) computes the same cells faster and
// hands back to this one what it does not take.

#include "solver/network/sonar_plane.h"

namespace gesmi {

/// The ranges within [0, max_range] at which mine box m can lie in `plane` (its side is
/// ignored) seen from position box p, on the sides `sonar_side` looks to, or empty: the
/// rough body offset first, then SonarPlane::contract on each side whose prior it meets,
/// the hull of both.
Interval sonar_ranges(const SonarPlane& plane, const Vec3I& p, const Vec3I& m, SonarSide sonar_side, double max_range);

}  // namespace gesmi
