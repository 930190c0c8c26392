// gesmi export: a mission back to the CSV files of gesmi import (docs/formats.md),
// or to a GESMI text log.

#include <cstdio>

#include "io/output/atomic_output.h"
#include "io/exports/export_csv.h"
#include "io/exports/export_gesmi_txt.h"
#include "io/text/message_text.h"
#include "io/files/mission_file.h"
#include "io/output/output_set.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/input_files.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

int run_export(std::span<const std::string> args) {
  po::options_description options("export options");
  options.add_options()
      ("mission", po::value<std::string>()->required(), "mission file (HDF5)")
      ("format", po::value<std::string>()->default_value("csv"), "csv (a folder of CSV files) or gesmi-txt (one file)")
      ("output,o", po::value<std::string>()->required(), "folder to create (csv) or file to write (gesmi-txt)");
  po::positional_options_description positional;
  positional.add("mission", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi export MISSION.h5 -o DIR [--format csv|gesmi-txt]"))
    return kExitOk;
  const std::string format = v["format"].as<std::string>(), output = v["output"].as<std::string>();
  if (format != "csv" && format != "gesmi-txt") throw UsageError("--format: expected csv or gesmi-txt, got " + io::quoted_input(format));
  io::OutputSet outputs(input_files(v, {"mission"}));
  if (format == "csv")
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
  io::export_gesmi_txt(m, v["mission"].as<std::string>(), output);
  outputs.commit();
  std::printf("wrote %s: %zu rows, %zu position fixes (marks are not part of the GESMI text format)\n", output.c_str(),
              m.size(), m.gps_time.size());
  return kExitOk;
}

const bool registered = register_command({"export", "write a mission as CSV files (or a GESMI text log)", run_export});

}  // namespace
}  // namespace gesmi::cli
