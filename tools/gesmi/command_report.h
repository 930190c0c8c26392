#pragma once
// The --json report every command can print instead of its summary: one JSON object
// on one line of stdout (docs/reports.md and its schema, docs/report.schema.json):
// schema name and version, command, gesmi version, exit code, the files read and
// written, timings, and the command's own fields. Warnings and errors stay on stderr;
// a command that fails on bad input (exit 2) prints no report.

#include <boost/program_options.hpp>
#include <chrono>
#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace gesmi::cli {

/// Milliseconds of wall time since `since`, for the reports' timings.
inline double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

inline constexpr int kReportSchemaVersion = 1;

/// Adds --json (and, for solve and kalman, its older name --stats).
void add_json_option(boost::program_options::options_description& options, bool with_stats_alias = false);

class CommandReport {
 public:
  CommandReport(std::string command, const boost::program_options::variables_map& values);
  /// True when --json (or --stats) was given: print the report, not the summary.
  bool enabled() const { return enabled_; }
  void input(const std::string& role, const std::string& path);
  /// The given ones of `options` as inputs, each in the role of its option's name.
  void inputs(const boost::program_options::variables_map& values, std::initializer_list<const char*> options);
  void output(const std::string& path);
  void outputs(const std::vector<std::string>& paths);
  void timings(const std::map<std::string, double>& milliseconds);
  /// The command's own fields.
  nlohmann::json& operator[](const std::string& key) { return fields_[key]; }
  /// Prints the report when enabled; returns exit_code.
  int finish(int exit_code);

 private:
  bool enabled_ = false;
  nlohmann::json fields_;
  nlohmann::json inputs_ = nlohmann::json::array(), outputs_ = nlohmann::json::array();
};

}  // namespace gesmi::cli
