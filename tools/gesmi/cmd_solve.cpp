// gesmi solve: the interval solver on a mission (cold, warm from an earlier result,
// or tolerating outliers), writing the result file, the mine boxes as CSV, GeoJSON
// and the envelope picture. The solve itself is solve_mission (solver/solve/).

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "io/io_version.h"
#include "io/mission_digest.h"
#include "io/mission_file.h"
#include "io/output_set.h"
#include "io/sensor_model_yaml.h"
#include "io/solve_outputs.h"
#include "io/warm_start_file.h"
#include "solver/solve/solve_mission.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/progress.h"
#include "tools/gesmi/solve_report.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    "gesmi solve MISSION.h5 -o RESULT.h5 [--config bounds.yaml] [--max-sweeps N] [--tolerance T] [--stats] "
    "[--from RESULT.h5] [--max-outliers Q | --minimal-outliers Q] [--trust-gps] [--mines K]";

double elapsed_ms(Clock::time_point since) { return std::chrono::duration<double, std::milli>(Clock::now() - since).count(); }

po::options_description solve_options() {
  po::options_description options("solve options");
  options.add_options()
      ("mission", po::value<std::string>()->required(), "mission file (HDF5)")
      ("output,o", po::value<std::string>()->required(), "result file to write (HDF5)")
      ("config", po::value<std::string>(), "sensor bounds (YAML) overriding the mission's")
      ("max-sweeps", po::value<std::string>()->default_value("100"), "sweep limit")
      ("tolerance", po::value<std::string>()->default_value("0.001"), "stop when no bound moves more (m)")
      ("stats", "print one JSON object with timings and sweeps on stdout")
      ("from", po::value<std::string>(), "warm start from an earlier result of this mission")
      ("max-outliers", po::value<std::string>(),
       "tolerate up to Q wrong marks or GPS fixes: the result holds every trajectory consistent with all the data "
       "but at most Q of them (guaranteed whenever at most Q are wrong)")
      ("minimal-outliers", po::value<std::string>(),
       "CONDITIONAL: the hull over the smallest sets (q* <= Q) of marks or fixes whose removal restores "
       "consistency; it contains the truth only if exactly q* inputs are wrong")
      ("trust-gps", "GPS fixes are never outliers: only marks are tolerated as wrong")
      ("mines", po::value<std::string>(), "number of mines K (default: the mission's)");
  return options;
}

SolveOptions parse_solve_options(const po::variables_map& v) {
  SolveOptions o;
  const long long sweeps = parse_integer("--max-sweeps", v["max-sweeps"].as<std::string>());
  if (sweeps < 1 || sweeps > 1000000) throw UsageError("--max-sweeps: must be between 1 and 1000000");
  o.propagation.max_sweeps = static_cast<int>(sweeps);
  o.propagation.tolerance = parse_non_negative("--tolerance", v["tolerance"].as<std::string>());
  if (!std::isfinite(o.propagation.tolerance)) throw UsageError("--tolerance: must be finite");
  for (const std::string name : {"max-outliers", "minimal-outliers"}) {
    if (!v.count(name)) continue;
    if (o.max_outliers >= 0) throw UsageError("--max-outliers and --minimal-outliers cannot be combined");
    const long long q = parse_integer("--" + name, v[name].as<std::string>());
    if (q < 0 || q > 8) throw UsageError("--" + name + ": must be between 0 and 8");
    o.max_outliers = static_cast<int>(q);
    o.outlier_mode = name == "max-outliers" ? OutlierMode::relaxed : OutlierMode::minimal;
  }
  o.trust_gps = v.count("trust-gps") > 0;
  if (o.trust_gps && o.max_outliers < 0) throw UsageError("--trust-gps goes with --max-outliers or --minimal-outliers");
  if (v.count("from") && o.max_outliers >= 0) throw UsageError("--from and --max-outliers cannot be combined");
  return o;
}

void apply_mine_count(const po::variables_map& v, Mission& mission) {
  if (!v.count("mines")) return;
  const long long k = parse_integer("--mines", v["mines"].as<std::string>());
  int largest = -1;
  for (const std::int32_t i : mission.mark_mine) largest = std::max(largest, static_cast<int>(i));
  if (k <= largest)
    throw UsageError("--mines: " + std::to_string(k) + " is not more than the largest mine number in the mark table (" +
                     std::to_string(largest) + ")");
  if (k > kMaxMines) throw UsageError("--mines: at most 64 mines");
  mission.mine_count = static_cast<int>(k);
}

int run_solve(std::span<const std::string> args) {
  po::variables_map v;
  if (!parse_options(args, solve_options(), po::positional_options_description().add("mission", 1), v, kUsage)) return kExitOk;
  SolveOptions options = parse_solve_options(v);
  const std::string output = v["output"].as<std::string>(), mission_path = v["mission"].as<std::string>();
  io::OutputSet outputs(input_files(v, {"mission", "config", "from"}));
  outputs.check(output);
  for (const std::string& sibling : io::solve_output_siblings(output)) {
    outputs.check(sibling);
    outputs.owns(sibling);
  }

  std::map<std::string, double> timings;
  auto start = Clock::now();
  Mission mission = io::read_mission(mission_path);
  if (v.count("config")) io::merge_sensor_model_yaml(v["config"].as<std::string>(), mission.model);
  apply_mine_count(v, mission);
  MissionSolution previous;
  if (v.count("from")) {
    previous = io::read_warm_start(v["from"].as<std::string>(), mission);
    options.warm_from = &previous;
  }
  timings["load"] = elapsed_ms(start);

  Progress progress("solving");
  options.propagation.on_sweep = [&](int sweep, double move) {
    progress.update(static_cast<double>(sweep) / options.propagation.max_sweeps,
                    "sweep " + std::to_string(sweep) + ", largest move " + std::to_string(move) + " m");
  };
  io::SolveResult result;
  result.solution = solve_mission(mission, options);
  progress.finish();
  const MissionSolution& s = result.solution;
  timings.insert(s.timings_ms.begin(), s.timings_ms.end());

  start = Clock::now();
  result.navigation_digest = io::navigation_digest(mission);
  result.bounds_digest = io::bounds_digest(mission.model);
  result.marks_digest = io::marks_digest(mission, mission.mark_count());
  result.version = std::string(io::version());
  result.solution.timings_ms = timings;
  io::write_solve_outputs(result, mission, output, std::filesystem::path(mission_path).filename().string());
  outputs.commit();
  timings["write"] = elapsed_ms(start);

  print_solve_notes(s);
  if (v.count("stats"))
    print_solve_stats(mission, s, timings);
  else
    print_solve_summary(mission, s, output);
  if (s.report.consistent) return kExitOk;
  std::fprintf(stderr, "gesmi solve: inconsistent data: %s\n", s.report.message.c_str());
  return kExitInconsistent;
}

const bool registered = register_command({"solve", "interval solve of a mission: tube, mine boxes, waterfall", run_solve});

}  // namespace
}  // namespace gesmi::cli
