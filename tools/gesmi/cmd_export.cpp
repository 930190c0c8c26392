// gesmi export: a mission back to the CSV files of gesmi import (docs/formats.md),
// or to a GESMI text log; a result as CSV (tube, mine boxes) or GeoJSON for GIS.

#include <cstdio>
#include <filesystem>

#include "io/output/atomic_output.h"
#include "io/exports/export_csv.h"
#include "io/exports/export_gesmi_txt.h"
#include "io/exports/export_logger.h"
#include "io/exports/result_exports.h"
#include "io/files/result_file.h"
#include "io/files/mission_digest.h"
#include "io/report/report_json.h"
#include "io/time/utc_time.h"
#include "io/text/message_text.h"
#include "io/files/mission_file.h"
#include "io/output/output_set.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/progress.h"
#include "tools/gesmi/skip_existing.h"
#include "tools/gesmi/inconsistent_gate.h"
#include "tools/gesmi/input_files.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

constexpr std::int64_t kDefaultLoggerEpoch = 1778745600;  // 2026-05-14T08:00:00Z

bool is_result_format(const std::string& format) {
  return format == "tube-csv" || format == "mines-csv" || format == "geojson";
}

// With --json, the report of a mission's export (true when printed).
bool report_mission_export(const po::variables_map& v, const std::string& format, const std::string& output,
                           const Mission& m) {
  CommandReport report("export", v);
  if (!report.enabled()) return false;
  report.inputs(v, {"file"});
  report.output(output);
  report["format"] = format;
  report["mission"] = io::mission_json(m);
  report.finish(kExitOk);
  return true;
}

// A result's exports: one file, every row or feature marked with the result's status.
int export_result(const po::variables_map& v, const std::string& format, const std::string& output,
                  io::OutputSet& outputs) {
  const std::string path = v["file"].as<std::string>();
  Progress progress("gesmi export:");  // on a terminal, for long runs only (progress.h)
  progress.update(-1.0, "reading " + path);
  // The tube CSV reads the whole result again, the tube block by block as it writes its
  // rows, and checks every digest then.
  const io::SolveResult r = io::read_result(
      path, {.tube = format == "geojson", .increments = false, .waterfall = false, .check_unread = format != "tube-csv"});
  if (!r.solution.report.consistent) progress.finish();  // before the refusal's line, or the notes below
  if (!accept_result_status(v, "export", path, r.solution.report.consistent)) return kExitInconsistent;
  // (the CSVs' note on NaN columns comes once they are written: a tube read again may
  // still be refused)
  const std::string geodetic_why = io::geodetic_problem(r.origin);
  if (!geodetic_why.empty() && format == "geojson") throw UsageError(path + ": " + geodetic_why);
  std::optional<Mission> mission;
  if (v.count("mission")) {
    if (format != "geojson") throw UsageError("--mission: only the geojson format uses the mission (its GPS fixes)");
    mission = io::read_mission(v["mission"].as<std::string>(), io::TruthReading::skip);
    if (io::navigation_digest(*mission, io::result_digest_kind(r.format_version)) != r.navigation_digest)
      throw UsageError("--mission: " + v["mission"].as<std::string>() + " is not the mission " + path +
                       " was solved from (its navigation digest differs)");
  }
  progress.update(-1.0, "writing " + output);
  if (format == "tube-csv") io::write_tube_csv(path, r, output);
  if (format == "mines-csv") io::write_mines_csv(r, output);
  if (format == "geojson") io::write_geojson(r, mission ? &*mission : nullptr, output);
  outputs.commit();
  progress.finish();
  if (!geodetic_why.empty())
    std::fprintf(stderr, "%s\n",
                 io::one_line("gesmi export: note: latitude/longitude columns left NaN: " + path + ": " + geodetic_why).c_str());
  CommandReport report("export", v);
  if (report.enabled()) {
    report.inputs(v, {"file", "mission"});
    report.output(output);
    report["format"] = format;
    report["status"] = r.solution.report.consistent ? "consistent" : "inconsistent";
    return report.finish(kExitOk);
  }
  const char* status = r.solution.report.consistent ? "" : ", INCONSISTENT result";
  if (format == "tube-csv") std::printf("wrote %s (%zu samples%s)\n", output.c_str(), r.solution.time.size(), status);
  if (format == "mines-csv") std::printf("wrote %s (%d mines%s)\n", output.c_str(), r.solution.mine_count, status);
  if (format == "geojson")
    std::printf("wrote %s (envelope, %d mine boxes, %zu GPS fixes%s)\n", output.c_str(), r.solution.mine_count,
                mission ? mission->gps_time.size() : std::size_t{0}, status);
  return kExitOk;
}

