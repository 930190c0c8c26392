#pragma once
// The sensor error model as YAML (docs/formats.md lists every key):
//   heading: 5.27e-3      # rad
//   sonar_side: starboard
// Keys not given keep their current value; unknown keys and bad values are errors
// naming the file, the line and the key.

#include <string>

#include "solver/mission/sensor_model.h"

namespace gesmi::io {

/// Overrides the fields of `model` given in the YAML file at path.
void merge_sensor_model_yaml(const std::string& path, SensorModel& model);
/// The whole model as YAML text (the reference defaults when given SensorModel{}).
std::string sensor_model_yaml(const SensorModel& model);

}  // namespace gesmi::io
