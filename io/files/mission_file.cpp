#include "io/files/mission_file.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "io/output/atomic_output.h"
#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/files/model_attributes.h"
#include "io/files/provenance.h"
#include "io/files/sensor_model_yaml.h"
#include "io/hdf5/h5_file.h"
#include "io/hdf5/h5_format.h"
#include "io/files/mark_rules.h"
#include "io/text/message_text.h"
#include "io/time/utc_time.h"
#include "solver/network/mission_network.h"

namespace gesmi::io {
namespace {

constexpr const char* kMissionFormat = "gesmi-mission";
// 2: the sensor model gained max_jerk and step_model (version-1 files take their defaults).
// 3: the sensor model gained max_depth_rate and max_altitude_rate; the optional root
//    attribute epoch_utc (ISO 8601, whole seconds, Z).
// 4: the sensor model gained max_speed and the surface regime's keys (surface_layer_depth,
//    surface_max_jerk, surface_max_speed).
constexpr H5FormatVersions kMissionVersions{.current = 4, .oldest = 1, .when_absent = 0};

std::string half_width_dataset(const NavChannel& c) { return "/nav/half_widths/" + std::string(c.name); }

// What the import filled (ChannelFill), as attributes of the channel's half-width dataset.
void write_fill(H5File& f, const std::string& dataset, const ChannelFill& fill) {
  if (fill.key.empty()) return;
  f.set_attribute(dataset, "filled_by", fill.key);
  f.set_attribute(dataset, "samples_before_first_reading", static_cast<std::int64_t>(fill.before));
  f.set_attribute(dataset, "samples_between_readings", static_cast<std::int64_t>(fill.between));
  f.set_attribute(dataset, "samples_after_last_reading", static_cast<std::int64_t>(fill.after));
  f.set_attribute(dataset, "first_reading", fill.first_reading);
  f.set_attribute(dataset, "last_reading", fill.last_reading);
}

ChannelFill read_fill(const H5File& f, const std::string& dataset, std::size_t samples) {
  ChannelFill fill;
  const auto key = f.string_attribute(dataset, "filled_by");
  if (!key) return fill;
  const auto reject = [&](const std::string& why) { throw FormatError(f.path() + ": " + dataset + ": " + why); };
  const auto known = {"surface_max_speed", "max_attitude_rate", "max_depth_rate", "max_altitude_rate"};
  if (std::find(known.begin(), known.end(), *key) == known.end())
    reject("attribute filled_by must name the model key the import filled with, found " + quoted_input(*key));
  fill.key = *key;
  std::size_t* counts[3] = {&fill.before, &fill.between, &fill.after};
  const char* names[3] = {"samples_before_first_reading", "samples_between_readings", "samples_after_last_reading"};
  for (int i = 0; i < 3; ++i) {
    const auto v = f.int_attribute(dataset, names[i]);
    if (!v || *v < 0 || static_cast<std::uint64_t>(*v) > samples) reject(std::string("attribute ") + names[i] + " must count samples");
    *counts[i] = static_cast<std::size_t>(*v);
  }
  const auto first = f.double_attribute(dataset, "first_reading"), last = f.double_attribute(dataset, "last_reading");
  if (!first || !last || !std::isfinite(*first) || !std::isfinite(*last)) reject("attributes first_reading and last_reading must be times");
  fill.first_reading = *first;
  fill.last_reading = *last;
  if (fill.samples() > samples) reject("more samples filled than the mission has");
  return fill;
}

// Units (UDUNITS, as CF writes them; per column where columns differ) of the mission's
// datasets but its times, whose units follow the epoch (write_time_units).
constexpr DatasetUnits kMissionUnits[] = {
    {"/nav/attitude", "rad, rad, rad", "roll, pitch, heading (from true north, clockwise)"},
    {"/nav/velocity", "m s-1, m s-1, m s-1", "DVL velocity in the body frame: forward, starboard, down"},
    {"/nav/altitude", "m", "DVL altitude above the sea floor"},
    {"/nav/depth", "m", "depth (down positive)"},
    {"/nav/half_widths/roll", "rad", "bound of the roll error"},
    {"/nav/half_widths/pitch", "rad", "bound of the pitch error"},
    {"/nav/half_widths/heading", "rad", "bound of the heading error"},
    {"/nav/half_widths/vx", "m s-1", "bound of the forward velocity error"},
    {"/nav/half_widths/vy", "m s-1", "bound of the starboard velocity error"},
    {"/nav/half_widths/vz", "m s-1", "bound of the down velocity error"},
    {"/nav/half_widths/altitude", "m", "bound of the altitude error"},
    {"/nav/half_widths/depth", "m", "bound of the depth error"},
    {"/gps/lonlat", "degrees_east, degrees_north", "GPS fix longitude, latitude (WGS84)"},
    {"/gps/halfwidth", "m, m", "bound of each fix's north and east errors"},
    {"/marks/mine", "1", "mine number of the mark (-1: not associated)"},
    {"/marks/range", "m", "measured slant range"},
    {"/marks/side", "1", "sonar side: +1 starboard, -1 port"},
    {"/truth/position", "m, m, m", "true position: north, east, down (local frame)"},
    {"/truth/mines", "m, m, m", "true mine positions: north, east, down (local frame)"},
    {"/truth/missed_marks", "s, 1, m", "detections the simulator dropped: time, mine, true range"},
    {"/truth/marks_outlier", "1", "1 for a mark corrupted by the simulator"},
    {"/truth/marks_mine", "1", "the mine each mark really is (-1: an operator's mark)"},
    {"/truth/gps_outlier", "1", "1 for a fix corrupted by the simulator"},
};

std::string row_text(std::size_t row) { return "row " + std::to_string(row); }

// The root attributes of Mission::conversion_margins (absent: 0).
const std::array<std::pair<std::string, double Mission::ConversionMargins::*>, 4>& conversion_margin_attributes() {
  static const std::array<std::pair<std::string, double Mission::ConversionMargins::*>, 4> names = {{
      {"conversion_margin_roll", &Mission::ConversionMargins::roll},
      {"conversion_margin_pitch", &Mission::ConversionMargins::pitch},
      {"conversion_margin_heading", &Mission::ConversionMargins::heading},
      {"conversion_margin_dvl", &Mission::ConversionMargins::dvl},
  }};
  return names;
}

[[noreturn]] void bad(const std::string& source, const std::string& dataset, const std::string& what) {
  throw FormatError(source + ": " + dataset + ": " + what);
}

void expect_finite(const std::vector<double>& v, const std::string& source, const std::string& dataset,
                   const char* field) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i])) bad(source, dataset, row_text(i) + ": " + field + " is " + (std::isnan(v[i]) ? "NaN" : "infinite"));
}

