// gesmi solve: the interval solver on a mission (cold, warm from an earlier result,
// or tolerating outliers), writing the result file and, when asked, the mine boxes as
// CSV, GeoJSON and the envelope picture. The solve itself is solve_mission (solver/solve/).

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "io/files/mission_digest.h"
#include "io/files/mission_file.h"
#include "io/format_error.h"
#include "io/output/output_set.h"
#include "io/exports/solve_outputs.h"
#include "io/exports/result_exports.h"
#include "io/files/warm_start_file.h"
#include "solver/solve/solve_mission.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "io/report/report_json.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/progress.h"
#include "tools/gesmi/skip_existing.h"
#include "tools/gesmi/solve_arguments.h"
#include "tools/gesmi/solve_report.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;
using Clock = std::chrono::steady_clock;

int run_solve(std::span<const std::string> args) {
  po::variables_map v;
  if (!parse_options(args, solve_options(), po::positional_options_description().add("mission", 1), v, kSolveUsage))
    return kExitOk;
  SolveOptions options = parse_solve_options(v);
  const std::string output = v["output"].as<std::string>(), mission_path = v["mission"].as<std::string>();
  const io::SolveSiblings siblings = parse_solve_siblings(v);
  const auto file_options = {"mission", "config", "from"};  // the options naming files read
  io::OutputSet outputs(input_files(v, file_options));
  outputs.check(output);
  for (const std::string& sibling : io::solve_output_siblings(output)) {
    outputs.check(sibling);
    outputs.owns(sibling);
  }
  if (skipped_as_existing(v, "solve", io::asked_solve_outputs(output, siblings))) return kExitOk;

  std::map<std::string, double> timings;
  // One progress line over the whole command, on a terminal only (progress.h).
  Progress progress("gesmi solve:");
  progress.update(-1.0, "reading " + mission_path);
  auto start = Clock::now();
  // The solve never looks at the truth; only the envelope picture draws it.
  Mission mission = io::read_mission(mission_path, siblings.envelope_png ? io::TruthReading::read : io::TruthReading::skip);
  apply_config(v, mission, "solve");
  apply_mine_count(v, mission);
  // Before the solve, not after it: a GeoJSON needs latitudes/longitudes the origin allows.
  if (siblings.geojson)
    if (const std::string why = io::geodetic_problem(mission.origin); !why.empty())
      throw UsageError("--geojson: " + mission_path + ": " + why);
  // Hashed once: the warm start compares it, the result stores it.
  const std::string navigation = io::navigation_digest(mission, io::kResultDigest);
  std::optional<MissionSolution> previous;
  if (v.count("from")) {
    progress.update(-1.0, "reading " + v["from"].as<std::string>());
    previous = io::read_warm_start(v["from"].as<std::string>(), mission, navigation);
  }
  timings["load"] = elapsed_ms(start);

  options.propagation.on_sweep = [&](int sweep, double move) {
    progress.update(static_cast<double>(sweep) / options.propagation.max_sweeps,
                    "sweep " + std::to_string(sweep) + ", largest move " + std::to_string(move) + " m");
  };
  options.on_stage = [&](const char* stage, double fraction) { progress.update(fraction, stage); };
  io::SolveResult result;
  // A warm rerun gives the earlier result up: its increments move into the new one.
  result.solution = previous ? solve_mission(mission, options, std::move(*previous)) : solve_mission(mission, options);
  // The earlier result is done with (its tube and waterfall went into the solve): not
  // held in memory while the new one is written (the peak of a warm rerun).
  previous.reset();
  progress.update(-1.0, "writing " + output);
  const MissionSolution& s = result.solution;
  timings.insert(s.timings_ms.begin(), s.timings_ms.end());

  start = Clock::now();
  io::record_inputs(result, mission, navigation);
  result.solution.timings_ms = timings;
  const std::vector<std::string> written = io::write_solve_outputs(
      result, mission, output, std::filesystem::path(mission_path).filename().string(), siblings);
  outputs.commit();
  timings["write"] = elapsed_ms(start);
  progress.finish();

  print_solve_notes(s);
  CommandReport report("solve", v);
  if (report.enabled()) {
    report.inputs(v, file_options);
    report.outputs(written);
    report.timings(timings);
    report["solve"] = io::solve_json(mission, s);
  } else {
    print_solve_summary(mission, s, written);
  }
  if (!s.report.consistent) std::fprintf(stderr, "gesmi solve: inconsistent data: %s\n", s.report.message.c_str());
  return report.finish(s.report.consistent ? kExitOk : kExitInconsistent);
}

const bool solve_registered =
    register_command({"solve", "interval solve of a mission: tube, mine boxes, waterfall", run_solve});

}  // namespace
}  // namespace gesmi::cli
