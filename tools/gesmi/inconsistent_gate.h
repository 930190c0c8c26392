#pragma once
// Commands that read a result (candidates, waterfall, export) refuse an inconsistent
// one: its boxes are not an answer (the data contradict the bounds), so showing them
// as one misleads. --show-inconsistent draws it anyway, marked as such.

#include <boost/program_options.hpp>
#include <string>

namespace gesmi::cli {

void add_show_inconsistent(boost::program_options::options_description& options);

/// True when the command may go on with a result of this status; otherwise prints one
/// line naming the file and the remedy on stderr, and with --json a report with
/// "refused": true (the caller exits with kExitInconsistent).
bool accept_result_status(const boost::program_options::variables_map& values, const std::string& command,
                          const std::string& result_path, bool consistent);

}  // namespace gesmi::cli
