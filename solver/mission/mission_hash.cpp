#include "solver/mission/mission_hash.h"

#include <cstdint>
#include <span>

namespace gesmi {
namespace {

class Fnv1a {
 public:
  template <class T>
  void add(std::span<const T> values) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (std::size_t i = 0; i < values.size_bytes(); ++i) {
      hash_ ^= bytes[i];
      hash_ *= 0x100000001b3ULL;
    }
  }
  template <class T>
  void add(const std::vector<T>& v) {
    add(std::span<const T>(v));
  }
  void add(double x) { add(std::span<const double>(&x, 1)); }
  std::string hex() const {
    static const char digits[] = "0123456789abcdef";
    std::string out(16, '0');
    for (int i = 0; i < 16; ++i) out[static_cast<std::size_t>(i)] = digits[(hash_ >> (60 - 4 * i)) & 0xf];
    return out;
  }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace

std::string navigation_hash(const Mission& m) {
  Fnv1a h;
  for (const auto* v : {&m.time, &m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz, &m.altitude, &m.depth, &m.gps_time,
                        &m.gps_longitude, &m.gps_latitude, &m.gps_given_north_halfwidth, &m.gps_given_east_halfwidth})
    h.add(*v);
  for (const auto* v : {&m.half_widths.roll, &m.half_widths.pitch, &m.half_widths.heading, &m.half_widths.vx,
                        &m.half_widths.vy, &m.half_widths.vz, &m.half_widths.depth, &m.half_widths.altitude})
    h.add(*v);
  h.add(m.origin.latitude);
  h.add(m.origin.longitude);
  h.add(static_cast<double>(m.mine_count));
  return h.hex();
}

std::string bounds_hash(const SensorModel& model) {
  Fnv1a h;
  for (const double x : {model.dvl_relative, model.dvl_absolute, model.roll, model.pitch, model.heading,
                         model.depth_absolute, model.depth_relative, model.altitude, model.gps_lon_deg,
                         model.gps_lat_deg, model.gps_metres, model.mark_range, model.mine_depth_band,
                         model.sonar_max_range, model.along_track_tolerance, model.max_attitude_rate,
                         model.max_acceleration, static_cast<double>(static_cast<int>(model.sonar_side))})
    h.add(x);
  return h.hex();
}

std::string marks_hash(const Mission& m, std::size_t marks) {
  Fnv1a h;
  marks = std::min(marks, m.mark_count());
  h.add(std::span<const double>(m.mark_time.data(), marks));
  h.add(std::span<const std::int32_t>(m.mark_mine.data(), marks));
  h.add(std::span<const double>(m.mark_range.data(), marks));
  h.add(std::span<const std::int32_t>(m.mark_side.data(), marks));
  return h.hex();
}

}  // namespace gesmi