void expect_size(std::size_t size, std::size_t expected, const std::string& source, const std::string& dataset) {
  if (size != expected)
    bad(source, dataset, "expected " + std::to_string(expected) + " rows, found " + std::to_string(size));
}

// The truth's shape against the mission's, and its values.
void validate_truth(const Mission& m, const std::string& source) {
  const std::size_t n = m.size(), mk = m.mark_time.size(), g = m.gps_time.size();
  if (!m.truth_x.empty() || !m.truth_y.empty() || !m.truth_z.empty()) {
    expect_size(m.truth_x.size(), n, source, "/truth/position");
    expect_size(m.truth_y.size(), n, source, "/truth/position");
    expect_size(m.truth_z.size(), n, source, "/truth/position");
    for (const auto* axis : {&m.truth_x, &m.truth_y, &m.truth_z}) expect_finite(*axis, source, "/truth/position", "position");
  }
  if (!m.truth_mines.empty()) {
    expect_size(m.truth_mines.size(), 3 * static_cast<std::size_t>(m.mine_count), source, "/truth/mines (K x 3)");
    expect_finite(m.truth_mines, source, "/truth/mines", "position");
  }
  if (m.truth_missed_marks.size() % 3 != 0) bad(source, "/truth/missed_marks", "expected X x 3 values");
  expect_finite(m.truth_missed_marks, source, "/truth/missed_marks", "value");
  const auto expect_flags = [&](const std::vector<std::int32_t>& flags, std::size_t rows, const char* dataset) {
    expect_size(flags.size(), rows, source, dataset);
    for (std::size_t i = 0; i < flags.size(); ++i)
      if (flags[i] != 0 && flags[i] != 1) bad(source, dataset, row_text(i) + ": expected 0 or 1");
  };
  if (!m.truth_marks_outlier.empty()) expect_flags(m.truth_marks_outlier, mk, "/truth/marks_outlier");
  if (!m.truth_gps_outlier.empty()) expect_flags(m.truth_gps_outlier, g, "/truth/gps_outlier");
  if (!m.truth_marks_mine.empty()) {
    expect_size(m.truth_marks_mine.size(), mk, source, "/truth/marks_mine");
    for (std::size_t j = 0; j < mk; ++j)
      if (m.truth_marks_mine[j] < -1 || m.truth_marks_mine[j] >= m.mine_count)
        bad(source, "/truth/marks_mine", row_text(j) + ": not one of the mission's mines");
  }
}

