#include "tools/gesmi/command_report.h"

#include <cstdio>

#include "io/io_version.h"
#include "io/report/report_json.h"

namespace gesmi::cli {

void add_json_option(boost::program_options::options_description& options, bool with_stats_alias) {
  options.add_options()("json", "print one JSON report on stdout instead of the summary (docs/reports.md)");
  if (with_stats_alias) options.add_options()("stats", "the same as --json (its older name)");
}

CommandReport::CommandReport(std::string command, const boost::program_options::variables_map& values)
    : enabled_(values.count("json") > 0 || values.count("stats") > 0),
      fields_({{"schema", "gesmi-report"},
               {"schema_version", kReportSchemaVersion},
               {"command", std::move(command)},
               {"gesmi_version", std::string(io::version())}}) {}

void CommandReport::input(const std::string& role, const std::string& path) {
  inputs_.push_back({{"role", role}, {"path", path}});
}

void CommandReport::inputs(const boost::program_options::variables_map& values,
                           std::initializer_list<const char*> options) {
  for (const char* name : options)
    if (values.count(name)) input(name, values[name].as<std::string>());
}

void CommandReport::output(const std::string& path) { outputs_.push_back(path); }

void CommandReport::outputs(const std::vector<std::string>& paths) {
  for (const std::string& p : paths) output(p);
}

void CommandReport::timings(const std::map<std::string, double>& milliseconds) {
  for (const auto& [name, ms] : milliseconds) fields_["timings_ms"][name] = io::number_json(ms);
}

int CommandReport::finish(int exit_code) {
  if (!enabled_) return exit_code;
  fields_["exit_code"] = exit_code;
  fields_["inputs"] = inputs_;
  fields_["outputs"] = outputs_;
  if (!fields_.contains("timings_ms")) fields_["timings_ms"] = nlohmann::json::object();
  std::printf("%s\n", io::dump_shortest(fields_).c_str());
  return exit_code;
}

}  // namespace gesmi::cli
