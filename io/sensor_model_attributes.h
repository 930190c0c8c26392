#pragma once
// The sensor model as a list of named fields, shared by the HDF5 attributes of
// /model, the YAML file and docs/formats.md.

#include <string_view>
#include <vector>

#include "solver/mission/sensor_model.h"

namespace gesmi::io {

struct ModelField {
  std::string_view key;
  double SensorModel::*member;
  std::string_view unit, meaning;
};

/// Every numeric field of SensorModel (the sonar side is handled apart).
const std::vector<ModelField>& model_fields();

}  // namespace gesmi::io