// The shapes of /truth/position and /truth/mines against the mission's (metadata only).
void check_truth_shapes(const H5File& f, const std::string& path, const Mission& m) {
  const auto expect = [&](const char* dataset, std::size_t rows, const char* what) {
    if (!f.has(dataset)) return;
    const H5Shape s = f.shape(dataset);
    if (s.rank != 2 || s.columns != 3 || s.rows != rows)
      throw FormatError(path + ": " + dataset + ": expected " + std::to_string(rows) + " x 3 (" + what + "), found " +
                        std::to_string(s.rows) + " x " + std::to_string(s.columns));
  };
  expect("/truth/position", m.size(), "one row per navigation sample");
  expect("/truth/mines", static_cast<std::size_t>(m.mine_count), "one row per mine");
}

// Hands /truth/position to `positions` block by block, each value checked finite as
// validate_truth() checks the whole arrays.
void stream_truth_positions(const H5File& f, const std::string& path, const MissionReader::TruthPositions& positions) {
  H5File::RowBlocks blocks(f, "/truth/position", 3, 2);
  for (std::span<const double> rows = blocks.next(); !rows.empty(); rows = blocks.next()) {
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (!std::isfinite(rows[i]))
        bad(path, "/truth/position",
            row_text(blocks.first() + i / 3) + ": position is " + (std::isnan(rows[i]) ? "NaN" : "infinite"));
    positions(blocks.first(), rows);
  }
}

// Reads /truth into m, whose navigation and marks are read (their shapes are the truth's);
// the positions to `positions` instead when given.
void read_truth_datasets(const H5File& f, const std::string& path, Mission& m,
                         const MissionReader::TruthPositions* positions = nullptr) {
  check_truth_shapes(f, path, m);
  if (f.has("/truth/position") && positions) stream_truth_positions(f, path, *positions);
  if (f.has("/truth/position") && !positions) {
    std::vector<double>* position[3] = {&m.truth_x, &m.truth_y, &m.truth_z};
    f.read_columns_into("/truth/position", position);
  }
  if (f.has("/truth/mines")) m.truth_mines = f.read_doubles("/truth/mines", 2);
  if (f.has("/truth/missed_marks")) m.truth_missed_marks = f.read_doubles("/truth/missed_marks", 2);
  // Each per-mark or per-fix array has their rows when present, none included: an empty
  // one would read as absent.
  const auto per_row = [&](const char* dataset, std::size_t rows, std::vector<std::int32_t>& out) {
    if (!f.has(dataset)) return;
    out = f.read_ints(dataset, 1);
    expect_size(out.size(), rows, path, dataset);
  };
  per_row("/truth/marks_outlier", m.mark_count(), m.truth_marks_outlier);
  per_row("/truth/marks_mine", m.mark_count(), m.truth_marks_mine);
  per_row("/truth/gps_outlier", m.gps_time.size(), m.truth_gps_outlier);
}

void clear_truth(Mission& m) {
  for (auto* column : {&m.truth_x, &m.truth_y, &m.truth_z, &m.truth_mines, &m.truth_missed_marks})
    std::vector<double>().swap(*column);
  for (auto* flags : {&m.truth_marks_outlier, &m.truth_marks_mine, &m.truth_gps_outlier})
    std::vector<std::int32_t>().swap(*flags);
}

}  // namespace

