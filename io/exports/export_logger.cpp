#include "io/exports/export_logger.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "io/exports/export_csv.h"
#include "io/files/sensor_model_yaml.h"
#include "io/format_error.h"
#include "io/output/output_set.h"
#include "io/text/csv_number.h"
#include "io/time/utc_time.h"

namespace gesmi::io {
namespace {

namespace fs = std::filesystem;

constexpr double kDegreesPerRadian = 57.29577951308232;

// An instant epoch + t split into whole seconds and a decimal fraction of `digits`
// digits, and the time in seconds after `read_epoch` (the whole second of the log's
// first row, which the import takes as its epoch) read back from that text.
struct WrittenTime {
  std::int64_t seconds;
  long long fraction;  // in units of 10^-digits s
  double read_back;
};

WrittenTime written_time(std::int64_t epoch, double t, int digits, std::int64_t read_epoch) {
  const double scale = std::pow(10.0, digits);
  double whole = std::floor(t);
  long long fraction = std::llround((t - whole) * scale);
  if (fraction >= static_cast<long long>(scale)) {
    whole += 1.0;
    fraction = 0;
  }
  const std::int64_t seconds = epoch + static_cast<std::int64_t>(whole);
  char text[32];
  std::snprintf(text, sizeof text, "0.%0*lld", digits, fraction);
  return {seconds, fraction, static_cast<double>(seconds - read_epoch) + *parse_number(text)};
}

std::string iso_time(const WrittenTime& w, int digits) {
  std::string text = format_iso8601(w.seconds);  // "YYYY-MM-DDThh:mm:ssZ"
  char fraction[16];
  std::snprintf(fraction, sizeof fraction, ".%0*lld", digits, w.fraction);
  text.insert(text.size() - 1, fraction);
  return text;
}

// "ddmm.mmmmmmm" (degree_digits = 2) or "dddmm.mmmmmmm", and the hemisphere.
std::string nmea_angle(double degrees, int degree_digits, char positive, char negative) {
  const long long units = std::llround(std::fabs(degrees) * 60.0 * 1e7);  // 1e-7 minute
  const long long whole_degrees = units / 600000000LL, minute_units = units % 600000000LL;
  char text[48];
  std::snprintf(text, sizeof text, "%0*lld%02lld.%07lld,%c", degree_digits, whole_degrees, minute_units / 10000000LL,
                minute_units % 10000000LL, degrees < 0.0 ? negative : positive);
  return text;
}

void write_log(const Mission& m, const LoggerExportOptions& o, const std::vector<unsigned char>& dvl, std::ostream& out) {
  out << "timestamp;hdg_deg;depth_m;status;dvl_x;dvl_y;dvl_z;pitch_deg;alt_m;roll_deg;water_temp\n";
  std::string row;
  const auto field = [&](bool present, double value) {
    row += ';';
    if (present) append_number(row, value);
  };
  for (std::size_t k = 0; k < m.size(); ++k) {
    row = iso_time(written_time(o.epoch, m.time[k], 6, 0), 6);
    const bool in_gap = o.dvl_gap && m.time[k] >= o.dvl_gap->first && m.time[k] <= o.dvl_gap->second;
    field(true, m.heading[k] * kDegreesPerRadian);
    field(k % o.depth_every == 0, m.depth[k]);
    row += ";OK";
    for (const double v : {m.vx[k], m.vy[k], m.vz[k]}) {
      if (in_gap) row += ";NaN";
      else field(dvl[k] != 0, v);
    }
    field(true, m.pitch[k] * kDegreesPerRadian);
    field(dvl[k] != 0, m.altitude[k]);
    field(true, m.roll[k] * kDegreesPerRadian);
    row += ";12.5\n";
    out << row;
  }
}

void write_nmea(const Mission& m, const LoggerExportOptions& o, std::ostream& out) {
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    const WrittenTime w = written_time(o.epoch, m.gps_time[i], 3, 0);
    const std::string iso = format_iso8601(w.seconds);  // YYYY-MM-DDThh:mm:ssZ
    char time_of_day[48];
    std::snprintf(time_of_day, sizeof time_of_day, "%.2s%.2s%.2s.%03lld", iso.data() + 11, iso.data() + 14, iso.data() + 17,
                  w.fraction);
    const std::string date = iso.substr(8, 2) + iso.substr(5, 2) + iso.substr(2, 2);
    const std::string position =
        nmea_angle(m.gps_latitude[i], 2, 'N', 'S') + "," + nmea_angle(m.gps_longitude[i], 3, 'E', 'W');
    out << nmea_sentence("GPRMC," + std::string(time_of_day) + ",A," + position + ",0.0,0.0," + date + ",,,A") << "\r\n";
    out << nmea_sentence("GPGGA," + std::string(time_of_day) + "," + position + ",1,08,0.9,0.0,M,47.0,M,,") << "\r\n";
  }
}

void write_marks(const Mission& m, const LoggerExportOptions& o, std::ostream& out) {
  out << "utc,target,slant_range_m,side\n";
  std::string row;
  for (std::size_t j = 0; j < m.mark_count(); ++j) {
    row = iso_time(written_time(o.epoch, m.mark_time[j], 6, 0), 6) + ",";
    row += m.mark_mine[j] < 0 ? std::string("?") : std::to_string(m.mark_mine[j]);
    row += ',';
    append_number(row, m.mark_range[j]);
    row += m.mark_side[j] > 0 ? ",starboard\n" : ",port\n";
    out << row;
  }
}

}  // namespace

