// gesmi solve: the interval solver on a mission (cold, warm from an earlier result,
// or tolerating outliers), writing the result file, the mine boxes as CSV, GeoJSON
// and the envelope picture.

#include <bit>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "io/output_set.h"
#include "io/atomic_output.h"
#include "io/io_version.h"
#include "io/mission_digest.h"
#include "io/mission_file.h"
#include "io/plot/plot_envelope.h"
#include "io/result_exports.h"
#include "io/result_file.h"
#include "io/sensor_model_yaml.h"
#include "solver/network/incremental_solver.h"
#include "solver/network/outlier_solver.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/json_writer.h"
#include "tools/gesmi/progress.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    "gesmi solve MISSION.h5 -o RESULT.h5 [--config bounds.yaml] [--max-sweeps N] [--tolerance T] [--stats] "
    "[--from RESULT.h5] [--max-outliers Q | --minimal-outliers Q] [--trust-gps] [--mines K]";

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

// Files written beside RESULT.h5: RESULT.mines.csv, RESULT.geojson, RESULT.envelope.png.
std::string sibling(const std::string& result, const std::string& suffix) {
  std::filesystem::path p(result);
  if (p.extension() == ".h5") p.replace_extension();
  return p.string() + suffix;
}

struct Run {
  Mission mission;
  MissionNetwork network;
  TubeDomains domains;
  SolverReport report;
  std::vector<std::int32_t> outlier;      // per mark row
  std::vector<std::int32_t> gps_outlier;  // per GPS fix
  std::int64_t minimal_outliers = 0;
  std::string mode = "cold";
  std::size_t work_items = 0;
};

// Checks that `previous` was computed on this mission with only marks added, and
// returns its candidates by mark row. Throws UsageError naming what changed.
std::vector<std::uint64_t> check_warm_start(const io::SolveResult& previous, const Mission& mission,
                                            const std::string& from) {
  if (previous.format_version < 2)
    throw UsageError("--from " + from + ": written by an earlier gesmi, without the digests a warm start checks; run a cold solve");
  if (previous.navigation_digest != io::navigation_digest(mission))
    throw UsageError("--from " + from + ": the navigation data (DVL, attitude, depth, altitude, GPS) differ from the "
                     "mission it was computed on; run a cold solve");
  if (previous.bounds_digest != io::bounds_digest(mission.model))
    throw UsageError("--from " + from + ": the sensor bounds differ from those it was computed with; run a cold solve");
  const auto old_marks = static_cast<std::size_t>(previous.mark_count);
  if (old_marks > mission.mark_count() || previous.marks_digest != io::marks_digest(mission, old_marks))
    throw UsageError("--from " + from + ": the mark table changed other than by added rows; run a cold solve");
  if (previous.time.size() != mission.size() || previous.mine_count != mission.mine_count)
    throw UsageError("--from " + from + ": it was computed on another mission");
  if (!previous.consistent) throw UsageError("--from " + from + ": that result is inconsistent; run a cold solve");
  return previous.candidates;
}

// Returns false (and leaves the domains for a cold solve) when the added marks
// change the symmetry breaking among unlabelled mines.
bool prepare_warm(Run& run, const io::SolveResult& previous, const std::string& from,
                  std::vector<std::size_t>& added) {
  const std::vector<std::uint64_t> by_mark = check_warm_start(previous, run.mission, from);
  // Symmetry breaking among unlabelled mines depends on the labelled ones: if the
  // added marks change it, the earlier domains assumed other labels: solve cold.
  Mission before = run.mission;
  for (auto* v : {&before.mark_time, &before.mark_range}) v->resize(by_mark.size());
  for (auto* v : {&before.mark_mine, &before.mark_side}) v->resize(by_mark.size());
  const MissionNetwork old_net = build_network(before, before.model, gps_fixes(before));
  for (const Detection& old_det : old_net.detections)
    for (const Detection& det : run.network.detections)
      if (det.mark == old_det.mark && det.allowed != old_det.allowed) {
        std::fprintf(stderr, "gesmi solve: the added marks name a mine no mark named before; solving cold\n");
        run.domains = initial_domains(run.mission, run.mission.model, run.network);
        return false;
      }
  run.domains = previous.domains;
  add_network_priors(run.domains, run.network);  // mines and candidates reset...
  run.domains.mines = previous.domains.mines;    // ...then the earlier mine boxes restored
  added = carry_candidates(run.network, run.domains, by_mark);
  return true;
}

