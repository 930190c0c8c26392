#pragma once
// Runs a built executable (e.g. build/bin/gesmi) from a test and captures its exit
// code, standard output and standard error.

#include <set>
#include <string>
#include <vector>

namespace gesmi::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs bin_dir()/<program> with the arguments (each quoted for the shell).
/// A sanitizer report on the program's stderr fails the calling test.
CommandResult run_program(const std::string& program, const std::vector<std::string>& args);
inline CommandResult run_gesmi(const std::vector<std::string>& args) { return run_program("gesmi", args); }

/// A fresh empty temporary folder, removed at the end of the test program.
std::string temp_folder(const std::string& tag);

/// The names of the entries of a folder (what a command left there).
std::set<std::string> names_in(const std::string& folder);

/// The whole content of a file (empty when it cannot be read).
std::string file_text(const std::string& path);

/// Number of lines of s (a final line without newline counts).
int line_count(const std::string& s);

}  // namespace gesmi::test
