#pragma once
// Sensor error bounds in the form of seed 001 (section V-B), with the reference
// mission's values as defaults (../shared/reference/redermor.md). Stored with every
// mission and readable from YAML (docs/formats.md documents each key).

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace gesmi {

enum class SonarSide : int { port = -1, both = 0, starboard = 1 };

/// How a step's displacement p(k+1) - p(k) = integral of R v is enclosed (docs/model.md,
/// "Boxes over a step"):
///  - trapezoid: dt/2 ([R v]_k + [R v]_k+1) + dt^3/12 [-J, J] from the boxes at the two
///    samples alone, J = max_jerk bounding the second derivative of R v; intersected
///    with rate_hull, so never wider. Sound when the boxes hold at the sample instants.
///  - rate_hull: dt times R v over the hull of both samples' boxes widened by the
///    rates' excursion (max_attitude_rate, max_acceleration).
///  - sample: dt [R v]_k, the paper's convention: sound only when the box of sample k
///    holds over the whole step, which a sensor's datasheet does not promise.
enum class StepModel { trapezoid, rate_hull, sample };

struct SensorModel {
  // DVL body-frame speed, per component: true value in v ± (dvl_relative·|v| + dvl_absolute).
  double dvl_relative = 0.004;
  double dvl_absolute = 0.004;  // m/s
  // Gyrocompass: roll, pitch, heading ± bound (rad).
  double roll = 1.75e-4;
  double pitch = 1.75e-4;
  double heading = 5.27e-3;
  // Barometer: depth in d ± (depth_absolute + depth_relative·|d|) (m).
  double depth_absolute = 1.5;
  double depth_relative = 0.2;
  // DVL altitude ± bound (m).
  double altitude = 0.10;
  // GPS fix: ± in degrees of longitude and latitude, and a metric bound; the box
  // used is the larger of the two after conversion to the local frame.
  double gps_lon_deg = 1.35e-5;
  double gps_lat_deg = 9.0e-6;
  double gps_metres = 2.5;
  // Operator mark: slant range ± bound (m).
  double mark_range = 1.0;
  // Mine depth m_z = altitude + depth + s with |s| <= mine_depth_band (bottom slope
  // times swath: 0.01 × 75 m). Altitude and depth keep their own bounds.
  double mine_depth_band = 0.75;
  // Side-scan sonar.
  SonarSide sonar_side = SonarSide::starboard;
  double sonar_max_range = 75.0;      // m
  double along_track_tolerance = 1.0; // m: |i_r·e| <= this at the mark time
  // Bounds on how fast the true values change between two samples, which make a
  // box valid over a whole step (docs/model.md): the simulator honours them.
  double max_attitude_rate = 0.05;  // rad/s, roll, pitch and heading
  double max_acceleration = 0.2;    // m/s², each DVL component
  // Rate bounds that enclose the depth and the altitude between their own readings
  // when a log reads them slower than the DVL (docs/model.md, "Readings between samples").
  double max_depth_rate = 0.5;      // m/s
  double max_altitude_rate = 1.0;   // m/s (vertical speed plus sea-floor slope times speed)
  // Bound on |d²(R v)/dt²| (the jerk of the position) within a step, for the
  // trapezoid step model (docs/model.md justifies 1 m/s³).
  double max_jerk = 1.0;            // m/s³
  // The surface regime (docs/model.md, "Regimes"): a step whose possible depths reach
  // the surface layer, or that holds a GPS fix, takes the surface jerk bound, and its
  // displacement never exceeds the surface speed bound times its duration. Where the
  // readings contradict a step's jerk bound, or the DVL has no reading, the step is
  // bounded by its regime's speed alone.
  double max_speed = 4.0;            // m/s: the robot's speed over ground submerged, current included
  double surface_layer_depth = 1.0;  // m
  double surface_max_jerk = 10.0;    // m/s³
  double surface_max_speed = 6.5;    // m/s: the robot's own, the waves' orbital velocity and the current
  StepModel step_model = StepModel::trapezoid;

  /// Empty when every bound is finite and non-negative; otherwise the reason.
  std::string validate() const;
};

/// A DVL component's bound, dvl_relative |v| + dvl_absolute, rounded up: the solver's
/// boxes and the importers' per-sample half-widths alike.
double dvl_bound(const SensorModel& model, double v);
/// A depth reading's bound, depth_absolute + depth_relative |depth|, rounded up: the one
/// formula for the solver's boxes and the importers' per-sample half-widths.
double depth_bound(const SensorModel& model, double depth);
/// The same formula rounded to nearest, for a sum that carries its own relative margin
/// (io's deepest(), over every sample: directed rounding there was a fused
/// multiply-add call per sample, 1 % of a warm rerun).
inline double depth_bound_nearest(const SensorModel& model, double depth) {
  return model.depth_absolute + model.depth_relative * std::fabs(depth);
}

/// One numeric field of the sensor model: its key (the HDF5 /model attribute, the YAML
/// key, the docs/formats.md row), the member, its unit and meaning, and the mission
/// file version that introduced it (older files take the default).
struct SensorModelField {
  std::string_view key;
  double SensorModel::*member;
  std::string_view unit, meaning;
  int since_version = 1;
};

/// Every numeric field of SensorModel: the one list that files, validation, digests
/// and docs derive from.
const std::vector<SensorModelField>& sensor_model_fields();

/// A field of the sensor model chosen by name (sonar_side, step_model): a string in
/// files. names()[0] is its default.
struct SensorModelChoice {
  std::string_view key;
  std::vector<std::string_view> names;
  std::string_view meaning;
  int since_version = 1;
  std::string_view (*get)(const SensorModel&);
  bool (*set)(SensorModel&, std::string_view name);  // false when `name` is not one of names
};
const std::vector<SensorModelChoice>& sensor_model_choices();
/// Whether both models have every field and choice alike.
bool same_sensor_model(const SensorModel& a, const SensorModel& b);
/// "starboard, port or both": the names, for messages.
std::string choice_names(const SensorModelChoice& choice);

}  // namespace gesmi
