#include "io/files/model_attributes.h"

#include "io/format_error.h"
#include "io/text/message_text.h"

namespace gesmi::io {

void write_model_attributes(H5File& f, const std::string& group, const SensorModel& model) {
  f.create_group(group);
  for (const SensorModelField& field : sensor_model_fields()) f.set_attribute(group, std::string(field.key), model.*field.member);
  for (const SensorModelChoice& choice : sensor_model_choices())
    f.set_attribute(group, std::string(choice.key), std::string(choice.get(model)));
}

SensorModel read_model_attributes(const H5File& f, const std::string& group, std::int64_t file_version) {
  if (!f.has_group(group)) throw FormatError(f.path() + ": " + group + ": missing group (the sensor model)");
  SensorModel model;
  const auto missing = [&](std::string_view key) {
    throw FormatError(f.path() + ": " + group + ": missing attribute " + std::string(key));
  };
  for (const SensorModelField& field : sensor_model_fields()) {
    const auto value = f.double_attribute(group, std::string(field.key));
    if (value)
      model.*field.member = *value;
    else if (field.since_version <= file_version)
      missing(field.key);
  }
  for (const SensorModelChoice& choice : sensor_model_choices()) {
    const auto name = f.string_attribute(group, std::string(choice.key));
    if (!name) {
      if (choice.since_version <= file_version) missing(choice.key);
      continue;
    }
    if (!choice.set(model, *name))
      throw FormatError(f.path() + ": " + group + ": " + std::string(choice.key) + ": expected " + choice_names(choice) +
                        ", found " + quoted_input(*name));
  }
  if (const std::string why = model.validate(); !why.empty()) throw FormatError(f.path() + ": " + group + ": " + why);
  return model;
}

}  // namespace gesmi::io
