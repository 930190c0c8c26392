#pragma once
// The world and the robot's sensors for static localization (seeds 000, 002, 003,
// 004): oriented wall segments that reflect sonar waves and block sight lines,
// point landmarks seen by a goniometric sensor, and the sensors' poses in the robot
// frame. Angles in radians; the robot pose is p = (x, y, theta).

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "solver/setinv/localization/geometry2d.h"

namespace gesmi {

struct LandmarkPoint {
  double x = 0, y = 0;
};

struct LocalizationMap {
  std::vector<Segment> walls;
  std::vector<LandmarkPoint> landmarks;
};

/// A range sensor (sonar) of the belt: position and emission axis in the robot
/// frame, half aperture gamma of the emission cone, relative precision alpha. Two
/// options of the model (docs/setinversion.md, section 3.1): a maximum range, beyond
/// which the sonar reports "no echo" (seed 002), and a blind distance, below which
/// it hears nothing (seed 000, after (4.6)).
struct RangeSensor {
  std::string name;
  double x = 0, y = 0, heading = 0;
  double half_aperture = 0.0;
  double precision = 0.02;
  double max_range = std::numeric_limits<double>::infinity();  // +inf: no "no echo" reading
  double blind_distance = 0.0;                                  // 0: no blind zone

  bool has_max_range() const { return max_range < std::numeric_limits<double>::infinity(); }
};

/// A goniometric sensor: position and zero direction in the robot frame; each
/// bearing is known within +- precision (radians).
struct BearingSensor {
  std::string name;
  double x = 0, y = 0, heading = 0;
  double precision = 0.0;
};

/// The range of a "no echo" measurement: the sensor heard nothing within its max_range.
inline constexpr double kNoEcho = std::numeric_limits<double>::infinity();

struct RangeMeasurement {
  std::size_t sensor = 0;  // index into the range sensors
  double range = 0.0;      // d, or kNoEcho; the feasible set is feasible_range() (range_model.h)

  bool no_echo() const { return range == kNoEcho; }
};

struct BearingMeasurement {
  std::size_t sensor = 0;  // index into the bearing sensors
  double bearing = 0.0;    // in the sensor frame, radians
};

}  // namespace gesmi
