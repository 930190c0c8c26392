#include "io/files/sensor_model_yaml.h"

#include <cmath>
#include <sstream>

#include "io/format_error.h"
#include "io/text/message_text.h"
#include "io/text/strict_yaml.h"

namespace gesmi::io {

void merge_sensor_model_yaml(const std::string& path, SensorModel& model) {
  const YAML::Node root = load_strict_yaml_file(path);
  if (root.IsNull()) return;  // a file without a document (empty, or only comments) changes nothing
  SensorModel updated = model;
  for (const auto& entry : root) {
    const std::string key = entry.first.Scalar();
    const std::string line = path + ":" + std::to_string(entry.first.Mark().line + 1);
    const SensorModelField* field = nullptr;
    for (const SensorModelField& f : sensor_model_fields())
      if (f.key == key) field = &f;
    const SensorModelChoice* choice = nullptr;
    for (const SensorModelChoice& c : sensor_model_choices())
      if (c.key == key) choice = &c;
    if (!field && !choice)
      throw FormatError(line + ": unknown key " + quoted_input(key) + " (docs/formats.md lists the sensor model keys)");
    const std::string where = line + ": " + key;
    if (choice) {
      if (!entry.second.IsScalar() || !choice->set(updated, entry.second.Scalar()))
        throw FormatError(where + ": expected " + choice_names(*choice) +
                          (entry.second.IsScalar() ? ", found " + quoted_input(entry.second.Scalar()) : std::string()));
      continue;
    }
    double value = 0.0;
    try {
      if (!entry.second.IsScalar()) throw YAML::Exception(entry.second.Mark(), "not a number");
      value = entry.second.as<double>();
    } catch (const YAML::Exception&) {
      throw FormatError(where + ": expected a number" +
                        (entry.second.IsScalar() ? ", found " + quoted_input(entry.second.Scalar()) : std::string()));
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
  for (const SensorModelField& f : sensor_model_fields())
    out << f.key << ": " << model.*f.member << "  # " << f.unit << ", " << f.meaning << "\n";
  for (const SensorModelChoice& c : sensor_model_choices())
    out << c.key << ": " << c.get(model) << "  # " << choice_names(c) << "\n";
  return out.str();
}

}  // namespace gesmi::io
