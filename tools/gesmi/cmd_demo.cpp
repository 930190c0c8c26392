// gesmi demo: the README's main job. Simulates the reference-like mission, solves it,
// draws the envelope and the reconstructed waterfall, and prints a short summary.
// It chains the simulate, solve and waterfall commands, so it shows exactly what a
// user would run.

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "io/output/output_set.h"
#include "io/files/result_file.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

// Runs a step, shown as the command a user would type (not with --json: stdout then
// holds the reports only).
int run_command(const std::string& name, const std::vector<std::string>& args) {
  for (const Command& c : commands())
    if (c.name == name) {
      std::string line = "$ gesmi " + name;
      for (const std::string& a : args) line += " " + a;
      if (args.empty() || args.back() != "--json") std::printf("%s\n", line.c_str());
      return c.run(args);
    }
  throw std::logic_error("missing command " + name);
}

constexpr const char* kDemoFiles[] = {"mission.h5",  "result.h5",        "result.envelope.png",
                                     "waterfall.png", "result.mines.csv", "result.geojson"};

int run_demo(std::span<const std::string> args) {
  po::options_description options("demo options");
  options.add_options()("output,o", po::value<std::string>()->default_value("gesmi-demo"), "folder for the demo files")(
      "seed", po::value<std::string>()->default_value("1"), "simulation seed");
  options.add_options()("json", "print each step's JSON report, then the demo's own, one per line (docs/reports.md)");
  add_skip_existing(options);
  po::variables_map v;
  if (!parse_options(args, options, {}, v, "gesmi demo [-o DIR] [--seed S] [--json] [--skip-existing]")) return kExitOk;
  const std::string dir = v["output"].as<std::string>();
  const long long seed = parse_integer("--seed", v["seed"].as<std::string>());
  if (seed < 0) throw UsageError("--seed: must be >= 0");
  std::vector<std::string> files;
  for (const char* name : kDemoFiles) files.push_back((std::filesystem::path(dir) / name).string());
  io::OutputSet::check_folder(dir);
  if (skipped_as_existing(v, "demo", files)) return kExitOk;
  // One set over the whole demo: a step that fails removes what the earlier ones wrote.
  io::OutputSet outputs;
  outputs.prepare_folder(dir, /*in_place=*/true);  // the result names its mission by path
  const std::string mission = dir + "/mission.h5", result = dir + "/result.h5";

  const auto start = std::chrono::steady_clock::now();
  CommandReport report("demo", v);
  // Each step's arguments, with --json when asked: every step then prints its report.
  const auto step = [&](std::vector<std::string> arguments) {
    if (report.enabled()) arguments.push_back("--json");
    return arguments;
  };
  if (const int code = run_command("simulate", step({"--preset", "redermor", "--seed", std::to_string(seed), "-o", mission})))
    return code;
  const int solved = run_command("solve", step({mission, "-o", result, "--png", "--geojson", "--mines-csv"}));
  if (solved != kExitOk && solved != kExitInconsistent) return solved;
  if (const int code = run_command("waterfall", step({result, "-o", dir + "/waterfall.png", "--show-inconsistent"})))
    return code;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const io::SolveResult file = io::read_result(result, {.tube = true, .waterfall = false});
  const MissionSolution& r = file.solution;
  if (report.enabled()) {
    outputs.commit();
    report.outputs(files);
    report.timings({{"demo", seconds * 1000.0}});
    report["status"] = r.report.consistent ? "consistent" : "inconsistent";
    return report.finish(solved);
  }
  std::printf("\nsummary: %s, %lld sweeps, propagation %.1f ms, whole demo %.1f s\n",
              r.report.consistent ? "consistent" : "INCONSISTENT", static_cast<long long>(r.report.sweeps),
              r.timings_ms.count("propagate") ? r.timings_ms.at("propagate") : 0.0, seconds);
  std::printf("largest horizontal tube width: %.1f m\n", r.domains.max_horizontal_width());
  for (std::size_t i = 0; i < r.domains.mines.size(); ++i) {
    const Vec3I& m = r.domains.mines[i];
    std::printf("mine %zu box: %.1f m (north) x %.1f m (east) x %.1f m (down)\n", i, m[0].width(), m[1].width(),
                m[2].width());
  }
  outputs.commit();
  std::string names;
  for (const char* name : kDemoFiles) names += std::string(" ") + name;
  std::printf("files in %s/:%s\n", dir.c_str(), names.c_str());
  return solved;
}

const bool demo_registered =
    register_command({"demo", "simulate, solve and draw the reference-like mission", run_demo});

}  // namespace
}  // namespace gesmi::cli
