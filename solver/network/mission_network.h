#pragma once
// The constraint network of a mission (seed 001, sections II and IV): the evolution
// p(k+1) = p(k) + d(k) with d(k) enclosing the integral of R v over the step, the
// barometer depth, the GPS fixes and the sonar detections. The per-step parts live
// in TubeDomains (the priors of positions and increments); this holds the sparse
// constraints.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/network/detection.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/network/tube_domains.h"

namespace gesmi {

/// A position fix in the local frame: GPS at the surface after geodesy, or a
/// position box from a log. Axes without information are the whole line.
struct PositionFix {
  double time = 0.0;
  Vec3I box = Vec3I(Interval::entire(), Interval::entire(), Interval::entire());
  std::size_t source_index = 0;  // row in the mission's GPS table
};

/// The mission's GPS fixes as local boxes (io/ fills gps_north/east and their
/// half-widths from the longitudes and latitudes).
std::vector<PositionFix> gps_fixes(const Mission& mission);

struct Anchor {
  PositionFix fix;
  TimeLocation at;
};

struct MissionNetwork {
  std::span<const double> time;       // the mission's time grid (the mission outlives the network)
  std::vector<Anchor> anchors;        // in time order
  std::vector<Detection> detections;  // every detection, in time order
  int mine_count = 0;                 // K <= kMaxMines (mission.h)
};

/// Builds the sparse constraints. A mark with mine -1 is a disjunction over the
/// mines (seed 001 VI-4); mine_count must exceed every mine number and be <= kMaxMines.
/// The detections (heading, DVL boxes and horizontal slack) and the offsets between
/// samples take the mission's zone-wide frame margins, or `frame`'s per-sample ones.
/// The offsets take each step's regime (`regimes`; the first form classifies the steps
/// itself).
MissionNetwork build_network(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes);
MissionNetwork build_network(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                             const FrameMargins& frame, const StepRegimes& regimes);
/// The mines each of the first `rows` marks may belong to (bit i: mine i) in a network
/// of those marks alone: the allowed sets build_network() gives their detections.
std::vector<std::uint64_t> allowed_mines_of_marks(const Mission& mission, std::size_t rows);

/// The prior domains: increments from the sensors, depth from the barometer,
/// fixes on sample times, unbounded elsewhere; mines unbounded; each detection's
/// candidate mines.
TubeDomains initial_domains(const Mission& mission, const SensorModel& model, const MissionNetwork& network);

/// The two halves of initial_domains: what the sensors give (increments and depth, each
/// step under its regime, under the mission's zone-wide frame margins; sensor_priors.h builds them for
/// per-sample margins), which does not depend on the fixes and marks, and the network's own priors
/// (fixes on sample times, unbounded mines, candidate mines).
TubeDomains sensor_domains(const Mission& mission, const SensorModel& model);
void add_network_priors(TubeDomains& domains, const MissionNetwork& network);
/// The same priors intersected into domains that already enclose the solution (the
/// mines are left as they are, the candidates narrowed): no copy of the domains.
void intersect_network_priors(TubeDomains& domains, const MissionNetwork& network);

}  // namespace gesmi
