#include "io/localization/localization_scenario.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/text/message_text.h"
#include "io/text/strict_yaml.h"
#include "io/text/yaml_fields.h"
#include "solver/model/angles.h"

namespace gesmi::io {
namespace {

constexpr std::size_t kMaxNameLength = 200;
constexpr const char* kNoEchoText = "none";  // `range: none`: the sonar heard no echo

// Reads one scenario, naming the file, line and key path in every error.
using Reader = YamlFields;

void read_map(const Reader& r, const YAML::Node& root, LocalizationProblem& p) {
  const YAML::Node map = r.required(root, "", "map");
  r.only_keys(map, "map", {"walls", "landmarks"});
  if (const YAML::Node walls = map["walls"]) {
    if (!walls.IsSequence()) r.fail(walls, "map.walls", "expected a list of [ax, ay, bx, by]");
    for (std::size_t i = 0; i < walls.size(); ++i) {
      const auto v = r.numbers(walls[i], Reader::item("map.walls", i), 4);
      if (v[0] == v[2] && v[1] == v[3]) r.fail(walls[i], Reader::item("map.walls", i), "wall has zero length");
      p.map.walls.push_back({v[0], v[1], v[2], v[3]});
    }
  }
  if (const YAML::Node landmarks = map["landmarks"]) {
    if (!landmarks.IsSequence()) r.fail(landmarks, "map.landmarks", "expected a list of [x, y]");
    for (std::size_t i = 0; i < landmarks.size(); ++i) {
      const auto v = r.numbers(landmarks[i], Reader::item("map.landmarks", i), 2);
      p.map.landmarks.push_back({v[0], v[1]});
    }
  }
}

// Sensor name -> (is range, index among its kind).
using SensorIndex = std::map<std::string, std::pair<bool, std::size_t>>;

SensorIndex read_sensors(const Reader& r, const YAML::Node& root, LocalizationProblem& p) {
  const YAML::Node sensors = r.required(root, "", "sensors");
  if (!sensors.IsSequence() || sensors.size() == 0) r.fail(sensors, "sensors", "expected a non-empty list");
  SensorIndex index;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    const YAML::Node s = sensors[i];
    const std::string key = Reader::item("sensors", i);
    const std::string type = r.text(r.required(s, key, "type"), key + ".type");
    const std::string name = r.text(r.required(s, key, "name"), key + ".name");
    if (index.count(name)) r.fail(s["name"], key + ".name", "duplicate sensor name " + quoted_input(name));
    const double x = r.number_or(s, key, "x", 0.0), y = r.number_or(s, key, "y", 0.0);
    const double heading = r.number_or(s, key, "heading_deg", 0.0) * kRadiansPerDegree;
    if (type == "range") {
      r.only_keys(s, key, {"name", "type", "x", "y", "heading_deg", "half_aperture_deg", "precision", "max_range", "blind_distance"});
      const double gamma = r.number(r.required(s, key, "half_aperture_deg"), key + ".half_aperture_deg");
      if (!(gamma > 0.0 && gamma < 45.0)) r.fail(s["half_aperture_deg"], key + ".half_aperture_deg", "must be in (0, 45) degrees");
      const double alpha = r.number(r.required(s, key, "precision"), key + ".precision");
      if (!(alpha >= 0.0 && alpha < 1.0)) r.fail(s["precision"], key + ".precision", "relative precision must be in [0, 1)");
      RangeSensor sensor{name, x, y, heading, gamma * kRadiansPerDegree, alpha};
      sensor.max_range = r.number_or(s, key, "max_range", sensor.max_range);
      if (!(sensor.max_range > 0.0)) r.fail(s["max_range"], key + ".max_range", "must be positive");
      sensor.blind_distance = r.number_or(s, key, "blind_distance", 0.0);
      if (!(sensor.blind_distance >= 0.0)) r.fail(s["blind_distance"], key + ".blind_distance", "must not be negative");
      if (!(sensor.blind_distance < sensor.max_range))
        r.fail(s["blind_distance"], key + ".blind_distance", "must be below max_range " + format_number(sensor.max_range));
      index[name] = {true, p.range_sensors.size()};
      p.range_sensors.push_back(std::move(sensor));
    } else if (type == "bearing") {
      r.only_keys(s, key, {"name", "type", "x", "y", "heading_deg", "precision_deg"});
      const double delta = r.number(r.required(s, key, "precision_deg"), key + ".precision_deg");
      if (!(delta >= 0.0 && delta < 90.0)) r.fail(s["precision_deg"], key + ".precision_deg", "must be in [0, 90) degrees");
      index[name] = {false, p.bearing_sensors.size()};
      p.bearing_sensors.push_back({name, x, y, heading, delta * kRadiansPerDegree});
    } else {
      r.fail(s["type"], key + ".type", "expected 'range' or 'bearing', got " + quoted_input(type));
    }
  }
  return index;
}

void read_measurements(const Reader& r, const YAML::Node& root, const SensorIndex& index, LocalizationProblem& p) {
  const YAML::Node list = r.required(root, "", "measurements");
  if (!list.IsSequence() || list.size() == 0) r.fail(list, "measurements", "expected a non-empty list");
  std::vector<std::size_t> range_numbers, bearing_numbers;  // the problem stores ranges first
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node m = list[i];
    const std::string key = Reader::item("measurements", i);
    const std::string sensor = r.text(r.required(m, key, "sensor"), key + ".sensor");
    const auto found = index.find(sensor);
    if (found == index.end()) r.fail(m["sensor"], key + ".sensor", "unknown sensor " + quoted_input(sensor));
    if (found->second.first) {
      r.only_keys(m, key, {"sensor", "range"});
      const RangeSensor& s = p.range_sensors[found->second.second];
      const YAML::Node range = r.required(m, key, "range");
      double d = kNoEcho;
      if (range.IsScalar() && range.Scalar() == kNoEchoText) {
        if (!s.has_max_range()) r.fail(range, key + ".range", "'none' (no echo) needs a max_range on sensor " + quoted_input(s.name));
      } else {
        d = r.number(range, key + ".range");
        if (!(d > 0.0)) r.fail(range, key + ".range", "must be positive");
        if (d > s.max_range)
          r.fail(range, key + ".range", "beyond the max_range " + format_number(s.max_range) + " of sensor " +
                                            quoted_input(s.name) + " (no echo is written 'none')");
      }
      p.ranges.push_back({found->second.second, d});
      range_numbers.push_back(i + 1);
    } else {
      r.only_keys(m, key, {"sensor", "bearing_deg"});
      p.bearings.push_back({found->second.second,
                            r.number(r.required(m, key, "bearing_deg"), key + ".bearing_deg") * kRadiansPerDegree});
      bearing_numbers.push_back(i + 1);
    }
  }
  p.file_numbers = std::move(range_numbers);
  p.file_numbers.insert(p.file_numbers.end(), bearing_numbers.begin(), bearing_numbers.end());
}

