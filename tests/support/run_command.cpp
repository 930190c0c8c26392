#include "tests/support/run_command.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/support/paths.h"

namespace gesmi::test {
namespace {

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct TempRoot {
  std::filesystem::path path;
  TempRoot() {
    path = std::filesystem::temp_directory_path() / ("gesmi-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~TempRoot() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

TempRoot& temp_root() {
  static TempRoot root;
  return root;
}

}  // namespace

std::string temp_folder(const std::string& tag) {
  static int counter = 0;
  const auto folder = temp_root().path / (tag + "-" + std::to_string(++counter));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder.string();
}

CommandResult run_program(const std::string& program, const std::vector<std::string>& args) {
  const std::string folder = temp_folder("run");
  const std::string out = folder + "/stdout", err = folder + "/stderr";
  std::string command = shell_quote(bin_dir() + "/" + program);
  for (const std::string& a : args) command += " " + shell_quote(a);
  command += " >" + shell_quote(out) + " 2>" + shell_quote(err) + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = read_all(out);
  result.err = read_all(err);
  // In the GESMI_SANITIZE build a sanitizer report in the child fails the calling
  // test, whatever exit code that test expects (tools/sanitizers/check gives such a
  // child the exit code 86, and the report goes to its stderr).
  if (result.err.find("Sanitizer") != std::string::npos || result.err.find("runtime error:") != std::string::npos)
    ADD_FAILURE() << program << " reported a sanitizer error (exit code " << result.exit_code << "):\n" << result.err;
  return result;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int line_count(const std::string& s) {
  int lines = 0;
  for (const char c : s) lines += (c == '\n');
  if (!s.empty() && s.back() != '\n') ++lines;
  return lines;
}

std::set<std::string> names_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(folder)) names.insert(e.path().filename().string());
  return names;
}

}  // namespace gesmi::test
