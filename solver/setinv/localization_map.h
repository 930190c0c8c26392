#pragma once
// The world and the robot's sensors for static localization (seeds 000, 002, 003,
// 004): oriented wall segments that reflect sonar waves and block sight lines,
// point landmarks seen by a goniometric sensor, and the sensors' poses in the robot
// frame. Angles in radians; the robot pose is p = (x, y, theta).

#include <cstddef>
#include <string>
#include <vector>

#include "solver/setinv/geometry2d.h"

namespace gesmi {

struct LandmarkPoint {
  double x = 0, y = 0;
};

struct LocalizationMap {
  std::vector<Segment> walls;
  std::vector<LandmarkPoint> landmarks;
};

/// A range sensor (sonar) of the belt: position and emission axis in the robot
/// frame, half aperture gamma of the emission cone, relative precision alpha.
struct RangeSensor {
  std::string name;
  double x = 0, y = 0, heading = 0;
  double half_aperture = 0.0;
  double precision = 0.02;
};

/// A goniometric sensor: position and zero direction in the robot frame; each
/// bearing is known within +- precision (radians).
struct BearingSensor {
  std::string name;
  double x = 0, y = 0, heading = 0;
  double precision = 0.0;
};

struct RangeMeasurement {
  std::size_t sensor = 0;  // index into the range sensors
  double range = 0.0;      // d: the feasible set is [d (1 - alpha), d (1 + alpha)]
};

struct BearingMeasurement {
  std::size_t sensor = 0;  // index into the bearing sensors
  double bearing = 0.0;    // in the sensor frame, radians
};

}  // namespace gesmi
