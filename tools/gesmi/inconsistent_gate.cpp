#include "tools/gesmi/inconsistent_gate.h"

#include <cstdio>

#include "io/text/message_text.h"
#include "tools/gesmi/command.h"
#include "tools/gesmi/command_report.h"

namespace gesmi::cli {

void add_show_inconsistent(boost::program_options::options_description& options) {
  options.add_options()("show-inconsistent",
                        "go on with an inconsistent result (its output is marked INCONSISTENT); refused otherwise");
}

bool accept_result_status(const boost::program_options::variables_map& values, const std::string& command,
                          const std::string& result_path, bool consistent) {
  if (consistent || values.count("show-inconsistent")) return true;
  const char* verb = command == "candidates" ? "list" : (command == "waterfall" ? "draw" : "export");
  std::fprintf(stderr, "%s\n",
               io::one_line("gesmi " + command + ": " + result_path +
                            " is an inconsistent result (the data contradict the bounds, so its boxes are no answer): "
                            "see its diagnosis with gesmi solve, or add --show-inconsistent to " + verb + " it anyway")
                   .c_str());
  CommandReport report(command, values);
  if (report.enabled()) {
    report.input("result", result_path);
    report["status"] = "inconsistent";
    report["refused"] = true;
    report.finish(kExitInconsistent);
  }
  return false;
}

}  // namespace gesmi::cli