void read_prior(const Reader& r, const YAML::Node& root, LocalizationProblem& p) {
  const YAML::Node prior = r.required(root, "", "prior");
  r.only_keys(prior, "prior", {"boxes", "halfplanes"});
  const YAML::Node boxes = r.required(prior, "prior", "boxes");
  if (!boxes.IsSequence() || boxes.size() == 0) r.fail(boxes, "prior.boxes", "expected a non-empty list");
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string key = Reader::item("prior.boxes", i);
    r.only_keys(boxes[i], key, {"x", "y", "theta_deg"});
    const Interval theta = r.range(r.required(boxes[i], key, "theta_deg"), key + ".theta_deg", kRadiansPerDegree);
    if (theta.width() > 360.0 * kRadiansPerDegree * (1 + 1e-12))
      r.fail(boxes[i]["theta_deg"], key + ".theta_deg", "wider than 360 degrees");
    p.priors.push_back(Box{r.range(r.required(boxes[i], key, "x"), key + ".x", 1.0),
                           r.range(r.required(boxes[i], key, "y"), key + ".y", 1.0), theta});
  }
  if (const YAML::Node planes = prior["halfplanes"]) {
    if (!planes.IsSequence()) r.fail(planes, "prior.halfplanes", "expected a list of [a, b, c] (a x + b y <= c)");
    for (std::size_t i = 0; i < planes.size(); ++i) {
      const auto v = r.numbers(planes[i], Reader::item("prior.halfplanes", i), 3);
      if (v[0] == 0.0 && v[1] == 0.0) r.fail(planes[i], Reader::item("prior.halfplanes", i), "a and b are both zero");
      p.constraints.push_back({v[0], v[1], v[2]});
    }
  }
}

