#include "tools/gesmi/solve_arguments.h"

#include <cmath>
#include <cstdio>

#include "io/files/mission_file.h"
#include "solver/network/mission_network.h"
#include "tools/gesmi/cli_args.h"
#include "tools/gesmi/command_report.h"
#include "tools/gesmi/skip_existing.h"

namespace gesmi::cli {

namespace po = boost::program_options;

po::options_description solve_options() {
  po::options_description options("solve options");
  options.add_options()
      ("mission", po::value<std::string>()->required(), "mission file (HDF5)")
      ("output,o", po::value<std::string>()->required(), "result file to write (HDF5)")
      ("config", po::value<std::string>(), "sensor bounds (YAML) overriding the mission's")
      ("max-sweeps", po::value<std::string>()->default_value("100"), "sweep limit")
      ("tolerance", po::value<std::string>()->default_value("0.001"), "stop when no bound moves more (m)")
      ("from", po::value<std::string>(), "warm start from an earlier result of this mission")
      ("max-outliers", po::value<std::string>(),
       "tolerate up to Q wrong marks or GPS fixes: the result holds every trajectory consistent with all the data "
       "but at most Q of them (guaranteed whenever at most Q are wrong)")
      ("minimal-outliers", po::value<std::string>(),
       "CONDITIONAL: the hull over the smallest sets (q* <= Q) of marks or fixes whose removal restores "
       "consistency; it contains the truth only if exactly q* inputs are wrong")
      ("trust-gps", "GPS fixes are never outliers: only marks are tolerated as wrong")
      ("mines", po::value<std::string>(), "number of mines K (default: the mission's)")
      ("png", "also draw the envelope and mine boxes: RESULT.envelope.png")
      ("geojson", "also write the mine boxes and envelope as GeoJSON: RESULT.geojson")
      ("mines-csv", "also write the mine boxes as CSV: RESULT.mines.csv");
  add_json_option(options, true);
  add_skip_existing(options);
  return options;
}

SolveOptions parse_solve_options(const po::variables_map& v) {
  SolveOptions o;
  o.propagation.max_sweeps = parse_int("--max-sweeps", v["max-sweeps"].as<std::string>());
  o.propagation.tolerance = parse_double("--tolerance", v["tolerance"].as<std::string>());
  if (v.count("max-outliers") && v.count("minimal-outliers"))
    throw UsageError("--max-outliers and --minimal-outliers cannot be combined");
  for (const std::string name : {"max-outliers", "minimal-outliers"}) {
    if (!v.count(name)) continue;
    // (-1 is the options' "no outlier mode": a negative count given here becomes -2,
    // which validate() refuses)
    const int q = parse_int("--" + name, v[name].as<std::string>());
    o.max_outliers = q < 0 ? -2 : q;
    o.outlier_mode = name == "max-outliers" ? OutlierMode::relaxed : OutlierMode::minimal;
  }
  o.trust_gps = v.count("trust-gps") > 0;
  // The warm rerun's earlier result is read later: a placeholder stands for it in the
  // check, and the caller sets the real one.
  static const MissionSolution kEarlierResult;
  SolveOptions checked = o;
  if (v.count("from")) checked.warm_from = &kEarlierResult;
  if (const std::string why = checked.validate(); !why.empty()) throw UsageError("--" + why);
  return o;
}

io::SolveSiblings parse_solve_siblings(const po::variables_map& v) {
  io::SolveSiblings s;
  s.envelope_png = v.count("png") > 0;
  s.geojson = v.count("geojson") > 0;
  s.mines_csv = v.count("mines-csv") > 0;
  return s;
}

void apply_mine_count(const po::variables_map& v, Mission& mission) {
  if (!v.count("mines")) return;
  const long long k = parse_integer("--mines", v["mines"].as<std::string>());
  int largest = -1;
  for (const std::int32_t i : mission.mark_mine) largest = std::max(largest, static_cast<int>(i));
  if (k <= largest)
    throw UsageError("--mines: " + std::to_string(k) + " is not more than the largest mine number in the mark table (" +
                     std::to_string(largest) + ")");
  if (k > kMaxMines) throw UsageError("--mines: at most " + std::to_string(kMaxMines) + " mines");
  mission.mine_count = static_cast<int>(k);
}

void apply_config(const po::variables_map& v, Mission& mission, std::string_view command) {
  if (!v.count("config")) return;
  if (const auto notice = io::merge_model_config(mission, v["config"].as<std::string>()))
    std::fprintf(stderr, "gesmi %.*s: note: %s\n", static_cast<int>(command.size()), command.data(), notice->c_str());
}

}  // namespace gesmi::cli
