#pragma once
// The gesmi command's subcommands. Each lives in its own cmd_*.cpp file and
// registers itself; main.cpp only dispatches. Exit codes (tools/README.md):
//   0 success, 2 bad input or usage (nothing written), 3 inconsistent data
//   (a result marked inconsistent is written), 1 unexpected internal error.

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gesmi::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInconsistent = 3;

/// Bad command line or input: printed as one line "gesmi: <what>", exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Command {
  std::string_view name;     // e.g. "solve", or "example" for "example paper2d"
  std::string_view summary;  // one line for `gesmi --help`
  int (*run)(std::span<const std::string> args);  // args after the command name
};

/// Registers a subcommand; call from a namespace-scope initializer in its file.
bool register_command(const Command& command);
const std::vector<Command>& commands();

}  // namespace gesmi::cli
