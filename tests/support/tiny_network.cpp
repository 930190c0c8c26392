#include "tests/support/tiny_network.h"

namespace gesmi::test {

TinyNetwork::TinyNetwork(TinyMission t) : tiny(std::move(t)) {
  net = build_network(tiny.mission, tiny.mission.model, tiny.fixes);
  sensor = sensor_domains(tiny.mission, tiny.mission.model);
}

std::vector<std::size_t> TinyNetwork::all_ids() const {
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < net.detections.size() + net.anchors.size(); ++i) ids.push_back(i);
  return ids;
}

}  // namespace gesmi::test
