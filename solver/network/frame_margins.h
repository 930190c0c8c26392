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
//
// The step increments are built once, as if headings were measured in the local
// frame and the frame kept distances, with each step's sensitivities: a turn by at
// most m moves a world velocity w by R(m) w - w, whose north component is at most
// (1 - cos m)|w_n| + sin(m)|w_e| <= m²/2 |w_n| + m |w_e| in magnitude (and the east
// one symmetrically); a scale error of at most s moves it by at most s |w_h| <=
// s (|w_n| + |w_e|) on each horizontal axis (the turn keeps |w_h|). So the increment
// under the margins lies in the frameless one widened by those amounts times the
// step's integrated |w| (SensorPriors::turn_north and turn_east).

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/step_regimes.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

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

/// The sensor domains without any frame margin (but the depth's), and per step the
/// integral of the magnitude of the north and east world velocities under the step
/// model (m), rounded up: a turn by at most m widens the step's north increment by
/// m turn_east + m²/2 turn_north (and the east one symmetrically), a scale error by at
/// most s widens both by s (turn_north + turn_east).
struct SensorPriors {
  std::vector<Interval> depth;       // the depth boxes (pz), which no frame changes
  std::vector<Interval> dx, dy, dz;  // the increments without frame margin

  std::vector<float> turn_north, turn_east;
  /// Steps whose trapezoid and rate hull did not meet (SensorBoxes::StepTurn): the
  /// hull, which the turned increment is intersected with. In step order; rare.
  std::vector<std::pair<std::size_t, Vec3I>> apart_hulls;
};

/// Each step under its regime (`regimes`, of the same mission and model: classify_steps()).
SensorPriors frameless_sensor_priors(const Mission& mission, const SensorModel& model, const StepRegimes& regimes);

/// The sensor domains under `frame`: each step's increments widened by the turn and the
/// scale of the larger margins of its two samples; positions unbounded but for depth; no
/// mines.
TubeDomains sensor_domains_in(const SensorPriors& priors, const FrameMargins& frame);
/// The same, moving the depth boxes and vertical increments out of `priors` (no frame
/// changes them) instead of copying them: what a solve does with its first pass, so
/// that the largest memory of the solve holds one copy. The priors keep dx, dy and the
/// turns; narrow_to_frame() then leaves dz as it is.
TubeDomains take_sensor_domains(SensorPriors& priors, const FrameMargins& frame);
/// In place: d's increments intersected with those of sensor_domains_in(priors, frame),
/// for domains that already enclose the solution under a looser frame (no copy); dz
/// too unless the priors released it.
void narrow_to_frame(TubeDomains& d, const SensorPriors& priors, const FrameMargins& frame);

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
