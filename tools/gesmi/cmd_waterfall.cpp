// gesmi waterfall: the reconstructed waterfall picture of a result (seed 001, Fig. 8),
// with the windows where a missed mine could be marked.

#include <cstdio>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/plot/plot_waterfall.h"
#include "io/files/result_file.h"
#include "solver/network/waterfall/look_again.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/inconsistent_gate.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

int run_waterfall(std::span<const std::string> args) {
  po::options_description options("waterfall options");
  options.add_options()("result", po::value<std::string>()->required(), "result file of gesmi solve")(
      "output,o", po::value<std::string>()->required(), "PNG picture to write")(
      "max-range", po::value<std::string>()->default_value("75"), "range axis length (m)");
  add_show_inconsistent(options);
  add_json_option(options);
  add_skip_existing(options);
  po::positional_options_description positional;
  positional.add("result", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi waterfall RESULT.h5 -o waterfall.png [--show-inconsistent] [--skip-existing]")) return kExitOk;
  const double max_range = parse_non_negative("--max-range", v["max-range"].as<std::string>());
  if (!(max_range > 0.0) || !std::isfinite(max_range)) throw UsageError("--max-range: must be a positive number");
  const std::string output = v["output"].as<std::string>();
  io::OutputSet outputs(input_files(v, {"result"}));
  outputs.check(output);
  if (skipped_as_existing(v, "waterfall", {output})) return kExitOk;
  const io::SolveResult file = io::read_result(v["result"].as<std::string>(), {.tube = false});
  const MissionSolution& r = file.solution;
  if (!accept_result_status(v, "waterfall", v["result"].as<std::string>(), r.report.consistent)) return kExitInconsistent;
  io::WaterfallPicture picture;
  picture.waterfall = &r.waterfall;
  picture.time = r.time;
  picture.max_range = max_range;
  for (std::size_t j = 0; j < r.mark_time.size(); ++j)
    for (int i = 0; i < r.mine_count; ++i)
      if (r.candidates[j] >> i & 1) picture.marks.push_back({r.mark_time[j], r.mark_range[j], i});
  for (const LookAgainWindow& w : look_again_windows(r.waterfall, r.time, r.mark_time, r.candidates))
    picture.windows.push_back({w.mine, w.t_start, w.t_end, w.range_lo, w.range_hi});
  picture.title = std::string(r.report.consistent ? "" : "INCONSISTENT result, no answer: ") + "reconstructed waterfall" +
                  ": grey = where each mine can appear, dots = marks, orange = look again";
  io::write_waterfall_png(picture, output);
  outputs.commit();
  CommandReport report("waterfall", v);
  if (report.enabled()) {
    report.inputs(v, {"result"});
    report.output(output);
    report["status"] = r.report.consistent ? "consistent" : "inconsistent";
    report["mines"] = r.mine_count;
    report["marks"] = r.mark_time.size();
    report["windows"] = picture.windows.size();
    return report.finish(kExitOk);
  }
  std::printf("wrote %s (%s%d mines, %zu marks, %zu windows to look at again)\n", output.c_str(), r.report.consistent ? "" : "INCONSISTENT result, ", r.mine_count,
              r.mark_time.size(), picture.windows.size());
  return kExitOk;
}

const bool waterfall_registered =
    register_command({"waterfall", "draw the reconstructed waterfall of a result", run_waterfall});

}  // namespace
}  // namespace gesmi::cli
