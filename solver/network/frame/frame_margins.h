#pragma once
// The local frame's margins per sample (docs/model.md, "The local frame's north" and
// "The local frame's scale"). The gyrocompass measures heading from true north, and
// the local frame's north axis turns against it by the meridian convergence; the DVL
// measures speeds along the surface, which the frame's plane shrinks by its scale
// error. Both grow with the distance from the origin. A solve first takes them at the
// farthest the robot can be from its GPS fixes (or anywhere in the frame's zone when
// the fixes may be wrong), then bounds them per sample over the tube that pass
// solved, and solves again with those narrower margins, intersected with the first
// enclosure.

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

/// x rounded up to a float (infinity beyond the float range, or for NaN): a bound kept
/// at half the memory (the per-sample margins, the steps' turn sensitivities).
inline float float_up(double x) {
  if (!(x <= std::numeric_limits<float>::max())) return std::numeric_limits<float>::infinity();
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

/// A margin at each sample: per_sample[k] when given (one per sample; floats rounded up,
/// which keeps them bounds at half the memory), the uniform margin otherwise.
struct SampleMargins {
  double uniform = 0.0;
  std::span<const float> per_sample;
  double at(std::size_t k) const { return per_sample.empty() ? uniform : per_sample[k]; }
};

/// The local frame's margins at each sample: the heading's turn (rad), added to the
/// heading box, and the frame's relative scale error, added to the DVL boxes (besides
/// Mission::depth_scale_margin) and to a mark's horizontal offset.
struct FrameMargins {
  SampleMargins heading, scale;
};

/// The mission's own margins: its uniform zone-wide ones.
inline FrameMargins zone_frame(const Mission& mission) {
  return FrameMargins{{mission.heading_frame_margin, {}}, {mission.frame_scale_margin, {}}};
}

/// Whether the mission has a frame to take margins for (geodesy; not a flat world).
inline bool has_frame_margins(const Mission& mission) {
  return mission.heading_frame_margin != 0.0 || mission.frame_scale_margin != 0.0;
}

/// Per-sample margins, owned; empty when the mission has no frame (no geodesy).
struct FrameMarginValues {
  std::vector<float> heading, scale;
  /// The farthest distance (m) at which the margins exceeded the zone's and were capped
  /// at them (0: nowhere; infinite where a box is unbounded): there the margins rest on
  /// the robot having stayed in the frame's zone, which the data did not show.
  double beyond_zone = 0.0;
  /// Margins that read these values (which must outlive them).
  FrameMargins view(const Mission& mission) const {
    return FrameMargins{{mission.heading_frame_margin, heading}, {mission.frame_scale_margin, scale}};
  }
};

/// Per-sample margins within the farthest point from the origin the robot can reach
/// while in the boxes of the sample's two steps of a tube that contains the truth,
/// never above the zone's margins.
/// Empty when the mission has no frame margins.
/// `max_speed` bounds |v| at any instant (speed_bound(), computed by the second form).
FrameMarginValues frame_margins_over(const Mission& mission, const TubeDomains& tube, double max_speed);
FrameMarginValues frame_margins_over(const Mission& mission, const TubeDomains& tube);

/// For a caller that reads the margins of a few samples only (the waterfall: the steps
/// with a mine in reach): every sample at the zone's margins as stored, which no sample
/// of frame_margins_over() exceeds; empty when the mission has no frame margins ...
FrameMarginValues zone_margin_values(const Mission& mission, std::size_t samples);
/// ... then at the samples `wanted` marks (one flag per sample of `tube`), the values
/// frame_margins_over(mission, tube, max_speed) gives them, in place (a view of
/// `margins` stays valid); beyond_zone over those samples only.
void narrow_margins_over(FrameMarginValues& margins, const Mission& mission, const TubeDomains& tube, double max_speed,
                         std::span<const unsigned char> wanted);

/// Per-sample margins before any solve, from the GPS fixes alone: at time t the robot
/// is at most max_speed |t - t_i| farther than the farthest point of fix i's box. For
/// fixes that are true (not while some may be outliers). Empty when the mission has no
/// frame margins.
FrameMarginValues frame_margins_from_fixes(const Mission& mission, double max_speed);

/// How far a turn by at most `turn` and a scale error by at most `scale` move one
/// horizontal component of a velocity or an increment, rounded up: turn times the other
/// component's magnitude, plus turn²/2 times its own, plus scale times both.
double frame_widening(double turn, double scale, double other, double own);

/// The largest |v| (m/s) the DVL boxes allow at any instant: at the samples, plus what
/// max_acceleration adds within the longest step on each axis.
double speed_bound(const Mission& mission);

}  // namespace gesmi
