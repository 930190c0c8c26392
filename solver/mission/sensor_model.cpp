#include "solver/mission/sensor_model.h"

#include <cmath>
#include <utility>

namespace gesmi {

std::string SensorModel::validate() const {
  const std::pair<const char*, double> bounds[] = {
      {"dvl_relative", dvl_relative},     {"dvl_absolute", dvl_absolute},
      {"roll", roll},                     {"pitch", pitch},
      {"heading", heading},               {"depth_absolute", depth_absolute},
      {"depth_relative", depth_relative}, {"altitude", altitude},
      {"gps_lon_deg", gps_lon_deg},       {"gps_lat_deg", gps_lat_deg},
      {"gps_metres", gps_metres},         {"mark_range", mark_range},
      {"mine_depth_band", mine_depth_band}, {"sonar_max_range", sonar_max_range},
      {"along_track_tolerance", along_track_tolerance},
      {"max_attitude_rate", max_attitude_rate}, {"max_acceleration", max_acceleration},
  };
  for (const auto& [name, value] : bounds) {
    if (!std::isfinite(value) || value < 0.0)
      return std::string(name) + " must be a finite non-negative number";
  }
  if (sonar_max_range <= 0.0) return "sonar_max_range must be positive";
  return {};
}

}  // namespace gesmi
