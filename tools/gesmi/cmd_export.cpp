// gesmi export: a mission back to the CSV files of gesmi import (docs/formats.md),
// or to a GESMI text log.

#include <cstdio>

#include "io/output/atomic_output.h"
#include "io/exports/export_csv.h"
#include "io/exports/export_gesmi_txt.h"
#include "io/exports/export_logger.h"
#include "io/time/utc_time.h"
#include "io/text/message_text.h"
#include "io/files/mission_file.h"
#include "io/output/output_set.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/input_files.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

constexpr std::int64_t kDefaultLoggerEpoch = 1778745600;  // 2026-05-14T08:00:00Z

int run_export(std::span<const std::string> args) {
  po::options_description options("export options");
  options.add_options()
      ("mission", po::value<std::string>()->required(), "mission file (HDF5)")
      ("format", po::value<std::string>()->default_value("csv"),
       "csv (a folder of CSV files), logger (a folder: multi-rate log, map, NMEA, marks) or gesmi-txt (one file)")
      ("output,o", po::value<std::string>()->required(), "folder to create (csv, logger) or file to write (gesmi-txt)")
      ("epoch", po::value<std::string>(), "logger: UTC time of t = 0, whole seconds (default: the mission's, else 2026-05-14T08:00:00Z)")
      ("dvl-every", po::value<std::string>()->default_value("2"), "logger: a DVL reading every N samples")
      ("depth-every", po::value<std::string>()->default_value("10"), "logger: a depth reading every N samples")
      ("dvl-gap", po::value<std::string>(), "logger: no DVL reading from FROM to TO s (FROM:TO)");
  po::positional_options_description positional;
  positional.add("mission", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi export MISSION.h5 -o DIR [--format csv|logger|gesmi-txt] [logger options]"))
    return kExitOk;
  const std::string format = v["format"].as<std::string>(), output = v["output"].as<std::string>();
  if (format != "csv" && format != "gesmi-txt" && format != "logger")
    throw UsageError("--format: expected csv, logger or gesmi-txt, got " + io::quoted_input(format));
  io::OutputSet outputs(input_files(v, {"mission"}));
  if (format == "csv" || format == "logger")
    io::check_export_folder(output);
  else
    outputs.check(output);
  const Mission m = io::read_mission(v["mission"].as<std::string>());
  if (format == "csv") {
    outputs.prepare_folder(output);
    io::export_mission_csv(m, output);
    outputs.commit();
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
    io::export_mission_logger(m, v["mission"].as<std::string>(), output, o);
    outputs.commit();
    std::printf("wrote %s/: log.csv (%zu rows), map.yaml, gps.nmea (%zu fixes), marks.csv (%zu), marks_map.yaml, model.yaml%s%s, "
                "import-command.txt\n",
                output.c_str(), m.size(), m.gps_time.size(), m.mark_count(), m.has_truth() ? ", truth.csv" : "",
                m.truth_mines.empty() ? "" : ", truth_mines.csv");
    return kExitOk;
  }
  io::export_gesmi_txt(m, v["mission"].as<std::string>(), output);
  outputs.commit();
  std::printf("wrote %s: %zu rows, %zu position fixes (marks are not part of the GESMI text format)\n", output.c_str(),
              m.size(), m.gps_time.size());
  return kExitOk;
}

const bool registered = register_command({"export", "write a mission as CSV files (or a GESMI text log)", run_export});

}  // namespace
}  // namespace gesmi::cli