int run_export(std::span<const std::string> args) {
  po::options_description options("export options");
  options.add_options()
      ("file", po::value<std::string>()->required(), "mission file (csv, logger, gesmi-txt) or result file (tube-csv, mines-csv, geojson)")
      ("format", po::value<std::string>()->default_value("csv"),
       "a mission: csv (a folder of CSV files), logger (a folder: multi-rate log, map, NMEA, marks) or gesmi-txt (one file); "
       "a result: tube-csv (the tube per sample, local and latitude/longitude bounds), mines-csv (the mine boxes) or "
       "geojson (envelope and mine boxes for GIS)")
      ("output,o", po::value<std::string>()->required(), "folder to create (csv, logger) or file to write (the others)")
      ("mission", po::value<std::string>(), "geojson: the result's mission, to add its GPS fixes as points")
      ("epoch", po::value<std::string>(), "logger: UTC time of t = 0, whole seconds (default: the mission's, else 2026-05-14T08:00:00Z)")
      ("dvl-every", po::value<std::string>()->default_value("2"), "logger: a DVL reading every N samples")
      ("depth-every", po::value<std::string>()->default_value("10"), "logger: a depth reading every N samples")
      ("dvl-gap", po::value<std::string>(), "logger: no DVL reading from FROM to TO s (FROM:TO)");
  add_show_inconsistent(options);
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("file", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi export MISSION.h5 -o DIR [--format csv|logger|gesmi-txt] [logger options]\n"
                     "       gesmi export RESULT.h5 -o FILE --format tube-csv|mines-csv|geojson [--mission MISSION.h5] "
                     "[--show-inconsistent] [--skip-existing]"))
    return kExitOk;
  const std::string format = v["format"].as<std::string>(), output = v["output"].as<std::string>();
  if (format != "csv" && format != "gesmi-txt" && format != "logger" && !is_result_format(format))
    throw UsageError("--format: expected csv, logger, gesmi-txt, tube-csv, mines-csv or geojson, got " + io::quoted_input(format));
  io::OutputSet outputs(input_files(v, {"file", "mission"}));
  if (is_result_format(format)) {
    outputs.check(output);
    if (skipped_as_existing(v, "export", {output})) return kExitOk;
    return export_result(v, format, output, outputs);
  }
  if (format == "csv" || format == "logger") {
    // A folder export is renamed into place whole, so its last file stands for it.
    const std::string last = (std::filesystem::path(output) / "import-command.txt").string();
    if (skipped_as_existing(v, "export", {last})) return kExitOk;
    io::check_export_folder(output);
  } else {
    outputs.check(output);
    if (skipped_as_existing(v, "export", {output})) return kExitOk;
  }
  Progress progress("gesmi export:");
  progress.update(-1.0, "reading " + v["file"].as<std::string>());
  const Mission m = io::read_mission(v["file"].as<std::string>());
  progress.update(-1.0, "writing " + output);
  if (format == "csv") {
    outputs.prepare_folder(output);
    io::export_mission_csv(m, output);
    outputs.commit();
    progress.finish();
    if (report_mission_export(v, format, output, m)) return kExitOk;
    std::printf("wrote %s/: nav.csv (%zu rows), gps.csv (%zu), marks.csv (%zu)%s%s, model.yaml, import-command.txt\n",
                output.c_str(), m.size(), m.gps_time.size(), m.mark_count(), m.has_truth() ? ", truth.csv" : "",
                m.truth_mines.empty() ? "" : ", truth_mines.csv");
    return kExitOk;
  }
  if (format == "logger") {
    io::LoggerExportOptions o;
    o.epoch = m.epoch.value_or(kDefaultLoggerEpoch);
    if (v.count("epoch")) {
      std::string why;
      const auto epoch = io::parse_epoch_utc(v["epoch"].as<std::string>(), &why);
      if (!epoch) throw UsageError("--epoch: expected the UTC time of t = 0 in whole seconds, like 2026-05-14T08:00:00Z (" + why + ")");
      o.epoch = *epoch;
    }
    const auto count = [&](const char* name) {
      const long long n = parse_integer(std::string("--") + name, v[name].as<std::string>());
      if (n < 1) throw UsageError(std::string("--") + name + ": must be at least 1");
      return static_cast<std::size_t>(n);
    };
    o.dvl_every = count("dvl-every");
    o.depth_every = count("depth-every");
    if (v.count("dvl-gap")) {
      const std::string text = v["dvl-gap"].as<std::string>();
      const std::size_t colon = text.find(':');
      if (colon == std::string::npos) throw UsageError("--dvl-gap: expected FROM:TO in seconds, got " + io::quoted_input(text));
      o.dvl_gap = {parse_double("--dvl-gap", text.substr(0, colon)), parse_double("--dvl-gap", text.substr(colon + 1))};
    }
    outputs.prepare_folder(output);
    io::export_mission_logger(m, v["file"].as<std::string>(), output, o);
    outputs.commit();
    progress.finish();
    if (report_mission_export(v, format, output, m)) return kExitOk;
    std::printf("wrote %s/: log.csv (%zu rows), map.yaml, gps.nmea (%zu fixes), marks.csv (%zu), marks_map.yaml, model.yaml%s%s, "
                "import-command.txt\n",
                output.c_str(), m.size(), m.gps_time.size(), m.mark_count(), m.has_truth() ? ", truth.csv" : "",
                m.truth_mines.empty() ? "" : ", truth_mines.csv");
    return kExitOk;
  }
  io::export_gesmi_txt(m, v["file"].as<std::string>(), output);
  outputs.commit();
  progress.finish();
  if (report_mission_export(v, format, output, m)) return kExitOk;
  std::printf("wrote %s: %zu rows, %zu position fixes (marks are not part of the GESMI text format)\n", output.c_str(),
              m.size(), m.gps_time.size());
  return kExitOk;
}

const bool export_registered =
    register_command({"export", "write a mission as CSV files (or a GESMI text log)", run_export});

}  // namespace
}  // namespace gesmi::cli
