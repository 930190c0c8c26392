#include "solver/network/reduced_network.h"

#include <algorithm>

#include "solver/tube/chain_sweep.h"

namespace gesmi {

bool build_reduced_network(const MissionNetwork& full, const TubeDomains& sensor, ReducedNetwork& r) {
  // Event samples: every fix and detection, and the next sample of those between two.
  std::vector<std::size_t> events;
  const auto add = [&](const TimeLocation& at) {
    events.push_back(at.k);
    if (!at.on_grid) events.push_back(at.k + 1);
  };
  for (const Anchor& a : full.anchors) add(a.at);
  for (const Detection& d : full.detections) add(d.at);
  std::sort(events.begin(), events.end());
  events.erase(std::unique(events.begin(), events.end()), events.end());
  const auto event_index = [&](std::size_t k) {
    return static_cast<std::size_t>(std::lower_bound(events.begin(), events.end(), k) - events.begin());
  };

  // The depth tube from the barometer and the vertical increments alone.
  r.depth = sensor.pz;
  r.depth_increments = sensor.dz;
  std::vector<Interval>& z = r.depth;
  std::vector<Interval>& dz = r.depth_increments;
  if (!chain_forward(z, dz).consistent() || !chain_backward(z, dz).consistent()) return false;

  r.time.clear();
  for (const std::size_t k : events) r.time.push_back(full.time[k]);
  r.events = events;
  TubeDomains& d = r.domains;
  const std::size_t e = events.size();
  d.px.assign(e, Interval::entire());
  d.py.assign(e, Interval::entire());
  d.pz.resize(e);
  for (std::size_t i = 0; i < e; ++i) d.pz[i] = z[events[i]];
  const std::size_t steps = e > 0 ? e - 1 : 0;
  d.dx.assign(steps, Interval(0.0));
  d.dy.assign(steps, Interval(0.0));
  d.dz.assign(steps, Interval(0.0));
  for (std::size_t i = 0; i < steps; ++i)
    for (std::size_t k = events[i]; k < events[i + 1]; ++k) {
      d.dx[i] += sensor.dx[k];
      d.dy[i] += sensor.dy[k];
      d.dz[i] += dz[k];
    }

  r.net = MissionNetwork{};
  r.net.time = r.time;
  r.net.mine_count = full.mine_count;
  for (Anchor a : full.anchors) {
    a.at.k = event_index(a.at.k);
    r.net.anchors.push_back(a);
  }
  for (Detection det : full.detections) {
    det.at.k = event_index(det.at.k);
    r.net.detections.push_back(det);
  }
  return true;
}

}  // namespace gesmi