void validate_mission(const Mission& m, const std::string& source) {
  const std::size_t n = m.size();
  if (n < 2) bad(source, "/nav/time", "a mission needs at least 2 samples, found " + std::to_string(n));
  expect_finite(m.time, source, "/nav/time", "time");
  for (std::size_t k = 1; k < n; ++k)
    if (!(m.time[k] > m.time[k - 1]))
      bad(source, "/nav/time", row_text(k) + ": time does not increase (" + format_number(m.time[k]) + " after " +
                                   format_number(m.time[k - 1]) + ")");
  const std::pair<const std::vector<double>*, const char*> nav[] = {
      {&m.roll, "/nav/attitude roll"}, {&m.pitch, "/nav/attitude pitch"}, {&m.heading, "/nav/attitude heading"},
      {&m.vx, "/nav/velocity x"},      {&m.vy, "/nav/velocity y"},        {&m.vz, "/nav/velocity z"},
      {&m.altitude, "/nav/altitude"},  {&m.depth, "/nav/depth"}};
  for (const auto& [values, name] : nav) {
    expect_size(values->size(), n, source, name);
    expect_finite(*values, source, name, "value");
  }
  for (const NavChannel& c : nav_channels()) {
    const std::vector<double>& hw = m.half_widths.*c.half_widths;
    if (hw.empty()) continue;
    const std::string name = half_width_dataset(c);
    expect_size(hw.size(), n, source, name);
    for (std::size_t k = 0; k < n; ++k)
      if (!(hw[k] >= 0.0) || !std::isfinite(hw[k])) bad(source, name, row_text(k) + ": half-width must be finite and >= 0");
  }
  const std::string model_error = m.model.validate();
  if (!model_error.empty()) bad(source, "/model", model_error);
  if (m.mine_count < 0 || m.mine_count > kMaxMines)
    bad(source, "/", "mine_count must be between 0 and " + std::to_string(kMaxMines));
  if (!std::isfinite(m.origin.latitude) || std::fabs(m.origin.latitude) > 89.0 || !std::isfinite(m.origin.longitude) ||
      std::fabs(m.origin.longitude) > 180.0)
    bad(source, "/", "origin_latitude/origin_longitude out of range");

  // GPS.
  const std::size_t g = m.gps_time.size();
  expect_size(m.gps_latitude.size(), g, source, "/gps/lonlat");
  expect_size(m.gps_longitude.size(), g, source, "/gps/lonlat");
  expect_finite(m.gps_time, source, "/gps/time", "time");
  for (std::size_t i = 0; i < g; ++i) {
    if (i > 0 && !(m.gps_time[i] > m.gps_time[i - 1]))
      bad(source, "/gps/time", row_text(i) + ": fix times must increase (" + format_number(m.gps_time[i]) + " after " +
                                   format_number(m.gps_time[i - 1]) + ")");
    if (m.gps_time[i] < m.time.front() || m.gps_time[i] > m.time.back())
      bad(source, "/gps/time", row_text(i) + ": fix time " + format_number(m.gps_time[i]) + " s is outside the mission");
    if (!std::isfinite(m.gps_latitude[i]) || std::fabs(m.gps_latitude[i]) > 90.0)
      bad(source, "/gps/lonlat", row_text(i) + ": latitude must be in [-90, 90]");
    if (!std::isfinite(m.gps_longitude[i]) || std::fabs(m.gps_longitude[i]) > 180.0)
      bad(source, "/gps/lonlat", row_text(i) + ": longitude must be in [-180, 180]");
  }
  if (!m.gps_given_north_halfwidth.empty() || !m.gps_given_east_halfwidth.empty()) {
    expect_size(m.gps_given_north_halfwidth.size(), g, source, "/gps/halfwidth north");
    expect_size(m.gps_given_east_halfwidth.size(), g, source, "/gps/halfwidth east");
    for (std::size_t i = 0; i < g; ++i)
      if (!(m.gps_given_north_halfwidth[i] >= 0.0) || !std::isfinite(m.gps_given_north_halfwidth[i]) ||
          !(m.gps_given_east_halfwidth[i] >= 0.0) || !std::isfinite(m.gps_given_east_halfwidth[i]))
        bad(source, "/gps/halfwidth", row_text(i) + ": half-width must be finite and >= 0");
  }

  // Marks.
  const std::size_t mk = m.mark_time.size();
  expect_size(m.mark_mine.size(), mk, source, "/marks/mine");
  expect_size(m.mark_range.size(), mk, source, "/marks/range");
  expect_size(m.mark_side.size(), mk, source, "/marks/side");
  const MarkRules rules = mark_rules(m);
  for (std::size_t j = 0; j < mk; ++j)
    if (const auto problem = check_mark(rules, m.mark_time[j], m.mark_mine[j], m.mark_range[j], m.mark_side[j]))
      bad(source, std::string("/marks/") + mark_field_name(problem->field), row_text(j) + ": " + problem->reason);

  validate_truth(m, source);
}

