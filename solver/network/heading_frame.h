#pragma once
// The local frame's north against true north, per sample (docs/model.md, "The local
// frame's north"). The gyrocompass measures heading from true north; the local frame's
// north axis turns against it by the meridian convergence, which grows with the
// distance from the origin. A solve first assumes the largest turn anywhere in the
// frame's zone (Mission::heading_frame_margin, sound wherever the robot is in the
// zone), then bounds the turn per sample over the tube that pass solved, and solves
// again with those narrower margins, intersected with the first enclosure.
//
// The step increments are built once, as if headings were measured in the local
// frame, with each step's sensitivity to a turn: a turn by at most m moves a world
// velocity w by R(m) w - w, whose north component is at most (1 - cos m)|w_n| +
// sin(m)|w_e| <= m²/2 |w_n| + m |w_e| in magnitude (and the east one symmetrically),
// so the increment with margin m lies in the frameless one widened by those amounts
// times the step's integrated |w| (SensorPriors::turn_north and turn_east).

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

/// The margin added to the heading box at each sample (rad): per_sample[k] when given
/// (one per sample), the uniform margin otherwise.
struct HeadingFrame {
  double uniform = 0.0;
  std::span<const double> per_sample;
  double at(std::size_t k) const { return per_sample.empty() ? uniform : per_sample[k]; }
};

/// The mission's own frame: its uniform zone-wide margin.
inline HeadingFrame zone_frame(const Mission& mission) { return HeadingFrame{mission.heading_frame_margin, {}}; }

/// The sensor domains without any heading frame margin, and per step the integral of
/// the magnitude of the north and east world velocities under the step model (m),
/// rounded up: a turn by at most m widens the step's north increment by
/// m turn_east + m²/2 turn_north (and the east one symmetrically).
struct SensorPriors {
  std::vector<Interval> depth;       // the depth boxes (pz), which no frame changes
  std::vector<Interval> dx, dy, dz;  // the increments without frame margin

  std::vector<float> turn_north, turn_east;
  /// Steps whose trapezoid and rate hull did not meet (SensorBoxes::StepTurn): the
  /// hull, which the turned increment is intersected with. In step order; rare.
  std::vector<std::pair<std::size_t, Vec3I>> apart_hulls;
};

SensorPriors frameless_sensor_priors(const Mission& mission, const SensorModel& model);

/// The sensor domains under `frame`: each step's increments widened by the turn of the
/// larger margin of its two samples; positions unbounded but for depth; no mines.
TubeDomains sensor_domains_in(const SensorPriors& priors, const HeadingFrame& frame);
/// The same, moving the depth boxes and vertical increments out of `priors` (no frame
/// changes them) instead of copying them: what a solve does with its first pass, so
/// that the largest memory of the solve holds one copy. The priors keep dx, dy and the
/// turns; narrow_to_frame() then leaves dz as it is.
TubeDomains take_sensor_domains(SensorPriors& priors, const HeadingFrame& frame);
/// In place: d's increments intersected with those of sensor_domains_in(priors, frame),
/// for domains that already enclose the solution under a looser frame (no copy); dz
/// too unless the priors released it.
void narrow_to_frame(TubeDomains& d, const SensorPriors& priors, const HeadingFrame& frame);

/// Per-sample margins over a tube that contains the truth: the convergence within the
/// farthest point from the origin the robot can reach while in the boxes of the
/// sample's two steps, never above the zone's margin. Empty when the mission's margin
/// is zero (a mission without geodesy).
/// `max_speed` bounds |v| at any instant (speed_bound(), computed by the second form).
std::vector<double> heading_margins_over(const Mission& mission, const TubeDomains& tube, double max_speed);
std::vector<double> heading_margins_over(const Mission& mission, const TubeDomains& tube);

/// The largest |v| (m/s) the DVL boxes allow at any instant: at the samples, plus what
/// max_acceleration adds within the longest step on each axis.
double speed_bound(const Mission& mission);

}  // namespace gesmi
