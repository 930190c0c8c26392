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

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

int run_command(const std::string& name, const std::vector<std::string>& args) {
  for (const Command& c : commands())
    if (c.name == name) {
      std::string line = "$ gesmi " + name;
      for (const std::string& a : args) line += " " + a;
      std::printf("%s\n", line.c_str());
      return c.run(args);
    }
  throw std::logic_error("missing command " + name);
}

int run_demo(std::span<const std::string> args) {
  po::options_description options("demo options");
  options.add_options()("output,o", po::value<std::string>()->default_value("gesmi-demo"), "folder for the demo files")(
      "seed", po::value<std::string>()->default_value("1"), "simulation seed");
  po::variables_map v;
  if (!parse_options(args, options, {}, v, "gesmi demo [-o DIR] [--seed S]")) return kExitOk;
  const std::string dir = v["output"].as<std::string>();
  const long long seed = parse_integer("--seed", v["seed"].as<std::string>());
  if (seed < 0) throw UsageError("--seed: must be >= 0");
  // One set over the whole demo: a step that fails removes what the earlier ones wrote.
  io::OutputSet outputs;
  outputs.prepare_folder(dir);
  const std::string mission = dir + "/mission.h5", result = dir + "/result.h5";

  const auto start = std::chrono::steady_clock::now();
  if (const int code = run_command("simulate", {"--preset", "redermor", "--seed", std::to_string(seed), "-o", mission}))
    return code;
  const int solved = run_command("solve", {mission, "-o", result, "--png", "--geojson", "--mines-csv"});
  if (solved != kExitOk && solved != kExitInconsistent) return solved;
  if (const int code = run_command("waterfall", {result, "-o", dir + "/waterfall.png", "--show-inconsistent"})) return code;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const io::SolveResult file = io::read_result(result, {.tube = true, .waterfall = false});
  const MissionSolution& r = file.solution;
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
  std::printf("files in %s/: mission.h5 result.h5 result.envelope.png waterfall.png result.mines.csv result.geojson\n",
              dir.c_str());
  return solved;
}

const bool registered = register_command({"demo", "simulate, solve and draw the reference-like mission", run_demo});

}  // namespace
}  // namespace gesmi::cli