Mission read_mission(const std::string& path, TruthReading truth) { return MissionReader(path).read(truth); }

MissionReader::MissionReader(const std::string& path) : path_(path), file_(H5File::open_read(path)) {}

Mission MissionReader::read(TruthReading truth) const {
  const H5File& f = file_;
  const std::string& path = path_;
  Mission m;
  const std::int64_t version = check_format(f, kMissionFormat, "gesmi mission", kMissionVersions);
  const auto required_double = [&](const std::string& object, const std::string& name) {
    const auto v = f.double_attribute(object, name);
    if (!v) throw FormatError(path + ": " + object + ": missing attribute " + name);
    return *v;
  };
  m.origin.latitude = required_double("/", "origin_latitude");
  m.origin.longitude = required_double("/", "origin_longitude");
  const auto mines = f.int_attribute("/", "mine_count");
  if (!mines) throw FormatError(path + ": /: missing attribute mine_count");
  if (*mines < 0 || *mines > kMaxMines)
    throw FormatError(path + ": /: mine_count must be between 0 and " + std::to_string(kMaxMines));
  m.mine_count = static_cast<int>(*mines);
  m.model = read_model_attributes(f, "/model", version);
  if (const auto epoch = f.string_attribute("/", "epoch_utc")) {
    m.epoch = parse_epoch_utc(*epoch);
    if (!m.epoch)
      throw FormatError(path + ": /: epoch_utc: expected a UTC time YYYY-MM-DDThh:mm:ssZ, found " + quoted_input(*epoch));
  }
  for (const auto& [name, member] : conversion_margin_attributes())
    if (const auto margin = f.double_attribute("/", name)) {
      if (!std::isfinite(*margin) || *margin < 0.0 || *margin > 1e-6)
        throw FormatError(path + ": /: " + name + ": expected a rounding margin in [0, 1e-6], found " + format_number(*margin));
      m.conversion_margins.*member = *margin;
    }

  // Navigation, read column by column into the flat arrays (one copy of the data).
  m.time = f.read_doubles("/nav/time", 1);
  const std::size_t n = m.time.size();
  const auto columns = [&](const std::string& dataset, std::vector<double>* out[3]) {
    const H5Shape s = f.shape(dataset);
    if (s.rank != 2 || s.columns != 3 || s.rows != n)
      throw FormatError(path + ": " + dataset + ": expected " + std::to_string(n) + " x 3, found " + std::to_string(s.rows) +
                        " x " + std::to_string(s.columns));
    f.read_columns_into(dataset, std::span<std::vector<double>* const>(out, 3));
  };
  std::vector<double>* attitude[3] = {&m.roll, &m.pitch, &m.heading};
  std::vector<double>* velocity[3] = {&m.vx, &m.vy, &m.vz};
  columns("/nav/attitude", attitude);
  columns("/nav/velocity", velocity);
  m.altitude = f.read_doubles("/nav/altitude", 1);
  m.depth = f.read_doubles("/nav/depth", 1);
  // A per-sample bound of another name would be ignored, its channel keeping the model's.
  if (f.has_group("/nav/half_widths"))
    for (const std::string& member : f.members("/nav/half_widths", 64)) {
      const auto& channels = nav_channels();
      if (std::none_of(channels.begin(), channels.end(), [&](const NavChannel& c) { return c.name == member; }))
        throw FormatError(path + ": /nav/half_widths/" + member +
                          ": not a navigation channel (roll, pitch, heading, vx, vy, vz, altitude or depth)");
    }
  for (std::size_t i = 0; i < nav_channels().size(); ++i)
    if (const std::string name = half_width_dataset(nav_channels()[i]); f.has(name)) {
      m.half_widths.*nav_channels()[i].half_widths = f.read_doubles(name, 1);
      // (checked here, where the dataset is known to be present: an empty one would
      // read as no bounds given, the model's)
      expect_size((m.half_widths.*nav_channels()[i].half_widths).size(), m.time.size(), path, name);
      m.half_widths.fill[i] = read_fill(f, name, m.time.size());
      m.half_widths.fill_recorded = version >= 4;
    }
  // Optional groups: absent, or complete.
  const auto require_all = [&](const std::string& group, std::initializer_list<const char*> datasets) {
    if (!f.has_group(group)) return false;
    for (const char* name : datasets)
      if (!f.has(group + "/" + name))
        throw FormatError(path + ": " + group + "/" + name + ": missing dataset (the " + group + " group needs it)");
    return true;
  };
  if (require_all("/gps", {"time", "lonlat"})) {
    m.gps_time = f.read_doubles("/gps/time", 1);
    const H5Shape s = f.shape("/gps/lonlat");
    if (s.rank != 2 || s.columns != 2 || s.rows != m.gps_time.size())
      throw FormatError(path + ": /gps/lonlat: expected " + std::to_string(m.gps_time.size()) + " x 2");
    std::vector<double>* lonlat[2] = {&m.gps_longitude, &m.gps_latitude};
    f.read_columns_into("/gps/lonlat", lonlat);
    if (f.has("/gps/halfwidth")) {
      const H5Shape h = f.shape("/gps/halfwidth");
      if (h.rank != 2 || h.columns != 2 || h.rows != s.rows)
        throw FormatError(path + ": /gps/halfwidth: expected " + std::to_string(s.rows) + " x 2");
      std::vector<double>* halfwidth[2] = {&m.gps_given_north_halfwidth, &m.gps_given_east_halfwidth};
      f.read_columns_into("/gps/halfwidth", halfwidth);
    }
  }
  if (require_all("/marks", {"time", "mine", "range", "side"})) {
    m.mark_time = f.read_doubles("/marks/time", 1);
    m.mark_mine = f.read_ints("/marks/mine", 1);
    m.mark_range = f.read_doubles("/marks/range", 1);
    m.mark_side = f.read_ints("/marks/side", 1);
  }
  if (truth == TruthReading::skip) {
    // A damaged truth is refused before any work all the same: checked as read() checks
    // it, the positions block by block, and none of it kept.
    const TruthPositions unkept = [](std::size_t, std::span<const double>) {};
    read_truth_datasets(f, path, m, &unkept);
    validate_mission(m, path);
    clear_truth(m);
    fill_local_gps(m, path);
    return m;
  }
  read_truth_datasets(f, path, m);
  validate_mission(m, path);
  fill_local_gps(m, path);
  return m;
}

