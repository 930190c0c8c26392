// The sensor model's own checks (solver/mission/sensor_model.h).
#include "solver/mission/sensor_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace gesmi {
namespace {

TEST(SensorModel, RefusesBoundsThatCannotHold) {
  EXPECT_EQ(SensorModel{}.validate(), "");
  SensorModel m;
  m.heading = -1.0;
  EXPECT_NE(m.validate().find("heading"), std::string::npos);
  m = {};
  m.max_jerk = std::numeric_limits<double>::infinity();
  EXPECT_NE(m.validate().find("max_jerk"), std::string::npos);
  m = {};
  m.sonar_max_range = 0.0;
  EXPECT_NE(m.validate().find("sonar_max_range"), std::string::npos);
  // Over a flat floor the altitude changes as fast as the depth.
  m = {};
  m.max_depth_rate = 2.0;
  EXPECT_EQ(m.validate(), "max_altitude_rate must be at least max_depth_rate");
  m.max_altitude_rate = 2.0;
  EXPECT_EQ(m.validate(), "");
}

TEST(SensorModel, DepthBoundRoundsUp) {
  SensorModel m;
  m.depth_absolute = 0.1;
  m.depth_relative = 0.1;
  for (const double d : {0.3, -7.7, 1e-300, 123.456}) {
    // The model's values are the doubles (0.1 is not exact in binary): compare with them.
    const long double model = static_cast<long double>(m.depth_absolute) +
                              static_cast<long double>(m.depth_relative) * std::fabs(static_cast<long double>(d));
    EXPECT_GE(static_cast<long double>(depth_bound(m, d)), model) << d;
    EXPECT_LE(static_cast<long double>(depth_bound(m, d)), model * (1.0L + 1e-15L)) << d;
  }
}

}  // namespace
}  // namespace gesmi