void solve_with_outlier_search(Run& run, const OutlierOptions& outliers, const SolverOptions& options) {
  const TubeDomains sensor = sensor_domains(run.mission, run.mission.model);
  OutlierOptions o = outliers;
  o.solver = options;
  const OutlierReport r = solve_with_outliers(run.network, sensor, run.domains, o);
  run.report = r.consistent() ? SolverReport{} : r.first_solve;
  if (r.consistent()) {
    run.report.converged = true;
    run.report.sweeps = r.full_solves;
  } else if (run.report.inconsistency) {
    run.report.inconsistency->message = "more than " + std::to_string(o.max_outliers) + " of the " +
                                        (o.trust_fixes ? "marks" : "marks and GPS fixes") +
                                        " are wrong (removing any " + std::to_string(o.max_outliers) +
                                        " of them leaves the data inconsistent); with all the data: " +
                                        run.report.inconsistency->message;
  }
  run.minimal_outliers = r.minimal_outliers;
  run.mode = o.mode == OutlierMode::relaxed ? "outliers" : "minimal-outliers";
  for (std::size_t j = 0; j < run.network.detections.size(); ++j)
    run.outlier[run.network.detections[j].mark] = r.detection_outlier[j];
  for (std::size_t a = 0; a < run.network.anchors.size(); ++a)
    run.gps_outlier[run.network.anchors[a].fix.source_index] = r.fix_outlier[a];
  if (r.consistent() && r.minimal_outliers > 0) {
    std::fprintf(stderr, "gesmi solve: consistent with %d outlier(s); %zu hypothesis(es) restore consistency:\n",
                 r.minimal_outliers, r.hypotheses.size());
    for (const auto& h : r.hypotheses) {
      std::string names;
      for (const std::size_t id : h)
        names += (names.empty() ? "" : ", ") +
                 (id < run.network.detections.size() ? "mark " + std::to_string(run.network.detections[id].mark)
                                                     : "GPS fix " + std::to_string(run.network.anchors[id - run.network.detections.size()].fix.source_index));
      std::fprintf(stderr, "  without %s\n", names.c_str());
    }
  }
}

// On an inconsistency: the single measurements whose removal restores consistency
// (an outlier search with q = 1), appended to the message so that the operator
// knows which mark or fix to check.
std::string diagnose(const Run& run, const SolverOptions& options) {
  OutlierOptions o;
  o.max_outliers = 1;
  o.mode = OutlierMode::minimal;  // only the hypotheses are wanted
  o.solver = options;
  o.solver.on_sweep = nullptr;
  TubeDomains scratch;
  const OutlierReport r = solve_with_outliers(run.network, sensor_domains(run.mission, run.mission.model), scratch, o);
  if (r.minimal_outliers != 1) return "; no single mark or fix explains it (try --max-outliers 2)";
  std::string names;
  for (const auto& h : r.hypotheses) {
    const std::size_t id = h[0];
    names += (names.empty() ? "" : " or ") +
             (id < run.network.detections.size()
                  ? "mark " + std::to_string(run.network.detections[id].mark)
                  : "GPS fix " + std::to_string(run.network.anchors[id - run.network.detections.size()].fix.source_index));
  }
  return "; removing " + names + " restores consistency";
}

// For each mark without a mine number, the mines still possible.
void print_candidates(const MissionNetwork& network, const std::vector<std::uint64_t>& candidates_by_mark) {
  for (const Detection& det : network.detections) {
    if (det.mine >= 0) continue;
    const std::uint64_t candidates = candidates_by_mark[det.mark];
    std::string mines;
    for (int i = 0; i < network.mine_count; ++i)
      if (candidates >> i & 1) mines += (mines.empty() ? "" : ", ") + std::to_string(i);
    const int count = std::popcount(candidates);
    std::printf("mark %zu at t = %.1f s: %s %s\n", det.mark, det.time,
                count == 1 ? "mine" : (count == 0 ? "no mine" : "mines"), mines.c_str());
  }
}