std::string nmea_sentence(const std::string& body) {
  unsigned char sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X", sum);
  return "$" + body + tail;
}

void export_mission_logger(const Mission& m, const std::string& source, const std::string& folder,
                           const LoggerExportOptions& o) {
  if (o.dvl_every == 0 || o.depth_every == 0) throw FormatError("--dvl-every and --depth-every must be at least 1");
  for (const NavChannel& c : nav_channels())
    if (!(m.half_widths.*c.half_widths).empty())
      throw FormatError(source + ": /nav/half_widths/" + std::string(c.name) + ": the mission bounds its " + std::string(c.name) +
                        " per sample, which a logger export cannot carry (its import would take the model's bounds): "
                        "export it with --format csv");
  check_export_folder(folder);
  const fs::path target = fs::path(folder).lexically_normal();
  create_output_folder(folder);

  // The DVL rows: every dvl_every-th sample and the last one, outside the gap.
  const std::size_t n = m.size();
  std::vector<unsigned char> dvl(n, 0);
  const std::int64_t read_epoch = written_time(o.epoch, m.time.front(), 6, 0).seconds;
  Mission grid;  // the truth on every row, at the times the import reads
  for (std::size_t k = 0; k < n; ++k) {
    const bool in_gap = o.dvl_gap && m.time[k] >= o.dvl_gap->first && m.time[k] <= o.dvl_gap->second;
    dvl[k] = !in_gap && (k % o.dvl_every == 0 || k + 1 == n);
    if (!m.has_truth()) continue;
    grid.time.push_back(written_time(o.epoch, m.time[k], 6, read_epoch).read_back);
    grid.truth_x.push_back(m.truth_x[k]);
    grid.truth_y.push_back(m.truth_y[k]);
    grid.truth_z.push_back(m.truth_z[k]);
  }
  grid.truth_mines = m.truth_mines;

  const auto path = [&](const char* name) { return (target / name).string(); };
  write_text_file(path("log.csv"), [&](std::ostream& out) { write_log(m, o, dvl, out); });
  write_text_file(path("map.yaml"), [](std::ostream& out) {
    out << "# Column map of log.csv (docs/formats.md, \"Logger exports\")\n"
           "delimiter: \";\"\n"
           "time:     {column: timestamp, format: iso8601}\n"
           "roll:     {column: roll_deg,  unit: deg}\n"
           "pitch:    {column: pitch_deg, unit: deg}\n"
           "heading:  {column: hdg_deg,   unit: deg}\n"
           "vx:       {column: dvl_x, unit: m/s}\n"
           "vy:       {column: dvl_y, unit: m/s}\n"
           "vz:       {column: dvl_z, unit: m/s}\n"
           "altitude: {column: alt_m}\n"
           "depth:    {column: depth_m}\n";
  });
  write_text_file(path("gps.nmea"), [&](std::ostream& out) { write_nmea(m, o, out); });
  write_text_file(path("marks.csv"), [&](std::ostream& out) { write_marks(m, o, out); });
  write_text_file(path("marks_map.yaml"), [](std::ostream& out) {
    out << "# Column map of marks.csv (docs/formats.md, \"Logger exports\")\n"
           "time:  {column: utc, format: iso8601}\n"
           "mine:  {column: target}\n"
           "range: {column: slant_range_m, unit: m}\n"
           "side:  {column: side}\n";
  });
  write_text_file(path("model.yaml"), [&](std::ostream& out) { out << sensor_model_yaml(m.model); });
  if (m.has_truth()) write_text_file(path("truth.csv"), [&](std::ostream& out) { write_truth_csv(grid, out); });
  if (!m.truth_mines.empty()) write_text_file(path("truth_mines.csv"), [&](std::ostream& out) { write_truth_mines_csv(grid, out); });
  write_text_file(path("import-command.txt"), [&](std::ostream& out) {
    out << "gesmi import nav log.csv --map map.yaml --gps gps.nmea --marks marks.csv --marks-map marks_map.yaml"
           " --config model.yaml --origin "
        << format_number(m.origin.latitude) << "," << format_number(m.origin.longitude) << " --mines " << m.mine_count;
    if (m.has_truth()) out << " --truth truth.csv";
    if (!m.truth_mines.empty()) out << " --truth-mines truth_mines.csv";
    out << " -o mission.h5\n";
  });
}

}  // namespace gesmi::io