void read_settings(const Reader& r, const YAML::Node& root, LocalizationProblem& p) {
  const YAML::Node solver = r.required(root, "", "solver");
  r.only_keys(solver, "solver", {"epsilon", "epsilon_min", "theta_scale", "contractors", "max_boxes", "max_seconds"});
  p.epsilon = r.number(r.required(solver, "solver", "epsilon"), "solver.epsilon");
  if (!(p.epsilon > 0.0)) r.fail(solver["epsilon"], "solver.epsilon", "must be positive");
  p.epsilon_min = r.number_or(solver, "solver", "epsilon_min", p.epsilon / 64.0);
  if (!(p.epsilon_min > 0.0 && p.epsilon_min <= p.epsilon))
    r.fail(solver["epsilon_min"], "solver.epsilon_min", "must be positive and at most epsilon");
  p.theta_scale = r.number_or(solver, "solver", "theta_scale", 1.0);
  if (!(p.theta_scale > 0.0)) r.fail(solver["theta_scale"], "solver.theta_scale", "must be positive");
  // Below this the bisection cannot meet epsilon near the prior's largest coordinates.
  if (const double finest = finest_epsilon(p.priors, {1.0, 1.0, p.theta_scale}); p.epsilon < finest)
    r.fail(solver["epsilon"], "solver.epsilon",
           format_number(p.epsilon) + " is finer than doubles can split over the prior boxes: at least " +
               format_number(finest));
  if (const YAML::Node c = solver["contractors"]) {
    if (!c.IsScalar() || (c.Scalar() != "true" && c.Scalar() != "false"))
      r.fail(c, "solver.contractors", "expected true or false");
    p.use_contractors = c.Scalar() == "true";
  }
  if (solver["max_boxes"]) {
    const long long n = r.integer(solver["max_boxes"], "solver.max_boxes");
    if (n <= 0) r.fail(solver["max_boxes"], "solver.max_boxes", "must be positive");
    p.max_boxes = static_cast<std::size_t>(n);
  }
  p.max_seconds = r.number_or(solver, "solver", "max_seconds", p.max_seconds);
  if (!(p.max_seconds > 0.0)) r.fail(solver["max_seconds"], "solver.max_seconds", "must be positive");

  const YAML::Node outliers = root["outliers"];
  if (!outliers) return;
  r.only_keys(outliers, "outliers", {"policy", "count", "extra", "max"});
  const std::string policy = r.text(r.required(outliers, "outliers", "policy"), "outliers.policy");
  const int n = static_cast<int>(p.datum_count());
  const auto count = [&](const char* name, long long lo, long long hi) {
    const long long v = r.integer(outliers[name], std::string("outliers.") + name);
    if (v < lo || v > hi)
      r.fail(outliers[name], std::string("outliers.") + name, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
    return static_cast<int>(v);
  };
  if (policy == "fixed") {
    p.policy = OutlierPolicy::fixed;
    if (outliers["count"]) p.outliers = count("count", 0, n);
    if (outliers["extra"] || outliers["max"]) r.fail(outliers, "outliers", "'extra' and 'max' go with policy 'minimal'");
  } else if (policy == "minimal") {
    p.policy = OutlierPolicy::minimal;
    if (outliers["count"]) r.fail(outliers["count"], "outliers.count", "goes with policy 'fixed'");
    if (outliers["extra"]) p.extra_outliers = count("extra", 0, n);
    if (outliers["max"]) p.max_outliers = count("max", 0, n);
  } else {
    r.fail(outliers["policy"], "outliers.policy", "expected 'fixed' or 'minimal', got " + quoted_input(policy));
  }
}

void read_truth(const Reader& r, const YAML::Node& root, LocalizationProblem& p) {
  const YAML::Node truth = root["truth"];
  if (!truth) return;
  r.only_keys(truth, "truth", {"x", "y", "theta_deg"});
  p.truth = Pose<double>{r.number(r.required(truth, "truth", "x"), "truth.x"), r.number(r.required(truth, "truth", "y"), "truth.y"),
                         r.number(r.required(truth, "truth", "theta_deg"), "truth.theta_deg") * kRadiansPerDegree};
}

LocalizationProblem scenario_from(const YAML::Node& root, const std::string& source) {
  const Reader r(source);
  if (root.IsNull()) throw FormatError(source + ": no YAML document: expected a scenario (docs/setinversion.md)");
  try {
    r.only_keys(root, "", {"name", "description", "map", "sensors", "measurements", "prior", "solver", "outliers", "truth"});
    LocalizationProblem p;
    p.name = root["name"] ? r.text(root["name"], "name") : std::string();
    // The name titles the summary and the pictures and is stored as an HDF5 attribute.
    if (p.name.size() > kMaxNameLength || one_line(p.name) != p.name)
      r.fail(root["name"], "name", "expected one line of at most " + std::to_string(kMaxNameLength) +
                                       " characters, got " + quoted_input(p.name));
    read_map(r, root, p);
    const SensorIndex index = read_sensors(r, root, p);
    read_measurements(r, root, index, p);
    read_prior(r, root, p);
    read_settings(r, root, p);
    read_truth(r, root, p);
    if (!p.bearings.empty() && p.map.landmarks.empty()) r.fail(root["map"], "map.landmarks", "bearing measurements need landmarks");
    if (!p.ranges.empty() && p.map.walls.empty()) r.fail(root["map"], "map.walls", "range measurements need walls");
    if (const std::string e = p.validate(); !e.empty()) throw FormatError(source + ": " + e);
    return p;
  } catch (const YAML::Exception& e) {
    throw FormatError(source + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
}

}  // namespace

LocalizationProblem parse_localization_scenario(std::istream& in, const std::string& source) {
  std::ostringstream text;
  text << in.rdbuf();
  return scenario_from(load_strict_yaml(text.str(), source), source);
}

LocalizationProblem read_localization_scenario(const std::string& path) {
  return scenario_from(load_strict_yaml_file(path), path);
}

std::string localization_measurements_yaml(const LocalizationProblem& p) {
  std::ostringstream out;
  out.precision(10);
  out << "measurements:\n";
  for (const RangeMeasurement& m : p.ranges) {
    out << "  - {sensor: " << p.range_sensors[m.sensor].name << ", range: ";
    if (m.no_echo()) {
      out << kNoEchoText;
    } else {
      // Ten digits read well; all of them where ten would round above max_range, which
      // the reader would refuse.
      std::ostringstream ten;
      ten.precision(10);
      ten << m.range;
      const std::string text = ten.str();
      double back = 0.0;
      std::from_chars(text.data(), text.data() + text.size(), back);
      if (back > p.range_sensors[m.sensor].max_range) {
        ten.str("");
        ten.precision(std::numeric_limits<double>::max_digits10);
        ten << m.range;
      }
      out << ten.str();
    }
    out << "}\n";
  }
  for (const BearingMeasurement& m : p.bearings)
    out << "  - {sensor: " << p.bearing_sensors[m.sensor].name << ", bearing_deg: " << m.bearing / kRadiansPerDegree
        << "}\n";
  return out.str();
}

}  // namespace gesmi::io
