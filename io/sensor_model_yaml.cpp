#include "io/sensor_model_yaml.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <sstream>

#include "io/format_error.h"
#include "io/sensor_model_attributes.h"
#include "io/sonar_side.h"

namespace gesmi::io {

void merge_sensor_model_yaml(const std::string& path, SensorModel& model) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw FormatError(path + ": cannot open the file (does it exist?)");
  } catch (const YAML::Exception& e) {
    throw FormatError(path + ": line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (root.IsNull()) return;  // an empty file changes nothing
  if (!root.IsMap()) throw FormatError(path + ": expected a mapping of key: value");
  SensorModel updated = model;
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    const std::string where = path + ": line " + std::to_string(entry.first.Mark().line + 1) + ": " + key;
    if (key == "sonar_side") {
      if (!entry.second.IsScalar()) throw FormatError(where + ": expected starboard, port or both");
      updated.sonar_side = parse_sonar_side(entry.second.as<std::string>(), where);
      continue;
    }
    const ModelField* field = nullptr;
    for (const ModelField& f : model_fields())
      if (f.key == key) field = &f;
    if (!field) throw FormatError(where + ": unknown key (docs/formats.md lists the sensor model keys)");
    double value = 0.0;
    try {
      if (!entry.second.IsScalar()) throw YAML::Exception(entry.second.Mark(), "not a number");
      value = entry.second.as<double>();
    } catch (const YAML::Exception&) {
      throw FormatError(where + ": expected a number");
    }
    if (!std::isfinite(value) || value < 0.0) throw FormatError(where + ": must be a finite number >= 0");
    updated.*field->member = value;
  }
  if (const std::string why = updated.validate(); !why.empty()) throw FormatError(path + ": " + why);
  model = updated;
}

std::string sensor_model_yaml(const SensorModel& model) {
  std::ostringstream out;
  out.precision(17);
  out << "# gesmi sensor error model (docs/formats.md)\n";
  for (const ModelField& f : model_fields())
    out << f.key << ": " << model.*f.member << "  # " << f.unit << ", " << f.meaning << "\n";
  out << "sonar_side: " << sonar_side_name(model.sonar_side) << "  # starboard, port or both\n";
  return out.str();
}

}  // namespace gesmi::io
