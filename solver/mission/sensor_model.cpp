#include "solver/mission/sensor_model.h"

#include <cmath>

#include "solver/interval/rounding.h"

namespace gesmi {

double dvl_bound(const SensorModel& model, double v) {
  return add_up(mul_up(model.dvl_relative, std::fabs(v)), model.dvl_absolute);
}

double depth_bound(const SensorModel& model, double depth) {
  return add_up(model.depth_absolute, mul_up(model.depth_relative, std::fabs(depth)));
}

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
      {"max_depth_rate", &SensorModel::max_depth_rate, "m/s", "bound on the depth rate, between a log's depth readings", 3},
      {"max_altitude_rate", &SensorModel::max_altitude_rate, "m/s", "bound on the altitude rate, between a log's altitude readings", 3},
      {"max_jerk", &SensorModel::max_jerk, "m/s³", "bound on the second derivative of the world velocity within a step (trapezoid step model)", 2},
      {"max_speed", &SensorModel::max_speed, "m/s", "bound on the speed over ground while submerged, current included", 4},
      {"surface_layer_depth", &SensorModel::surface_layer_depth, "m", "a step whose possible depths come this close to the surface takes the surface bounds", 4},
      {"surface_max_jerk", &SensorModel::surface_max_jerk, "m/s³", "max_jerk in the surface regime (waves)", 4},
      {"surface_max_speed", &SensorModel::surface_max_speed, "m/s", "bound on the speed over ground in the surface regime: the robot's, the waves' orbital velocity and the current", 4},
  };
  return fields;
}

namespace {

template <class Enum>
struct Named {
  std::string_view name;
  Enum value;
};

constexpr Named<SonarSide> kSides[] = {{"starboard", SonarSide::starboard}, {"port", SonarSide::port}, {"both", SonarSide::both}};
constexpr Named<StepModel> kStepModels[] = {
    {"trapezoid", StepModel::trapezoid}, {"rate-hull", StepModel::rate_hull}, {"sample", StepModel::sample}};

template <class Enum, std::size_t n>
std::string_view name_of(const Named<Enum> (&table)[n], Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return table[0].name;
}

template <class Enum, std::size_t n>
bool value_of(const Named<Enum> (&table)[n], std::string_view name, Enum& value) {
  for (const auto& entry : table)
    if (entry.name == name) {
      value = entry.value;
      return true;
    }
  return false;
}

template <class Enum, std::size_t n>
std::vector<std::string_view> names_of(const Named<Enum> (&table)[n]) {
  std::vector<std::string_view> names;
  for (const auto& entry : table) names.push_back(entry.name);
  return names;
}

}  // namespace

const std::vector<SensorModelChoice>& sensor_model_choices() {
  static const std::vector<SensorModelChoice> choices = {
      {"sonar_side", names_of(kSides), "the side-scan sonar's side(s)", 1,
       [](const SensorModel& m) { return name_of(kSides, m.sonar_side); },
       [](SensorModel& m, std::string_view name) { return value_of(kSides, name, m.sonar_side); }},
      {"step_model", names_of(kStepModels),
       "how a step's displacement is enclosed: trapezoid (sound for boxes at the sample instants), rate-hull, "
       "or sample (the paper's convention: sound only for boxes valid over the whole step)",
       2, [](const SensorModel& m) { return name_of(kStepModels, m.step_model); },
       [](SensorModel& m, std::string_view name) { return value_of(kStepModels, name, m.step_model); }},
  };
  return choices;
}

std::string choice_names(const SensorModelChoice& choice) {
  std::string text;
  for (std::size_t i = 0; i < choice.names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == choice.names.size() ? " or " : ", ") + std::string(choice.names[i]);
  return text;
}

std::string SensorModel::validate() const {
  for (const SensorModelField& f : sensor_model_fields()) {
    const double value = this->*f.member;
    if (!std::isfinite(value) || value < 0.0) return std::string(f.key) + " must be a finite non-negative number";
  }
  if (sonar_max_range <= 0.0) return "sonar_max_range must be positive";
  // The altitude is the floor's depth minus the robot's: over a flat floor it changes
  // exactly as fast as the depth.
  if (max_altitude_rate < max_depth_rate) return "max_altitude_rate must be at least max_depth_rate";
  // The surface regime is the wider one: a step that may be in either takes its bounds.
  if (surface_max_jerk < max_jerk) return "surface_max_jerk must be at least max_jerk";
  if (surface_max_speed < max_speed) return "surface_max_speed must be at least max_speed";
  if (max_speed <= 0.0) return "max_speed must be positive";
  return {};
}

bool same_sensor_model(const SensorModel& a, const SensorModel& b) {
  for (const SensorModelField& f : sensor_model_fields())
    if (a.*f.member != b.*f.member) return false;
  for (const SensorModelChoice& c : sensor_model_choices())
    if (c.get(a) != c.get(b)) return false;
  return true;
}

}  // namespace gesmi
