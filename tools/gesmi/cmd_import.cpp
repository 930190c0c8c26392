// gesmi import marks|nav|gesmi-txt: missions from text files (docs/formats.md).

#include <cmath>
#include <cstdio>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/imports/import_mission.h"
#include "io/text/message_text.h"
#include "io/time/utc_time.h"
#include "io/files/mission_file.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/progress.h"
#include "io/report/report_json.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

GeoOrigin parse_origin(const std::string& text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos) throw UsageError("--origin: expected LAT,LON in degrees, got " + io::quoted_input(text));
  const GeoOrigin o{parse_double("--origin", text.substr(0, comma)), parse_double("--origin", text.substr(comma + 1))};
  if (!std::isfinite(o.latitude) || std::fabs(o.latitude) > 89.0)
    throw UsageError("--origin: latitude must be in [-89, 89] degrees, got " + io::quoted_input(text));
  if (!std::isfinite(o.longitude) || std::fabs(o.longitude) > 180.0)
    throw UsageError("--origin: longitude must be in [-180, 180] degrees, got " + io::quoted_input(text));
  return o;
}

std::optional<int> parse_mines(const po::variables_map& v) {
  if (!v.count("mines")) return std::nullopt;
  const long long k = parse_integer("--mines", v["mines"].as<std::string>());
  if (k < 0 || k > kMaxMines) throw UsageError("--mines: must be between 0 and " + std::to_string(kMaxMines));
  return static_cast<int>(k);
}

std::optional<std::int64_t> parse_epoch(const po::variables_map& v) {
  if (!v.count("epoch")) return std::nullopt;
  std::string why;
  const auto epoch = io::parse_epoch_utc(v["epoch"].as<std::string>(), &why);
  if (!epoch) throw UsageError("--epoch: expected the UTC time of t = 0 in whole seconds, like 2026-05-14T08:00:00Z (" + why + ")");
  return epoch;
}

std::optional<std::int64_t> parse_date(const po::variables_map& v) {
  if (!v.count("date")) return std::nullopt;
  const std::string text = v["date"].as<std::string>();
  const io::ParsedTime parsed = io::parse_iso8601(text + "T00:00:00Z");
  if (text.size() != 10 || !parsed.time) throw UsageError("--date: expected a UTC date YYYY-MM-DD, got " + io::quoted_input(text));
  return parsed.time->seconds / 86400;
}

io::GpsFormat parse_gps_format(const po::variables_map& v) {
  const std::string text = v["gps-format"].as<std::string>();
  if (text == "detect") return io::GpsFormat::detect;
  if (text == "csv") return io::GpsFormat::csv;
  if (text == "nmea") return io::GpsFormat::nmea;
  throw UsageError("--gps-format: expected detect, csv or nmea, got " + io::quoted_input(text));
}

std::string optional_path(const po::variables_map& v, const char* name) {
  return v.count(name) ? v[name].as<std::string>() : std::string();
}

// The summary, or with --json the report: every file option given is an input.
int finish_import(const po::variables_map& v, std::string_view kind, std::initializer_list<const char*> input_options,
                  const Mission& m, const std::string& output, const io::ImportNotes& notes = {}) {
  CommandReport report("import " + std::string(kind), v);
  if (report.enabled()) {
    report.inputs(v, input_options);
    report.output(output);
    report["mission"] = io::mission_json(m);
    report["notes"] = notes.lines;
    report["unused_fixes"] = nlohmann::json::array();
    for (const io::UnusedFix& f : notes.unused_fixes)
      report["unused_fixes"].push_back({{"where", f.where}, {"time_s", f.time}, {"reason", f.reason}});
    return report.finish(kExitOk);
  }
  for (const std::string& note : notes.lines) std::printf("%s\n", note.c_str());
  for (const io::UnusedFix& f : notes.unused_fixes) std::fprintf(stderr, "%s\n", io::unused_fix_line(f).c_str());
  const std::string epoch = m.epoch ? ", t = 0 at " + io::format_iso8601(*m.epoch) : std::string();
  std::printf("wrote %s: %zu samples over %g s, %zu GPS fixes, %zu marks, %d mines%s\n", output.c_str(), m.size(),
              m.time.back() - m.time.front(), m.gps_time.size(), m.mark_count(), m.mine_count, epoch.c_str());
  return kExitOk;
}

