#include "tools/gesmi/inconsistent_gate.h"

#include <cstdio>

namespace gesmi::cli {

void add_show_inconsistent(boost::program_options::options_description& options) {
  options.add_options()("show-inconsistent",
                        "go on with an inconsistent result (its output is marked INCONSISTENT); refused otherwise");
}

bool accept_result_status(const boost::program_options::variables_map& values, const std::string& command,
                          const std::string& result_path, bool consistent) {
  if (consistent || values.count("show-inconsistent")) return true;
  std::fprintf(stderr,
               "gesmi %s: %s is an inconsistent result (the data contradict the bounds, so its boxes are no answer): "
               "see its diagnosis with gesmi solve, or add --show-inconsistent to %s it anyway\n",
               command.c_str(), result_path.c_str(), command == "candidates" ? "list" : "draw");
  return false;
}

}  // namespace gesmi::cli
