#include "io/geodesy.h"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/format_error.h"
#include "io/text/csv_number.h"
#include "solver/interval/rounding.h"
#include "solver/mission/frame_scale.h"
#include "solver/mission/meridian_convergence.h"
#include "solver/network/frame/frame_margins.h"

namespace gesmi::io {

std::string fix_beyond_zone(double distance) {
  return "the fix is " + format_number(std::round(distance)) + " m from the origin, beyond the " +
         format_number(kLocalFrameZone / 1000.0) +
         " km zone of the local frame: import the log again with an origin nearer the mission (--origin LAT,LON)";
}

LocalFrame::LocalFrame(const GeoOrigin& origin) : origin_(origin), plane_(origin.latitude, origin.longitude, 0.0) {}

NorthEast LocalFrame::to_local(double latitude, double longitude) const {
  const GeographicLib::LocalCartesian& frame = plane_;
  double east = 0, north = 0, up = 0;
  frame.Forward(latitude, longitude, 0.0, east, north, up);
  return {north, east};
}

GeoOrigin LocalFrame::to_geodetic(double north, double east) const {
  const GeographicLib::LocalCartesian& frame = plane_;
  // The inverse of to_local: the sea-surface point whose projection on the tangent
  // plane is (north, east). That point lies below the plane by about d^2 / 2R, and
  // taking the surface point under (north, east, 0) along its own normal instead
  // would shift it by about d^3 / 2R^2 (12 m at 100 km). Solve for its height in the
  // plane's frame: each pass reduces the error by a factor near (d / R)^2.
  double lat = 0, lon = 0, h = 0, up = 0;
  for (int pass = 0; pass < 3; ++pass) {
    frame.Reverse(east, north, up, lat, lon, h);
    double e = 0, n = 0;
    frame.Forward(lat, lon, 0.0, e, n, up);
  }
  frame.Reverse(east, north, up, lat, lon, h);
  return {lat, lon};
}

void set_geodetic_gps(Mission& m) {
  const LocalFrame frame(m.origin);
  m.gps_latitude.resize(m.gps_north.size());
  m.gps_longitude.resize(m.gps_north.size());
  for (std::size_t i = 0; i < m.gps_north.size(); ++i) {
    const GeoOrigin g = frame.to_geodetic(m.gps_north[i], m.gps_east[i]);
    m.gps_latitude[i] = g.latitude;
    m.gps_longitude[i] = g.longitude;
  }
}

double deepest(const Mission& m) {
  // The floor under the robot: its depth and altitude plus their bounds, and the
  // mine's depth band.
  double deepest = 0.0, longest = 0.0;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double depth =
        m.depth[k] + (m.half_widths.depth.empty() ? depth_bound_nearest(m.model, m.depth[k]) : m.half_widths.depth[k]);
    const double altitude = m.altitude[k] + (m.half_widths.altitude.empty() ? m.model.altitude : m.half_widths.altitude[k]);
    deepest = std::max(deepest, depth + std::max(altitude, 0.0));
    if (k + 1 < m.size()) longest = std::max(longest, m.time[k + 1] - m.time[k]);
  }
  // Between samples the floor under the robot can go deeper, for half the longest step:
  // at the depth's and the altitude's rates (the readings' model), or at the floor's
  // slope times the speed (the solver's altitude model, SensorBoxes::step_altitude),
  // whichever is faster.
  const double slope = m.model.mine_depth_band / m.model.sonar_max_range;
  const double floor_rate = std::max(m.model.max_depth_rate + m.model.max_altitude_rate, 1.001 * slope * speed_bound(m));
  deepest += floor_rate * longest / 2.0 + m.model.mine_depth_band;
  return 1.000001 * deepest;  // the few roundings above
}

void fill_local_gps(Mission& m, const std::string& source) {
  const LocalFrame frame(m.origin);
  const std::size_t g = m.gps_time.size();
  m.gps_north.assign(g, 0.0);
  m.gps_east.assign(g, 0.0);
  m.gps_north_halfwidth.assign(g, 0.0);
  m.gps_east_halfwidth.assign(g, 0.0);
  const double a = GeographicLib::Constants::WGS84_a();
  const double degree = std::numbers::pi / 180.0;
  for (std::size_t i = 0; i < g; ++i) {
    const NorthEast p = frame.to_local(m.gps_latitude[i], m.gps_longitude[i]);
    const double distance = std::hypot(p.north, p.east);
    if (distance > kLocalFrameZone)
      throw FormatError(source + ": /gps/lonlat: row " + std::to_string(i) + ": " + fix_beyond_zone(distance));
    m.gps_north[i] = p.north;
    m.gps_east[i] = p.east;
    // A degree bound in metres: the radius of curvature never exceeds a / (1 - f)^2
    // (< 1.01 a), and a longitude degree spans cos(latitude) of that.
    const double radius = 1.01 * a;
    const double lat_m = m.model.gps_lat_deg * degree * radius;
    const double lon_m = m.model.gps_lon_deg * degree * radius * std::cos(m.gps_latitude[i] * degree);
    m.gps_north_halfwidth[i] = add_up(std::max(lat_m, m.model.gps_metres), kLocalFrameError);
    m.gps_east_halfwidth[i] = add_up(std::max(lon_m, m.model.gps_metres), kLocalFrameError);
    // A bound given with the fix (a position from a text log) replaces the model's,
    // unless a --config set the model's GPS bounds: then the larger of the two holds.
    if (!m.gps_given_north_halfwidth.empty()) {
      const double north = m.gps_given_north_halfwidth[i], east = m.gps_given_east_halfwidth[i];
      m.gps_north_halfwidth[i] = m.gps_model_floor ? std::max(m.gps_north_halfwidth[i], add_up(north, kLocalFrameError))
                                                   : add_up(north, kLocalFrameError);
      m.gps_east_halfwidth[i] = m.gps_model_floor ? std::max(m.gps_east_halfwidth[i], add_up(east, kLocalFrameError))
                                                  : add_up(east, kLocalFrameError);
    }
  }
  // The heading's margin holds anywhere in the frame's zone: the solver bounds it
  // again, per sample, over the tube it solved (solver/network/frame/frame_margins.h).
  m.heading_frame_margin = meridian_convergence_within(m.origin.latitude, kLocalFrameZone);
  // The frame's scale along a path anywhere in the zone (narrowed per sample by the
  // solve like the heading's), and the surface point's speed at the deepest the
  // sonar sees (docs/model.md, "The local frame's scale").
  m.frame_scale_margin = frame_scale_within(kLocalFrameZone);
  m.depth_scale_margin = depth_scale_within(deepest(m));
  // A fix's bounds are north and east half-widths along its own meridian and
  // parallel, which turn against the frame's axes by the convergence where the true
  // position lies (within the larger half-width of the fix): the frame box must hold
  // that box turned, so each half-width grows by the other times sin(angle) <= angle
  // (for a 2.51 m box 3 km from the origin, 1.2 mm at 48°; 25 cm at 89° and 10 km).
  for (std::size_t i = 0; i < g; ++i) {
    const double north = m.gps_north_halfwidth[i], east = m.gps_east_halfwidth[i];
    const double reach = add_up(std::hypot(m.gps_north[i], m.gps_east[i]), 2.0 * std::max(north, east));
    const double turn = std::min(m.heading_frame_margin, meridian_convergence_within(m.origin.latitude, reach));
    m.gps_north_halfwidth[i] = add_up(north, mul_up(east, turn));
    m.gps_east_halfwidth[i] = add_up(east, mul_up(north, turn));
  }
}

}  // namespace gesmi::io
