// gesmi candidates: where to look again on the sonar record (missed-mine windows).

#include <cstdio>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/files/result_file.h"
#include "solver/network/look_again.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

int run_candidates(std::span<const std::string> args) {
  po::options_description options("candidates options");
  options.add_options()("result", po::value<std::string>()->required(), "result file of gesmi solve")(
      "csv", po::value<std::string>(), "also write the windows as CSV (mine,t_start,t_end,range_lo,range_hi)");
  po::positional_options_description positional;
  positional.add("result", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi candidates RESULT.h5 [--csv OUT.csv]")) return kExitOk;
  io::OutputSet outputs(input_files(v, {"result"}));
  if (v.count("csv")) outputs.check(v["csv"].as<std::string>());
  const io::SolveResult file = io::read_result(v["result"].as<std::string>(), {.tube = false});
  const MissionSolution& r = file.solution;
  const std::vector<LookAgainWindow> windows = look_again_windows(r.waterfall, r.time, r.mark_time, r.candidates);
  std::string csv = "mine,t_start,t_end,range_lo,range_hi\n";
  std::printf("%-5s %10s %10s %9s %9s\n", "mine", "t_start", "t_end", "range_lo", "range_hi");
  for (const LookAgainWindow& w : windows) {
    char line[160];
    std::snprintf(line, sizeof line, "%d,%.1f,%.1f,%.2f,%.2f\n", w.mine, w.t_start, w.t_end, w.range_lo, w.range_hi);
    csv += line;
    std::printf("%-5d %10.1f %10.1f %9.2f %9.2f\n", w.mine, w.t_start, w.t_end, w.range_lo, w.range_hi);
  }
  if (windows.empty()) std::printf("no window: every place a mine can be on the swath has a mark\n");
  if (v.count("csv")) {
    io::write_text_file(v["csv"].as<std::string>(), csv);
    outputs.commit();
    std::printf("wrote %s\n", v["csv"].as<std::string>().c_str());
  }
  return kExitOk;
}

const bool registered = register_command({"candidates", "list where a missed mine could be on the sonar record", run_candidates});

}  // namespace
}  // namespace gesmi::cli
