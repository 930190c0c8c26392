#include "solver/network/mission_network.h"

#include <algorithm>

#include "solver/mission/frame_scale.h"
#include "solver/network/sensors/sensor_priors.h"

namespace gesmi {

namespace {

// Candidate mines of each detection before propagation. A labelled detection has
// its mine. Mines that no detection names are interchangeable, so any solution can
// be relabelled to use them in order of first detection: the r-th unlabelled mine
// can only be taken by an unassociated detection with at least r unassociated
// detections before it. Without this, a '?' could never be decided.
// The allowed sets of detections given in time order by their mines (-1: unknown).
std::vector<std::uint64_t> allowed_in_time_order(int k, const std::vector<int>& mines) {
  std::uint64_t labelled = 0;
  for (const int mine : mines)
    if (mine >= 0) labelled |= std::uint64_t{1} << mine;
  std::vector<int> unlabelled;
  for (int i = 0; i < k; ++i)
    if (!(labelled >> i & 1)) unlabelled.push_back(i);
  std::vector<std::uint64_t> allowed;
  std::size_t earlier = 0;
  for (const int mine : mines) {
    if (mine >= 0) {
      allowed.push_back(std::uint64_t{1} << mine);
      continue;
    }
    std::uint64_t a = labelled;
    for (std::size_t r = 0; r < unlabelled.size() && r <= earlier; ++r) a |= std::uint64_t{1} << unlabelled[r];
    allowed.push_back(a);
    ++earlier;
  }
  return allowed;
}

void assign_allowed_mines(MissionNetwork& net) {
  std::vector<int> mines;
  for (const Detection& d : net.detections) mines.push_back(d.mine);
  const std::vector<std::uint64_t> allowed = allowed_in_time_order(net.mine_count, mines);
  for (std::size_t j = 0; j < net.detections.size(); ++j) net.detections[j].allowed = allowed[j];
}

}  // namespace

std::vector<std::uint64_t> allowed_mines_of_marks(const Mission& mission, std::size_t rows) {
  // The detections' order of build_network: by time, rows in table order among equals.
  rows = std::min(rows, mission.mark_count());
  std::vector<std::size_t> order(rows);
  for (std::size_t j = 0; j < rows; ++j) order[j] = j;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return mission.mark_time[a] < mission.mark_time[b]; });
  std::vector<int> mines;
  for (const std::size_t j : order) mines.push_back(mission.mark_mine[j]);
  const std::vector<std::uint64_t> in_time_order = allowed_in_time_order(mission.mine_count, mines);
  std::vector<std::uint64_t> by_row(rows);
  for (std::size_t n = 0; n < rows; ++n) by_row[order[n]] = in_time_order[n];
  return by_row;
}

std::vector<PositionFix> gps_fixes(const Mission& m) {
  std::vector<PositionFix> fixes;
  for (std::size_t i = 0; i < m.gps_north.size(); ++i) {
    PositionFix f;
    f.time = m.gps_time[i];
    f.box[0] = Interval::around(m.gps_north[i], m.gps_north_halfwidth[i]);
    f.box[1] = Interval::around(m.gps_east[i], m.gps_east_halfwidth[i]);
    f.source_index = i;
    fixes.push_back(f);
  }
  return fixes;
}

MissionNetwork build_network(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes) {
  return build_network(mission, model, fixes, zone_frame(mission), classify_steps(mission, model));
}

MissionNetwork build_network(const Mission& mission, const SensorModel& model, std::span<const PositionFix> fixes,
                             const FrameMargins& frame, const StepRegimes& regimes) {
  const SensorBoxes boxes(mission, model, frame, &regimes);
  MissionNetwork net;
  net.time = mission.time;
  net.mine_count = mission.mine_count;
  for (const PositionFix& fix : fixes) net.anchors.push_back({fix, TimeLocation::locate(mission.time, fix.time, boxes)});
  std::sort(net.anchors.begin(), net.anchors.end(), [](const Anchor& a, const Anchor& b) { return a.fix.time < b.fix.time; });

  for (std::size_t j = 0; j < mission.mark_count(); ++j) {
    Detection d;
    d.mark = j;
    d.time = mission.mark_time[j];
    d.mine = mission.mark_mine[j];
    d.measured_range = mission.mark_range[j];
    d.at = TimeLocation::locate(mission.time, d.time, boxes);
    SonarPlane& plane = d.plane;
    plane.side = mission.mark_side[j] > 0 ? SonarSide::starboard : SonarSide::port;
    double scale = boxes.frame_scale(d.at.k);
    if (d.at.on_grid) {
      plane.attitude = make_attitude(boxes.roll(d.at.k), boxes.pitch(d.at.k), boxes.heading(d.at.k));
      plane.altitude = boxes.altitude(d.at.k);
    } else {
      plane.attitude = boxes.attitude_between(d.at.k);
      plane.altitude = boxes.altitude_between(d.at.k);
      scale = std::max(scale, boxes.frame_scale(d.at.k + 1));
    }
    plane.along_tolerance = model.along_track_tolerance;
    plane.depth_band = model.mine_depth_band;
    d.range = intersect(Interval::around(d.measured_range, model.mark_range), Interval::pos_reals());
    plane.frame_slack = sonar_frame_slack(scale, d.range.hi());
    net.detections.push_back(d);
  }
  std::stable_sort(net.detections.begin(), net.detections.end(),
                   [](const Detection& a, const Detection& b) { return a.time < b.time; });
  assign_allowed_mines(net);
  return net;
}

TubeDomains sensor_domains(const Mission& mission, const SensorModel& model) {
  return sensor_domains_in(frameless_sensor_priors(mission, model, classify_steps(mission, model)), zone_frame(mission));
}

void add_network_priors(TubeDomains& d, const MissionNetwork& network) {
  for (const Anchor& a : network.anchors)
    if (a.at.on_grid) a.at.narrow(d, a.fix.box);  // an empty result is found again by the solver
  d.mines.assign(static_cast<std::size_t>(std::max(network.mine_count, 0)),
                 Vec3I(Interval::entire(), Interval::entire(), Interval::entire()));
  d.candidates.clear();
  for (const Detection& det : network.detections) d.candidates.push_back(det.allowed);
}

void intersect_network_priors(TubeDomains& d, const MissionNetwork& network) {
  for (const Anchor& a : network.anchors)
    if (a.at.on_grid) a.at.narrow(d, a.fix.box);
  for (std::size_t j = 0; j < network.detections.size() && j < d.candidates.size(); ++j)
    d.candidates[j] &= network.detections[j].allowed;
}

TubeDomains initial_domains(const Mission& mission, const SensorModel& model, const MissionNetwork& network) {
  TubeDomains d = sensor_domains(mission, model);
  add_network_priors(d, network);
  return d;
}

}  // namespace gesmi