int import_marks(std::span<const std::string> args) {
  po::options_description options("import marks options");
  options.add_options()
      ("marks", po::value<std::string>()->required(), "marks CSV: time,mine,range,side")
      ("map", po::value<std::string>(), "column map (YAML) of the marks file: time, mine, range, side")
      ("into", po::value<std::string>()->required(), "mission file whose mark table is replaced")
      ("mines", po::value<std::string>(), "number of mines K (default: the mission's)")
      ("output,o", po::value<std::string>()->required(), "mission file to write");
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("marks", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi import marks FILE.csv --into MISSION.h5 [--map MAP.yaml] [--mines K] -o OUT.h5 [--skip-existing]"))
    return kExitOk;
  const std::string output = v["output"].as<std::string>();
  const auto file_options = {"marks", "into", "map"};  // the options naming files read
  io::OutputSet outputs(input_files(v, file_options));
  outputs.check(output);
  const std::optional<int> mines = parse_mines(v);
  if (skipped_as_existing(v, "import marks", {output})) return kExitOk;
  Progress progress("gesmi import:");
  progress.update(-1.0, "reading " + v["into"].as<std::string>() + " and " + v["marks"].as<std::string>());
  Mission m = io::read_mission(v["into"].as<std::string>());
  io::import_marks(m, v["marks"].as<std::string>(), mines, optional_path(v, "map"));
  progress.update(-1.0, "writing " + output);
  io::write_mission(m, output);
  outputs.commit();
  progress.finish();
  return finish_import(v, "marks", file_options, m, output);
}

int import_nav(std::span<const std::string> args) {
  po::options_description options("import nav options");
  options.add_options()
      ("nav", po::value<std::string>()->required(), "navigation CSV: time,roll,pitch,heading,vx,vy,vz,altitude,depth")
      ("map", po::value<std::string>(), "column map (YAML) of a logger export: columns, units, time format (docs/formats.md)")
      ("epoch", po::value<std::string>(), "UTC time of t = 0 for a log in seconds, like 2026-05-14T08:00:00Z")
      ("gps", po::value<std::string>(), "GPS fixes: CSV time,longitude,latitude or NMEA 0183 (GGA, RMC)")
      ("gps-format", po::value<std::string>()->default_value("detect"), "detect, csv or nmea")
      ("date", po::value<std::string>(), "UTC date YYYY-MM-DD of an NMEA log's first fix, when it has no RMC")
      ("marks", po::value<std::string>(), "marks CSV: time,mine,range,side")
      ("marks-map", po::value<std::string>(), "column map (YAML) of the marks file")
      ("origin", po::value<std::string>(), "local frame origin LAT,LON in degrees (default: the first GPS fix)")
      ("config", po::value<std::string>(), "sensor model YAML over the reference defaults")
      ("mines", po::value<std::string>(), "number of mines K (default: the rows of --truth-mines, else 0)")
      ("truth", po::value<std::string>(), "truth.csv: time,north,east,down (simulated missions)")
      ("truth-mines", po::value<std::string>(), "truth_mines.csv: mine,north,east,down")
      ("output,o", po::value<std::string>()->required(), "mission file to write");
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("nav", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v,
                     "gesmi import nav FILE.csv [--map MAP.yaml] [--epoch UTC] [--gps GPS.csv|GPS.nmea [--date YYYY-MM-DD]] "
                     "[--marks MARKS.csv [--marks-map MAP.yaml]] [--origin LAT,LON] "
                     "[--config bounds.yaml] [--mines K] [--truth truth.csv] [--truth-mines truth_mines.csv] -o OUT.h5 "
                     "[--skip-existing]"))
    return kExitOk;
  const std::string output = v["output"].as<std::string>();
  // the options naming files read
  const auto file_options = {"nav", "map", "gps", "marks", "marks-map", "config", "truth", "truth-mines"};
  io::OutputSet outputs(input_files(v, file_options));
  outputs.check(output);
  io::ImportInputs inputs;
  inputs.map = optional_path(v, "map");
  inputs.epoch = parse_epoch(v);
  inputs.gps = optional_path(v, "gps");
  inputs.gps_format = parse_gps_format(v);
  inputs.gps_date = parse_date(v);
  inputs.marks = optional_path(v, "marks");
  inputs.marks_map = optional_path(v, "marks-map");
  inputs.config = optional_path(v, "config");
  inputs.truth = optional_path(v, "truth");
  inputs.truth_mines = optional_path(v, "truth-mines");
  if (v.count("origin")) inputs.origin = parse_origin(v["origin"].as<std::string>());
  inputs.mines = parse_mines(v);
  if (skipped_as_existing(v, "import nav", {output})) return kExitOk;
  io::ImportNotes notes;
  Progress progress("gesmi import:");
  progress.update(-1.0, "reading " + v["nav"].as<std::string>() + " and its fixes and marks");
  const Mission m = io::import_nav(v["nav"].as<std::string>(), inputs, &notes);
  progress.update(-1.0, "writing " + output);
  io::write_mission(m, output);
  outputs.commit();
  progress.finish();
  return finish_import(v, "nav", file_options, m, output, notes);
}

