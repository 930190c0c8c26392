#pragma once
// The sensor domains of a solve before any frame margin (the sensor priors), and the
// same domains under the local frame's margins (frame_margins.h).
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
#include <utility>
#include <vector>

#include "solver/interval/box.h"
#include "solver/mission/mission.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/step_regimes.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

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

}  // namespace gesmi