void MissionReader::read_truth(Mission& m) const { read_truth_into(m, nullptr); }

void MissionReader::read_truth(Mission& m, const TruthPositions& positions) const { read_truth_into(m, &positions); }

void MissionReader::read_truth_into(Mission& m, const TruthPositions* positions) const {
  if (m.has_truth() || !m.truth_mines.empty()) throw std::logic_error("MissionReader::read_truth: the truth was read already");
  try {
    read_truth_datasets(file_, path_, m, positions);
    validate_truth(m, path_);
  } catch (...) {  // the mission stays as it was: without truth
    clear_truth(m);
    throw;
  }
}

void write_mission(const Mission& m, const std::string& path) {
  validate_mission(m, path);
  AtomicOutput out(path);
  {
    H5File f = H5File::create(out.temp_path(), path);
    const std::size_t n = m.size();
    const auto interleave = [&](const std::vector<double>& a, const std::vector<double>& b, const std::vector<double>& c) {
      std::vector<double> rows(3 * a.size());
      for (std::size_t k = 0; k < a.size(); ++k) {
        rows[3 * k] = a[k];
        rows[3 * k + 1] = b[k];
        rows[3 * k + 2] = c[k];
      }
      return rows;
    };
    f.write("/nav/time", m.time, n);
    f.write("/nav/attitude", interleave(m.roll, m.pitch, m.heading), n, 3, 2);
    f.write("/nav/velocity", interleave(m.vx, m.vy, m.vz), n, 3, 2);
    f.write("/nav/altitude", m.altitude, n);
    f.write("/nav/depth", m.depth, n);
    for (std::size_t i = 0; i < nav_channels().size(); ++i)
      if (const std::vector<double>& hw = m.half_widths.*nav_channels()[i].half_widths; !hw.empty()) {
        f.write(half_width_dataset(nav_channels()[i]), hw, n);
        write_fill(f, half_width_dataset(nav_channels()[i]), m.half_widths.fill[i]);
      }
    const std::size_t g = m.gps_time.size();
    f.write("/gps/time", m.gps_time, g);
    std::vector<double> lonlat(2 * g);
    for (std::size_t i = 0; i < g; ++i) {
      lonlat[2 * i] = m.gps_longitude[i];
      lonlat[2 * i + 1] = m.gps_latitude[i];
    }
    f.write("/gps/lonlat", lonlat, g, 2, 2);
    if (!m.gps_given_north_halfwidth.empty()) {
      std::vector<double> bounds(2 * g);
      for (std::size_t i = 0; i < g; ++i) {
        bounds[2 * i] = m.gps_given_north_halfwidth[i];
        bounds[2 * i + 1] = m.gps_given_east_halfwidth[i];
      }
      f.write("/gps/halfwidth", bounds, g, 2, 2);
    }
    const std::size_t mk = m.mark_count();
    f.write("/marks/time", m.mark_time, mk);
    f.write("/marks/mine", m.mark_mine, mk);
    f.write("/marks/range", m.mark_range, mk);
    f.write("/marks/side", m.mark_side, mk);
    if (m.has_truth()) f.write("/truth/position", interleave(m.truth_x, m.truth_y, m.truth_z), n, 3, 2);
    if (!m.truth_mines.empty()) f.write("/truth/mines", m.truth_mines, m.truth_mines.size() / 3, 3, 2);
    if (!m.truth_missed_marks.empty())
      f.write("/truth/missed_marks", m.truth_missed_marks, m.truth_missed_marks.size() / 3, 3, 2);
    if (!m.truth_marks_outlier.empty()) f.write("/truth/marks_outlier", m.truth_marks_outlier, mk);
    if (!m.truth_marks_mine.empty()) f.write("/truth/marks_mine", m.truth_marks_mine, mk);
    if (!m.truth_gps_outlier.empty()) f.write("/truth/gps_outlier", m.truth_gps_outlier, g);
    write_format(f, kMissionFormat, kMissionVersions);
    write_origin(f, m.origin);
    f.set_attribute("/", "mine_count", static_cast<std::int64_t>(m.mine_count));
    if (m.epoch) f.set_attribute("/", "epoch_utc", format_iso8601(*m.epoch));
    for (const auto& [name, member] : conversion_margin_attributes())
      if (m.conversion_margins.*member != 0.0) f.set_attribute("/", name, m.conversion_margins.*member);
    write_model_attributes(f, "/model", m.model);
    write_provenance(f, "trajectory");
    write_units(f, kMissionUnits);
    write_time_units(f, "/nav/time", "sample time", m.epoch);
    write_time_units(f, "/gps/time", "GPS fix time", m.epoch);
    write_time_units(f, "/marks/time", "sonar mark time", m.epoch);
    f.close();
  }
  out.commit();
}

