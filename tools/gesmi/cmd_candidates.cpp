// gesmi candidates: where to look again on the sonar record (missed-mine windows).

#include <cstdio>

#include "io/output/output_set.h"
#include "io/output/atomic_output.h"
#include "io/files/result_file.h"
#include "io/text/csv_number.h"
#include "solver/network/waterfall/look_again.h"
#include "tools/gesmi/input_files.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/inconsistent_gate.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

int run_candidates(std::span<const std::string> args) {
  po::options_description options("candidates options");
  options.add_options()("result", po::value<std::string>()->required(), "result file of gesmi solve")(
      "csv", po::value<std::string>(), "also write the windows as CSV (mine,t_start,t_end,range_lo,range_hi,status)");
  add_show_inconsistent(options);
  add_json_option(options);
  po::positional_options_description positional;
  positional.add("result", 1);
  po::variables_map v;
  if (!parse_options(args, options, positional, v, "gesmi candidates RESULT.h5 [--csv OUT.csv] [--show-inconsistent]")) return kExitOk;
  io::OutputSet outputs(input_files(v, {"result"}));
  if (v.count("csv")) outputs.check(v["csv"].as<std::string>());
  const io::SolveResult file = io::read_result(v["result"].as<std::string>(), {.tube = false});
  const MissionSolution& r = file.solution;
  if (!accept_result_status(v, "candidates", v["result"].as<std::string>(), r.report.consistent)) return kExitInconsistent;
  const char* status = r.report.consistent ? "consistent" : "inconsistent";
  const std::vector<LookAgainWindow> windows = look_again_windows(r.waterfall, r.time, r.mark_time, r.candidates);
  std::string csv = "mine,t_start,t_end,range_lo,range_hi,status\n";
  nlohmann::json listed = nlohmann::json::array();
  for (const LookAgainWindow& w : windows) {
    // Exact numbers (shortest round-trip text): a window's bounds are never rounded inward.
    csv += std::to_string(w.mine);
    for (const double x : {w.t_start, w.t_end, w.range_lo, w.range_hi}) csv += "," + io::format_number(x);
    csv += std::string(",") + status + "\n";
    listed.push_back({{"mine", w.mine}, {"t_start", w.t_start}, {"t_end", w.t_end}, {"range_lo", w.range_lo},
                      {"range_hi", w.range_hi}});
  }
  if (v.count("csv")) {
    io::write_text_file(v["csv"].as<std::string>(), csv);
    outputs.commit();
  }
  CommandReport report("candidates", v);
  if (report.enabled()) {
    report.inputs(v, {"result"});
    if (v.count("csv")) report.output(v["csv"].as<std::string>());
    report["status"] = status;
    report["windows"] = listed;
    return report.finish(kExitOk);
  }
  if (!r.report.consistent) std::printf("INCONSISTENT result: these windows are no answer\n");
  std::printf("%-5s %10s %10s %9s %9s\n", "mine", "t_start", "t_end", "range_lo", "range_hi");
  for (const LookAgainWindow& w : windows)
    std::printf("%-5d %10.1f %10.1f %9.2f %9.2f\n", w.mine, w.t_start, w.t_end, w.range_lo, w.range_hi);
  if (windows.empty()) std::printf("no window: every place a mine can be on the swath has a mark\n");
  if (v.count("csv")) std::printf("wrote %s\n", v["csv"].as<std::string>().c_str());
  return kExitOk;
}

const bool candidates_registered =
    register_command({"candidates", "list where a missed mine could be on the sonar record", run_candidates});

}  // namespace
}  // namespace gesmi::cli
