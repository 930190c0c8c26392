#include "solver/mission/mission.h"

#include <algorithm>
#include <stdexcept>

namespace gesmi {

const std::array<NavChannel, 8>& nav_channels() {
  static const std::array<NavChannel, 8> channels = {{
      {"roll", &Mission::roll, &NavHalfWidths::roll},
      {"pitch", &Mission::pitch, &NavHalfWidths::pitch},
      {"heading", &Mission::heading, &NavHalfWidths::heading},
      {"vx", &Mission::vx, &NavHalfWidths::vx},
      {"vy", &Mission::vy, &NavHalfWidths::vy},
      {"vz", &Mission::vz, &NavHalfWidths::vz},
      {"altitude", &Mission::altitude, &NavHalfWidths::altitude},
      {"depth", &Mission::depth, &NavHalfWidths::depth},
  }};
  return channels;
}

const NavChannel& nav_channel(std::string_view name) {
  for (const NavChannel& c : nav_channels())
    if (c.name == name) return c;
  throw std::logic_error("no navigation channel " + std::string(name));
}

double model_half_width(const SensorModel& model, std::size_t channel, double value) {
  const auto bounds = nav_channels()[channel].half_widths;
  if (bounds == &NavHalfWidths::roll) return model.roll;
  if (bounds == &NavHalfWidths::pitch) return model.pitch;
  if (bounds == &NavHalfWidths::heading) return model.heading;
  if (bounds == &NavHalfWidths::altitude) return model.altitude;
  if (bounds == &NavHalfWidths::depth) return depth_bound(model, value);
  return dvl_bound(model, value);  // vx, vy, vz
}

std::optional<std::size_t> longest_gap(const std::vector<double>& time) {
  if (time.size() < 2) return std::nullopt;
  std::vector<double> steps(time.size() - 1);
  std::size_t longest = 0;
  for (std::size_t k = 0; k + 1 < time.size(); ++k) {
    steps[k] = time[k + 1] - time[k];
    if (steps[k] > steps[longest]) longest = k;
  }
  const double step = steps[longest];
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
  if (step > 2.0 * steps[steps.size() / 2]) return longest;
  return std::nullopt;
}

}  // namespace gesmi