namespace {

// The channels a model key bounds, by their index in nav_channels(); `rate`: a bound on
// how fast they change, which the import uses to fill samples without a reading (depth
// near the surface, and the DVL, by surface_max_speed); the others bound each reading's
// error, which per-sample half-widths replace.
struct KeyChannels {
  double SensorModel::*key;
  const char* name;
  std::vector<std::size_t> channels;  // roll 0, pitch 1, heading 2, vx 3, vy 4, vz 5, altitude 6, depth 7
  bool rate;
};

std::string channel_text(std::size_t c) { return std::string(nav_channels()[c].name); }

// A --config key that would change nothing, or make a per-sample bound wrong, is
// refused with what holds it: per-sample half-widths replace the model's bound of
// their channel (a log's own, or made at import from the model), and a rate key made
// the import's fills (ChannelFill), which only a new import can redo.
void refuse_per_sample_changes(const Mission& m, const SensorModel& model, const std::string& path) {
  const KeyChannels keys[] = {
      {&SensorModel::roll, "roll", {0}, false},
      {&SensorModel::pitch, "pitch", {1}, false},
      {&SensorModel::heading, "heading", {2}, false},
      {&SensorModel::dvl_relative, "dvl_relative", {3, 4, 5}, false},
      {&SensorModel::dvl_absolute, "dvl_absolute", {3, 4, 5}, false},
      {&SensorModel::altitude, "altitude", {6}, false},
      {&SensorModel::depth_absolute, "depth_absolute", {7}, false},
      {&SensorModel::depth_relative, "depth_relative", {7}, false},
      {&SensorModel::max_attitude_rate, "max_attitude_rate", {0, 1, 2}, true},
      {&SensorModel::surface_max_speed, "surface_max_speed", {3, 4, 5, 7}, true},
      {&SensorModel::max_altitude_rate, "max_altitude_rate", {6}, true},
      {&SensorModel::max_depth_rate, "max_depth_rate", {7}, true},
  };
  const NavHalfWidths& h = m.half_widths;
  for (const KeyChannels& k : keys) {
    if (model.*k.key == m.model.*k.key) continue;
    for (const std::size_t c : k.channels) {
      if ((h.*nav_channels()[c].half_widths).empty()) continue;
      const ChannelFill& fill = h.fill[c];
      const std::string start = path + ": " + k.name + ": ";
      if (!h.fill_recorded)
        throw FormatError(start + "this mission bounds " + channel_text(c) + " per sample (its log's bounds, or "
                          "enclosures between readings made at import), which --config cannot change: import the log "
                          "again with --config");
      if (!fill.key.empty())
        throw FormatError(start + "the import filled " + std::to_string(fill.samples()) + " samples of " +
                          channel_text(c) + " without a reading of their own from the model, which --config cannot "
                          "redo: import the log again with --config");
      if (!k.rate)
        throw FormatError(start + "the log gives " + channel_text(c) + " its own bound per sample, which replaces the "
                          "model's: change the log's half-width column instead");
    }
  }
}

}  // namespace

