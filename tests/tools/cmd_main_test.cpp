// The gesmi command itself, before any subcommand: --help, --version, an unknown
// command.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

// The version the top-level CMakeLists.txt declares, read from the file itself:
// "project(gesmi VERSION x.y.z ...". (No std::regex: GCC 12 warns inside it.)
std::string declared_version() {
  std::ifstream in(source_dir() + "/CMakeLists.txt");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str(), key = "project(gesmi VERSION ";
  const std::size_t at = s.find(key);
  if (at == std::string::npos) return "";
  const std::size_t from = at + key.size();
  return s.substr(from, s.find_first_not_of("0123456789.", from) - from);
}

TEST(CmdMain, VersionPrintsTheDeclaredVersion) {
  const std::string version = declared_version();
  ASSERT_FALSE(version.empty());
  for (const char* flag : {"--version", "-V"}) {
    const CommandResult r = run_gesmi({flag});
    EXPECT_EQ(r.exit_code, 0) << flag;
    EXPECT_EQ(r.out, "gesmi " + version + "\n") << flag;
    EXPECT_EQ(r.err, "") << flag;
  }
}

TEST(CmdMain, HelpListsTheCommandsAndUnknownOnesAreRefused) {
  const CommandResult help = run_gesmi({"--help"});
  EXPECT_EQ(help.exit_code, 0);
  for (const char* command : {"solve", "import", "localize", "--version"}) EXPECT_NE(help.out.find(command), std::string::npos) << command;
  const CommandResult unknown = run_gesmi({"--versoin"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown command '--versoin'; 'gesmi --help' lists the commands"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace gesmi::test
