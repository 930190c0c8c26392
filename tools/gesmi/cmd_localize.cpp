// gesmi localize: static localization by set inversion (seeds 000, 002, 003, 004).
// Thin: read the scenario (io), solve (solver), write the outputs (io), print the
// summary. With --simulate it prints measurements simulated at the scenario's true
// pose instead (the generator of missions/localization/).

#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/output/output_set.h"
#include "io/localization/localization_json.h"
#include "io/localization/localization_output.h"
#include "io/localization/localization_scenario.h"
#include "solver/setinv/localization/measurement_simulator.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/progress.h"
#include "io/report/report_json.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

constexpr const char* kLocalizeUsage =
    "gesmi localize SCENARIO.yaml -o OUT_DIR [--safety] [--quiet] [--skip-existing]\n"
    "       gesmi localize SCENARIO.yaml --simulate [--seed N] [--error-fraction F] [--range-outliers I,J]\n"
    "                      [--bearing-outliers I,J]";

std::vector<std::size_t> parse_indices(std::string_view option, const std::string& text) {
  std::vector<std::size_t> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) {
      const long long v = parse_integer(option, item);
      if (v < 0) throw UsageError(std::string(option) + ": indices must not be negative");
      out.push_back(static_cast<std::size_t>(v));
    }
  return out;
}

int simulate(LocalizationProblem problem, const po::variables_map& values) {
  if (!problem.truth) throw UsageError("--simulate needs a 'truth' pose in the scenario");
  MeasurementSimulationOptions options;
  const long long seed = parse_integer("--seed", values["seed"].as<std::string>());
  if (seed < 0 || seed > std::numeric_limits<std::uint32_t>::max())
    throw UsageError("--seed: must be between 0 and " + std::to_string(std::numeric_limits<std::uint32_t>::max()));
  options.seed = static_cast<std::uint32_t>(seed);
  options.error_fraction = parse_non_negative("--error-fraction", values["error-fraction"].as<std::string>());
  if (options.error_fraction >= 1.0) throw UsageError("--error-fraction must be below 1");
  if (values.count("range-outliers"))
    options.range_outliers = parse_indices("--range-outliers", values["range-outliers"].as<std::string>());
  if (values.count("bearing-outliers"))
    options.bearing_outliers = parse_indices("--bearing-outliers", values["bearing-outliers"].as<std::string>());
  for (std::size_t i : options.range_outliers)
    if (i >= problem.range_sensors.size()) throw UsageError("--range-outliers: no range sensor " + std::to_string(i));
  try {
    problem.ranges = simulate_ranges(problem.map, problem.range_sensors, *problem.truth, options);
    problem.bearings = simulate_bearings(problem.map, problem.bearing_sensors, *problem.truth, options);
  } catch (const std::domain_error& e) {  // an outlier asked for where none can be drawn
    throw UsageError(std::string("--simulate: ") + e.what());
  }
  std::fputs(io::localization_measurements_yaml(problem).c_str(), stdout);
  return kExitOk;
}

int run_localize(std::span<const std::string> args) {
  po::options_description options("localize options");
  options.add_options()
      ("scenario", po::value<std::string>(), "scenario file (YAML)")
      ("output,o", po::value<std::string>(), "output folder (created if missing)")
      ("quiet,q", "print neither the summary nor the progress line")
      ("safety", "also compute Remark 6's safety of each datum (one more SIVIA per datum)")
      ("simulate", "print measurements simulated at the scenario's true pose, write nothing")
      ("seed", po::value<std::string>()->default_value("1"), "--simulate: random seed")
      ("error-fraction", po::value<std::string>()->default_value("0.9"), "--simulate: errors as a fraction of the bounds")
      ("range-outliers", po::value<std::string>(), "--simulate: range sensor indices given outlier values")
      ("bearing-outliers", po::value<std::string>(), "--simulate: bearing measurement indices given outlier values");
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("scenario", 1);
  po::variables_map values;
  if (!parse_options(args, options, positional, values, kLocalizeUsage)) return kExitOk;
  if (!values.count("scenario")) throw UsageError(std::string("missing SCENARIO.yaml; usage: ") + kLocalizeUsage);
  const LocalizationProblem problem = io::read_localization_scenario(values["scenario"].as<std::string>());
  if (values.count("simulate")) {
    if (values.count("json")) throw UsageError("--json: --simulate prints measurements as YAML, not a report");
    return simulate(problem, values);
  }
  if (!values.count("output")) throw UsageError(std::string("missing -o OUT_DIR; usage: ") + kLocalizeUsage);
  const std::string folder = values["output"].as<std::string>();
  io::OutputSet outputs(input_files(values, {"scenario"}));
  io::OutputSet::check_folder(folder);  // before the search, which can be long
  if (skipped_as_existing(values, "localize", io::localization_output_files(folder))) return kExitOk;
  Progress progress("gesmi localize:", values.count("quiet") > 0);  // on a terminal, for long searches only (progress.h)
  progress.update(-1.0, "searching");
  LocalizationResult result = localize(problem, [&](const SiviaProgress& p) {
    progress.update(-1.0, "searching: " + std::to_string(p.boxes_visited) + " boxes, " + std::to_string(p.inner_boxes) +
                              " inner, " + std::to_string(p.boundary_boxes) + " boundary");
  });
  if (values.count("safety") && result.found) {
    progress.update(-1.0, "safety of each datum");
    result.safety = localization_safety(problem, result);
  }
  progress.update(-1.0, "writing " + folder);
  outputs.prepare_folder(folder);
  const std::vector<std::string> written = io::write_localization_outputs(folder, problem, result);
  outputs.commit();
  progress.finish();
  const int exit_code = result.found ? kExitOk : kExitInconsistent;
  CommandReport report("localize", values);
  if (report.enabled()) {
    report.inputs(values, {"scenario"});
    report.outputs(written);
    report.timings({{"search", result.seconds * 1000.0}});
    report["localization"] = io::localization_json(problem, result, io::DatumNumbering::index);
    return report.finish(exit_code);
  }
  if (!values.count("quiet")) std::fputs(io::localization_summary(problem, result).c_str(), stdout);
  return exit_code;
}

const bool localize_registered = register_command(
    {"localize", "static localization by set inversion (SIVIA, GOMNE) from range and bearing data", run_localize});

}  // namespace
}  // namespace gesmi::cli