std::optional<std::string> merge_model_config(Mission& m, const std::string& path) {
  SensorModel model = m.model;
  merge_sensor_model_yaml(path, model);
  return change_model(m, model, path);
}

std::optional<std::string> change_model(Mission& m, SensorModel model, const std::string& path) {
  const SensorModel& before = m.model;
  refuse_per_sample_changes(m, model, path);
  if (const auto gap = longest_gap(m.time); gap && model.step_model == StepModel::sample && before.step_model != StepModel::sample)
    throw FormatError(path + ": step_model: 'sample' cannot cross the mission's gap of " +
                      format_number(m.time[*gap + 1] - m.time[*gap]) + " s at t = " + format_number(m.time[*gap]) +
                      " s soundly (it holds a sample's box over the whole step): use trapezoid or rate-hull");
  // A bound the config replaces gets back what a unit conversion at import added to it.
  const std::pair<double SensorModel::*, double> margins[] = {
      {&SensorModel::roll, m.conversion_margins.roll},
      {&SensorModel::pitch, m.conversion_margins.pitch},
      {&SensorModel::heading, m.conversion_margins.heading},
      {&SensorModel::dvl_absolute, m.conversion_margins.dvl}};
  for (const auto& [key, margin] : margins)
    if (model.*key != before.*key) model.*key = add_up(model.*key, margin);
  // GPS: a fix's own half-widths replace the model's bounds, but a config that sets
  // those bounds says the fixes may be worse than they claim: the larger holds.
  std::optional<std::string> notice;
  const bool gps_changed = model.gps_metres != before.gps_metres || model.gps_lat_deg != before.gps_lat_deg ||
                           model.gps_lon_deg != before.gps_lon_deg;
  if (gps_changed && !m.gps_given_north_halfwidth.empty()) {
    m.gps_model_floor = true;
    notice = path + " sets the GPS bounds of a mission whose fixes carry their own half-widths: each fix's box is the "
                    "larger of the two";
  }
  m.model = model;
  fill_local_gps(m, path);
  return notice;
}

}  // namespace gesmi::io
