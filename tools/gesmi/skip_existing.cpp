#include "tools/gesmi/skip_existing.h"

#include <cstdio>
#include <filesystem>

#include "tools/gesmi/command_report.h"

namespace gesmi::cli {

void add_skip_existing(boost::program_options::options_description& options) {
  options.add_options()("skip-existing", "do nothing when every output exists already (batch reruns)");
}

bool skipped_as_existing(const boost::program_options::variables_map& values, std::string_view command,
                         const std::vector<std::string>& outputs) {
  if (!values.count("skip-existing") || outputs.empty()) return false;
  std::error_code ec;
  for (const std::string& path : outputs)
    if (!std::filesystem::is_regular_file(path, ec)) return false;
  CommandReport report(std::string(command), values);
  if (report.enabled()) {
    report["skipped"] = true;
    report["existing"] = outputs;
    report.finish(0);
    return true;
  }
  std::string names;
  for (const std::string& path : outputs) names += (names.empty() ? "" : ", ") + path;
  std::printf("gesmi %.*s: %s already written; skipped (--skip-existing)\n", static_cast<int>(command.size()),
              command.data(), names.c_str());
  return true;
}

}  // namespace gesmi::cli
