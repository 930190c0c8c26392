// gesmi example paper2d: the academic example of seed 001 (sections II-B, III-D).

#include <cstdio>
#include <string>
#include <vector>

#include "solver/network/paper2d.h"
#include "tools/gesmi/cli_args.h"
#include "io/report/report_json.h"
#include "tools/gesmi/command_report.h"

namespace gesmi::cli {
namespace {

namespace po = boost::program_options;

std::string text_interval(const Interval& x) {
  if (x.is_empty()) return "[empty]";
  char buffer[80];
  std::snprintf(buffer, sizeof buffer, "[%.10g, %.10g]", x.lo(), x.hi());
  return buffer;
}

// The domains as report fields: each key a list of intervals ([lo, hi], null when empty).
void add_domains(CommandReport& report, const Paper2dDomains& d, const PropagationReport& propagation) {
  const auto add = [&](const std::string& key, const std::vector<Interval>& values) {
    nlohmann::json list = nlohmann::json::array();
    for (const Interval& x : values) list.push_back(io::interval_json(x));
    report[key] = list;
  };
  for (std::size_t k = 0; k < 3; ++k) add("z" + std::to_string(k + 1), {d.z[k]});
  add("m", {d.m[0], d.m[1]});
  for (std::size_t k = 0; k < 4; ++k) add("v" + std::to_string(k), {d.v[k][0], d.v[k][1]});
  for (std::size_t k = 1; k <= 4; ++k) add("x" + std::to_string(k), {d.x[k][0], d.x[k][1]});
  report["sweeps"] = propagation.sweeps;
  report["empty"] = propagation.empty;
}

void print_text(const Paper2dDomains& d, const PropagationReport& report) {
  std::printf("paper2d: fixpoint after %d sweeps%s\n", report.sweeps, report.empty ? " (no solution)" : "");
  for (std::size_t k = 0; k < 3; ++k) std::printf("  z%zu  %s\n", k + 1, text_interval(d.z[k]).c_str());
  std::printf("  m   %s x %s\n", text_interval(d.m[0]).c_str(), text_interval(d.m[1]).c_str());
  for (std::size_t k = 0; k < 4; ++k)
    std::printf("  v%zu  %s x %s\n", k, text_interval(d.v[k][0]).c_str(), text_interval(d.v[k][1]).c_str());
  for (std::size_t k = 1; k <= 4; ++k)
    std::printf("  x%zu  %s x %s\n", k, text_interval(d.x[k][0]).c_str(), text_interval(d.x[k][1]).c_str());
}

int run_example(std::span<const std::string> args) {
  if (args.empty() || args[0] != "paper2d") {
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
      std::printf("usage: gesmi example paper2d [--delta-v DV] [--delta-z DZ] [--delta-x DX] [--json]\n");
      return kExitOk;
    }
    throw UsageError("expected an example name: paper2d");
  }
  po::options_description options("paper2d options (domains [a - d, a + 2d] around the true values; inf = unmeasured)");
  options.add_options()
      ("delta-v", po::value<std::string>()->default_value("1"), "velocity error coefficient DV >= 0")
      ("delta-z", po::value<std::string>()->default_value("1"), "range error coefficient DZ >= 0")
      ("delta-x", po::value<std::string>()->default_value("inf"), "final GPS error coefficient DX >= 0")
      ("json", "print one JSON report (docs/reports.md) with keys z1 z2 z3 m v0..v3 x1..x4");
  po::variables_map values;
  if (!parse_options(args.subspan(1), options, {}, values,
                     "gesmi example paper2d [--delta-v DV] [--delta-z DZ] [--delta-x DX] [--json]"))
    return kExitOk;
  Paper2dDeltas deltas;
  deltas.v = parse_non_negative("--delta-v", values["delta-v"].as<std::string>());
  deltas.z = parse_non_negative("--delta-z", values["delta-z"].as<std::string>());
  deltas.x = parse_non_negative("--delta-x", values["delta-x"].as<std::string>());
  const Paper2dResult result = solve_paper2d(paper2d_prior(deltas));
  CommandReport report("example paper2d", values);
  if (report.enabled())
    add_domains(report, result.domains, result.report);
  else
    print_text(result.domains, result.report);
  return report.finish(kExitOk);
}

const bool example_registered =
    register_command({"example", "run a built-in example: paper2d (seed 001, section II-B)", run_example});

}  // namespace
}  // namespace gesmi::cli
