#include "solver/mission/sensor_model.h"

#include <cmath>

namespace gesmi {

const std::vector<SensorModelField>& sensor_model_fields() {
  static const std::vector<SensorModelField> fields = {
      {"dvl_relative", &SensorModel::dvl_relative, "1", "DVL bound a in v ± (a|v| + b), per component"},
      {"dvl_absolute", &SensorModel::dvl_absolute, "m/s", "DVL bound b in v ± (a|v| + b)"},
      {"roll", &SensorModel::roll, "rad", "roll bound"},
      {"pitch", &SensorModel::pitch, "rad", "pitch bound"},
      {"heading", &SensorModel::heading, "rad", "heading bound"},
      {"depth_absolute", &SensorModel::depth_absolute, "m", "depth bound d in depth ± (d + e·depth)"},
      {"depth_relative", &SensorModel::depth_relative, "1", "depth bound e in depth ± (d + e·depth)"},
      {"altitude", &SensorModel::altitude, "m", "DVL altitude bound"},
      {"gps_lon_deg", &SensorModel::gps_lon_deg, "deg", "GPS longitude bound"},
      {"gps_lat_deg", &SensorModel::gps_lat_deg, "deg", "GPS latitude bound"},
      {"gps_metres", &SensorModel::gps_metres, "m", "GPS horizontal bound (the larger of this and the degree bounds is used)"},
      {"mark_range", &SensorModel::mark_range, "m", "slant range bound of an operator mark"},
      {"mine_depth_band", &SensorModel::mine_depth_band, "m", "|s| in m_z = altitude + depth + s (bottom slope × swath)"},
      {"sonar_max_range", &SensorModel::sonar_max_range, "m", "side-scan sonar range"},
      {"along_track_tolerance", &SensorModel::along_track_tolerance, "m", "|along-track offset| of a marked mine from the sonar plane"},
      {"max_attitude_rate", &SensorModel::max_attitude_rate, "rad/s", "bound on roll, pitch and heading rates between samples"},
      {"max_acceleration", &SensorModel::max_acceleration, "m/s²", "bound on the rate of each DVL component between samples"},
  };
  return fields;
}

std::string SensorModel::validate() const {
  for (const SensorModelField& f : sensor_model_fields()) {
    const double value = this->*f.member;
    if (!std::isfinite(value) || value < 0.0) return std::string(f.key) + " must be a finite non-negative number";
  }
  if (sonar_max_range <= 0.0) return "sonar_max_range must be positive";
  return {};
}

}  // namespace gesmi