int run_solve(std::span<const std::string> args) {
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
  po::positional_options_description positional;
  positional.add("mission", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, kUsage)) return kExitOk;
  SolverOptions solver_options;
  const long long sweeps = parse_integer("--max-sweeps", v["max-sweeps"].as<std::string>());
  if (sweeps < 1 || sweeps > 1000000) throw UsageError("--max-sweeps: must be between 1 and 1000000");
  solver_options.max_sweeps = static_cast<int>(sweeps);
  solver_options.tolerance = parse_non_negative("--tolerance", v["tolerance"].as<std::string>());
  if (!std::isfinite(solver_options.tolerance)) throw UsageError("--tolerance: must be finite");
  int max_outliers = -1;
  OutlierOptions outlier_options;
  for (const char* name : {"max-outliers", "minimal-outliers"}) {
    if (!v.count(name)) continue;
    if (max_outliers >= 0) throw UsageError("--max-outliers and --minimal-outliers cannot be combined");
    const long long q = parse_integer(std::string("--") + name, v[name].as<std::string>());
    if (q < 0 || q > 8) throw UsageError(std::string("--") + name + ": must be between 0 and 8");
    max_outliers = static_cast<int>(q);
    outlier_options.mode = std::string(name) == "max-outliers" ? OutlierMode::relaxed : OutlierMode::minimal;
  }
  outlier_options.max_outliers = max_outliers;
  outlier_options.trust_fixes = v.count("trust-gps") > 0;
  if (outlier_options.trust_fixes && max_outliers < 0) throw UsageError("--trust-gps goes with --max-outliers or --minimal-outliers");
  if (v.count("from") && max_outliers >= 0) throw UsageError("--from and --max-outliers cannot be combined");
  const bool stats = v.count("stats") > 0;
  const std::string output = v["output"].as<std::string>();
  io::OutputSet outputs(input_files(v, {"mission", "config", "from"}));
  outputs.check(output);
  for (const char* suffix : {".mines.csv", ".geojson", ".envelope.png"}) {
    outputs.check(sibling(output, suffix));
    outputs.owns(sibling(output, suffix));
  }

  std::map<std::string, double> timings;
  auto start = Clock::now();
  Run run;
  run.mission = io::read_mission(v["mission"].as<std::string>());
  if (v.count("config")) io::merge_sensor_model_yaml(v["config"].as<std::string>(), run.mission.model);
  if (v.count("mines")) {
    const long long k = parse_integer("--mines", v["mines"].as<std::string>());
    int largest = -1;
    for (const std::int32_t i : run.mission.mark_mine) largest = std::max(largest, static_cast<int>(i));
    if (k <= largest) throw UsageError("--mines: " + std::to_string(k) + " is not more than the largest mine number in the mark table (" + std::to_string(largest) + ")");
    if (k > kMaxMines) throw UsageError("--mines: at most 64 mines");
    run.mission.mine_count = static_cast<int>(k);
  }
  timings["load"] = elapsed_ms(start);

  start = Clock::now();
  run.network = build_network(run.mission, run.mission.model, gps_fixes(run.mission));
  run.outlier.assign(run.mission.mark_count(), 0);
  run.gps_outlier.assign(run.mission.gps_time.size(), 0);
  timings["build"] = elapsed_ms(start);

  start = Clock::now();
  Progress progress("solving");
  solver_options.on_sweep = [&](int sweep, double move) {
    progress.update(static_cast<double>(sweep) / solver_options.max_sweeps,
                    "sweep " + std::to_string(sweep) + ", largest move " + std::to_string(move) + " m");
  };
  if (v.count("from")) {
    const std::string from = v["from"].as<std::string>();
    const auto load_start = Clock::now();
    const io::SolveResult previous = io::read_result(from, false);
    std::vector<std::size_t> added;
    const bool warm = prepare_warm(run, previous, from, added);
    timings["load"] += elapsed_ms(load_start);
    start = Clock::now();
    if (warm) {
      const IncrementalReport r = propagate_from(run.network, run.domains, added, solver_options);
      run.report = r.solver;
      run.work_items = r.work_items;
      run.mode = "warm";
    } else {
      run.report = solve(run.network, run.domains, solver_options);
    }
  } else if (max_outliers >= 0) {
    solve_with_outlier_search(run, outlier_options, solver_options);
  } else {
    run.domains = sensor_domains(run.mission, run.mission.model);
    add_network_priors(run.domains, run.network);
    timings["build"] += elapsed_ms(start);
    start = Clock::now();
    run.report = solve(run.network, run.domains, solver_options);
  }
  progress.finish();
  timings["propagate"] = elapsed_ms(start);

  start = Clock::now();
  io::SolveResult result;
  result.time = run.mission.time;
  result.waterfall = compute_waterfall(run.mission, run.mission.model, run.domains);
  timings["waterfall"] = elapsed_ms(start);
  start = Clock::now();
  result.domains = std::move(run.domains);
  result.mine_count = run.mission.mine_count;
  result.candidates.assign(run.mission.mark_count(), 0);
  for (std::size_t j = 0; j < run.network.detections.size(); ++j)
    result.candidates[run.network.detections[j].mark] = result.domains.candidates[j];
  result.outlier = run.outlier;
  result.mark_time = run.mission.mark_time;
  result.mark_range = run.mission.mark_range;
  result.mark_mine = run.mission.mark_mine;
  result.gps_outlier = run.gps_outlier;
  result.consistent = run.report.consistent();
  result.message = result.consistent ? "" : run.report.inconsistency->message;
  if (!result.consistent && run.mode == "cold") result.message += diagnose(run, solver_options);
  result.sweeps = run.report.sweeps;
  result.converged = run.report.converged;
  result.minimal_outliers = max_outliers >= 0 ? run.minimal_outliers : 0;
  result.navigation_digest = io::navigation_digest(run.mission);
  result.bounds_digest = io::bounds_digest(run.mission.model);
  result.marks_digest = io::marks_digest(run.mission, run.mission.mark_count());
  result.mark_count = static_cast<std::int64_t>(run.mission.mark_count());
  result.version = std::string(io::version());
  result.timings_ms = timings;
  io::write_result(result, output);
  io::write_mines_csv(result.domains, sibling(output, ".mines.csv"));
  io::write_geojson(result.domains, run.mission.origin, sibling(output, ".geojson"));
  io::EnvelopePicture picture;
  picture.domains = &result.domains;
  picture.mission = &run.mission;
  for (const Anchor& a : run.network.anchors) picture.fix_boxes.push_back(a.fix.box);
  picture.title = "gesmi envelope: " + std::filesystem::path(v["mission"].as<std::string>()).filename().string() +
                  (result.consistent ? "" : " (INCONSISTENT)");
  io::write_envelope_png(picture, sibling(output, ".envelope.png"));
  outputs.commit();
  timings["write"] = elapsed_ms(start);

  if (stats) {
    std::string json = "{\"status\": " + json_string(result.consistent ? "consistent" : "inconsistent") +
                       ", \"mode\": " + json_string(run.mode) + ", \"sweeps\": " + std::to_string(result.sweeps) +
                       ", \"converged\": " + (result.converged ? "true" : "false") +
                       ", \"steps\": " + std::to_string(run.mission.size()) +
                       ", \"marks\": " + std::to_string(run.mission.mark_count()) +
                       ", \"max_tube_width_m\": " + json_number(result.domains.max_horizontal_width()) +
                       ", \"work_items\": " + std::to_string(run.work_items) + ", \"timings_ms\": {";
    bool first = true;
    for (const auto& [name, ms] : timings) {
      json += (first ? "" : ", ") + json_string(name) + ": " + json_number(ms);
      first = false;
    }
    std::printf("%s}}\n", json.c_str());
  } else {
    print_candidates(run.network, result.candidates);
    std::printf("%s: %s after %lld sweeps, largest horizontal tube width %.1f m, written to %s\n",
                run.mode.c_str(), result.consistent ? "consistent" : "INCONSISTENT",
                static_cast<long long>(result.sweeps), result.domains.max_horizontal_width(), output.c_str());
  }
  if (!result.consistent) {
    std::fprintf(stderr, "gesmi solve: inconsistent data: %s\n", result.message.c_str());
    return kExitInconsistent;
  }
  return kExitOk;
}

const bool registered = register_command({"solve", "interval solve of a mission: tube, mine boxes, waterfall", run_solve});

}  // namespace
}  // namespace gesmi::cli
