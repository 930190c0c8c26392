// itl-check FILE.itl...: runs the ITF1788 conformance vectors against gesmi's
// interval library. One line per file, then "N passed, N failed, N skipped".
// Exit code: 0 all passed, 1 a test failed, 2 bad command line or unreadable or
// malformed file (one line on stderr). --stats adds a Markdown table per
// operation: counts and excess width over the expected results, in ulps;
// --excess N lists the passed tests whose result is more than N ulps wider.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "tools/itl_check/itl_parser.h"
#include "tools/itl_check/itl_runner.h"

namespace {

using gesmi::itl::Outcome;

struct Counts {
  int passed = 0, failed = 0, skipped = 0;
  void add(Outcome o) { (o == Outcome::passed ? passed : o == Outcome::failed ? failed : skipped) += 1; }
};

struct OperationStats {
  Counts counts;
  std::map<std::string, int> skip_reasons;
  std::vector<double> excess;  // ulps, one per passed test with an interval result
};

constexpr double kNoReportValue = -1.0;

struct Options {
  bool stats = false;
  double report_excess = kNoReportValue;  // --excess N: list passed tests wider than N ulps
  std::vector<std::string> files;
};

class UsageError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

constexpr const char* kUsage = "usage: itl-check [--stats] [--excess ULPS] FILE.itl...";

Options parse_command_line(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--stats") {
      options.stats = true;
    } else if (arg == "--excess" && i + 1 < argc) {
      options.report_excess = std::strtod(argv[++i], nullptr);
    } else if (arg == "--help" || arg == "-h") {
      std::cout << kUsage << "\n";
      std::exit(0);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "'; " + kUsage);
    } else {
      options.files.push_back(arg);
    }
  }
  if (options.files.empty()) throw UsageError(std::string("no input file; ") + kUsage);
  return options;
}

std::vector<gesmi::itl::Test> read_tests(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw UsageError(file + ": cannot read the file");
  try {
    return gesmi::itl::parse(in);
  } catch (const gesmi::itl::ParseError& e) {
    throw UsageError(file + ": " + e.what());
  }
}

std::string list(const std::vector<gesmi::itl::Value>& values) {
  std::string s;
  for (const auto& v : values) s += (s.empty() ? "" : " ") + gesmi::itl::to_string(v);
  return s;
}

std::string format_ulps(double u) {
  if (std::isinf(u)) return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.0f", u);
  return buffer;
}

void print_stats(const std::map<std::string, OperationStats>& stats) {
  std::cout << "\n| operation | passed | failed | skipped | skip reasons | median excess (ulps) | worst excess (ulps) |\n"
               "|---|---:|---:|---:|---|---:|---:|\n";
  for (const auto& [name, s] : stats) {
    std::string reasons;
    for (const auto& [reason, n] : s.skip_reasons) reasons += (reasons.empty() ? "" : ", ") + reason + " " + std::to_string(n);
    std::vector<double> e = s.excess;
    std::sort(e.begin(), e.end());
    const std::string median = e.empty() ? "-" : format_ulps(e[e.size() / 2]);
    const std::string worst = e.empty() ? "-" : format_ulps(e.back());
    std::cout << "| " << name << " | " << s.counts.passed << " | " << s.counts.failed << " | " << s.counts.skipped << " | "
              << reasons << " | " << median << " | " << worst << " |\n";
  }
  std::cout << "\n";
}

int run(const Options& options) {
  std::vector<std::pair<std::string, std::vector<gesmi::itl::Test>>> inputs;
  for (const std::string& file : options.files) inputs.emplace_back(file, read_tests(file));  // all readable first

  Counts total;
  std::map<std::string, OperationStats> stats;
  for (const auto& [file, tests] : inputs) {
    Counts counts;
    for (const gesmi::itl::Test& test : tests) {
      const gesmi::itl::TestResult result = gesmi::itl::run(test);
      counts.add(result.outcome);
      OperationStats& op = stats[test.operation];
      op.counts.add(result.outcome);
      if (result.outcome == Outcome::skipped) ++op.skip_reasons[result.message];
      if (result.outcome == Outcome::failed)
        std::cout << file << ":" << test.line << ": FAILED " << result.message << "\n";
      if (result.outcome == Outcome::passed && result.excess_ulps >= 0.0) op.excess.push_back(result.excess_ulps);
      if (options.report_excess >= 0.0 && result.excess_ulps > options.report_excess)
        std::cout << file << ":" << test.line << ": excess " << format_ulps(result.excess_ulps) << " ulps: " << test.operation
                  << " " << list(test.args) << " = " << list(test.results) << "\n";
    }
    std::cout << file << ": " << counts.passed << " passed, " << counts.failed << " failed, " << counts.skipped
              << " skipped\n";
    total.passed += counts.passed;
    total.failed += counts.failed;
    total.skipped += counts.skipped;
  }
  if (options.stats) print_stats(stats);
  std::cout << total.passed << " passed, " << total.failed << " failed, " << total.skipped << " skipped\n";
  return total.failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse_command_line(argc, argv));
  } catch (const UsageError& e) {
    std::cerr << "itl-check: " << e.what() << "\n";
    return 2;
  }
}
