#include "io/files/mission_digest.h"

#include <algorithm>
#include <span>

#include "io/digest/digest.h"

namespace gesmi::io {

std::string navigation_digest(const Mission& m, DigestKind kind) {
  Digest h(kind);
  for (const auto* v : {&m.time, &m.roll, &m.pitch, &m.heading, &m.vx, &m.vy, &m.vz, &m.altitude, &m.depth, &m.gps_time,
                        &m.gps_longitude, &m.gps_latitude, &m.gps_given_north_halfwidth, &m.gps_given_east_halfwidth})
    h.add(*v);
  for (const NavChannel& c : nav_channels()) h.add(m.half_widths.*c.half_widths);
  h.add(m.origin.latitude);
  h.add(m.origin.longitude);
  h.add(static_cast<double>(m.mine_count));
  return h.hex();
}

std::string bounds_digest(const SensorModel& model, DigestKind kind) {
  Digest h(kind);
  for (const SensorModelField& f : sensor_model_fields()) {
    h.add(f.key);
    h.add(model.*f.member);
  }
  for (const SensorModelChoice& c : sensor_model_choices()) {
    h.add(c.key);
    h.add(c.get(model));
  }
  return h.hex();
}

std::string marks_digest(const Mission& m, std::size_t marks, DigestKind kind) {
  Digest h(kind);
  marks = std::min(marks, m.mark_count());
  h.add(std::span<const double>(m.mark_time.data(), marks));
  h.add(std::span<const std::int32_t>(m.mark_mine.data(), marks));
  h.add(std::span<const double>(m.mark_range.data(), marks));
  h.add(std::span<const std::int32_t>(m.mark_side.data(), marks));
  return h.hex();
}

}  // namespace gesmi::io