int import_gesmi_txt(std::span<const std::string> args) {
  po::options_description options("import gesmi-txt options");
  options.add_options()
      ("log", po::value<std::string>()->required(), "GESMI text log (rows of 21 numbers)")
      ("origin", po::value<std::string>(), "geodetic origin LAT,LON of the log's x/y frame (default: the Redermor start fix)")
      ("config", po::value<std::string>(), "sensor model YAML over the reference defaults")
      ("xy", po::value<std::string>()->default_value("fixes"), "x/y columns: fixes (rows with half-widths) or truth")
      ("marks", po::value<std::string>(), "marks CSV: time,mine,range,side")
      ("mines", po::value<std::string>(), "number of mines K (default 0)")
      ("output,o", po::value<std::string>()->required(), "mission file to write");
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("log", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v,
                     "gesmi import gesmi-txt FILE [--origin LAT,LON] [--config bounds.yaml] [--xy fixes|truth] "
                     "[--marks MARKS.csv] [--mines K] -o OUT.h5 [--skip-existing]"))
    return kExitOk;
  const std::string xy = v["xy"].as<std::string>();
  if (xy != "fixes" && xy != "truth") throw UsageError("--xy: expected fixes or truth, got " + io::quoted_input(xy));
  const std::string output = v["output"].as<std::string>();
  const auto file_options = {"log", "marks", "config"};  // the options naming files read
  io::OutputSet outputs(input_files(v, file_options));
  outputs.check(output);
  io::ImportInputs inputs;
  inputs.marks = optional_path(v, "marks");
  inputs.config = optional_path(v, "config");
  if (v.count("origin")) inputs.origin = parse_origin(v["origin"].as<std::string>());
  inputs.mines = parse_mines(v);
  if (skipped_as_existing(v, "import gesmi-txt", {output})) return kExitOk;
  Progress progress("gesmi import:");
  progress.update(-1.0, "reading " + v["log"].as<std::string>());
  const Mission m = io::import_gesmi_txt(v["log"].as<std::string>(), xy == "fixes" ? io::GesmiXy::fixes : io::GesmiXy::truth, inputs);
  progress.update(-1.0, "writing " + output);
  io::write_mission(m, output);
  outputs.commit();
  progress.finish();
  return finish_import(v, "gesmi-txt", file_options, m, output);
}

int run_import(std::span<const std::string> args) {
  if (args.empty()) throw UsageError("expected marks, nav or gesmi-txt (gesmi import nav --help)");
  const std::string kind = args[0];
  if (kind == "marks") return import_marks(args.subspan(1));
  if (kind == "nav") return import_nav(args.subspan(1));
  if (kind == "gesmi-txt") return import_gesmi_txt(args.subspan(1));
  if (kind == "--help" || kind == "-h") {
    std::printf("usage: gesmi import marks|nav|gesmi-txt ... ('gesmi import nav --help'; formats in docs/formats.md)\n");
    return kExitOk;
  }
  throw UsageError("unknown kind " + io::quoted_input(kind) + ": expected marks, nav or gesmi-txt");
}

const bool import_registered =
    register_command({"import", "make or update a mission from CSV or GESMI text files", run_import});

}  // namespace
}  // namespace gesmi::cli
