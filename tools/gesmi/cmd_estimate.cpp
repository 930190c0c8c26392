// gesmi estimate: parameter estimation with outliers (seed 004, Example 2). Thin:
// read the scenario (io), characterise j^{-1}(q) for each q asked for (solver),
// write the outputs (io), print the summary.

#include <cstdio>
#include <string>
#include <vector>

#include "io/localization/estimation_output.h"
#include "io/localization/estimation_scenario.h"
#include "io/output/output_set.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/progress.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

constexpr const char* kEstimateUsage = "gesmi estimate SCENARIO.yaml -o OUT_DIR [--quiet] [--skip-existing]";

int run_estimate(std::span<const std::string> args) {
  po::options_description options("estimate options");
  options.add_options()
      ("scenario", po::value<std::string>(), "estimation scenario file (YAML)")
      ("output,o", po::value<std::string>(), "output folder (created if missing)")
      ("quiet,q", "print neither the summary nor the progress line");
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("scenario", 1);
  po::variables_map values;
  if (!parse_options(args, options, positional, values, kEstimateUsage)) return kExitOk;
  if (!values.count("scenario")) throw UsageError(std::string("missing SCENARIO.yaml; usage: ") + kEstimateUsage);
  if (!values.count("output")) throw UsageError(std::string("missing -o OUT_DIR; usage: ") + kEstimateUsage);
  const EstimationProblem problem = io::read_estimation_scenario(values["scenario"].as<std::string>());
  const std::string folder = values["output"].as<std::string>();
  io::OutputSet outputs(input_files(values, {"scenario"}));
  io::OutputSet::check_folder(folder);
  if (skipped_as_existing(values, "estimate", io::estimation_output_files(folder))) return kExitOk;
  Progress progress("gesmi estimate:", values.count("quiet") > 0);  // on a terminal, for long runs only (progress.h)
  const EstimationResult result = estimate(problem, [&](const EstimationProgress& p) {
    progress.update(static_cast<double>(p.level) / static_cast<double>(p.level_count),
                    "q = " + std::to_string(p.q) + " (level " + std::to_string(p.level + 1) + " of " +
                        std::to_string(p.level_count) + "): " + std::to_string(p.boxes_examined) + " boxes examined");
  });
  progress.update(1.0, "writing " + folder);
  outputs.prepare_folder(folder);
  const std::vector<std::string> written = io::write_estimation_outputs(folder, problem, result);
  outputs.commit();
  progress.finish();
  CommandReport report("estimate", values);
  if (report.enabled()) {
    report.inputs(values, {"scenario"});
    report.outputs(written);
    report.timings({{"estimate", result.seconds * 1000.0}});
    report["estimation"] = io::estimation_summary_json(problem, result);
    return report.finish(kExitOk);
  }
  if (!values.count("quiet")) std::fputs(io::estimation_summary(problem, result).c_str(), stdout);
  return kExitOk;
}

const bool estimate_registered = register_command(
    {"estimate", "parameter estimation with outliers by set inversion (seed 004, Example 2)", run_estimate});

}  // namespace
}  // namespace gesmi::cli
