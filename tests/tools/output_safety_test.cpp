// Outputs never lie about themselves: a command refuses to write over its inputs or
// over something that is not a regular file; the files it writes appear together or
// not at all (a failing write, a full disk, an interrupt); and temporaries of dead
// processes are cleaned up.

#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "io/digest/digest.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::test {
namespace {

namespace fs = std::filesystem;
extern "C" char** environ;

// A short simulated mission, made once.
const std::string& mission() {
  static const std::string path = [] {
    const std::string p = temp_folder("outputs-mission") + "/m.h5";
    EXPECT_EQ(run_gesmi({"simulate", "--seed", "4", "--duration", "600", "-o", p}).exit_code, 0);
    return p;
  }();
  return path;
}

// Runs a shell line whose '$GESMI' is the gesmi binary (environment, ulimit, trap).
CommandResult run_shell(const std::string& line) {
  const std::string folder = temp_folder("shell");
  std::string command = line;
  const std::string binary = "'" + bin_dir() + "/gesmi'";
  for (std::size_t at = command.find("$GESMI"); at != std::string::npos; at = command.find("$GESMI", at + binary.size()))
    command.replace(at, 6, binary);
  const int status = std::system(("(" + command + ") >" + folder + "/out 2>" + folder + "/err </dev/null").c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream out(folder + "/out"), err(folder + "/err");
  r.out.assign(std::istreambuf_iterator<char>(out), {});
  r.err.assign(std::istreambuf_iterator<char>(err), {});
  return r;
}

TEST(OutputSafety, AnOutputThatIsAnInputIsRefusedAndTheInputStaysIntact) {
  const std::string folder = temp_folder("outputs-input");
  const std::string input = folder + "/m.h5";
  fs::copy_file(mission(), input);
  fs::create_hard_link(input, folder + "/hard.h5");
  fs::create_symlink(input, folder + "/soft.h5");
  const std::string before = io::sha256_of_file(input);
  for (const std::string& output : {folder + "/./m.h5", folder + "/hard.h5", folder + "/soft.h5"}) {
    SCOPED_TRACE(output);
    const CommandResult r = run_gesmi({"solve", input, "-o", output});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(output + ": is also an input of this command"), std::string::npos) << r.err;
  }
  const CommandResult marks = run_gesmi({"marks", "add", input, "--time", "100", "--range", "30", "-o", folder + "/hard.h5"});
  EXPECT_EQ(marks.exit_code, 2) << marks.err;
  EXPECT_EQ(io::sha256_of_file(input), before);
  EXPECT_EQ(names_in(folder), (std::set<std::string>{"m.h5", "hard.h5", "soft.h5"}));
}

TEST(OutputSafety, DevicesPipesAndFoldersAreNotReplaced) {
  const std::string folder = temp_folder("outputs-special");
  ASSERT_EQ(::mkfifo((folder + "/pipe").c_str(), 0600), 0);
  fs::create_directory(folder + "/dir.h5");
  for (const std::string& output : {std::string("/dev/null"), folder + "/pipe", folder + "/dir.h5"}) {
    SCOPED_TRACE(output);
    const CommandResult r = run_gesmi({"solve", mission(), "-o", output});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(output + ": "), std::string::npos) << r.err;
  }
  struct stat null_status {};
  ASSERT_EQ(::stat("/dev/null", &null_status), 0);
  EXPECT_TRUE(S_ISCHR(null_status.st_mode));
  EXPECT_EQ(names_in(folder), (std::set<std::string>{"pipe", "dir.h5"}));
}

TEST(OutputSafety, AFailingWriteLeavesNoneOfTheNewFiles) {
  // The result, the mines CSV and the GeoJSON are complete when the picture fails.
  for (const std::string failing : {".envelope.png", ".geojson", "r.h5"}) {
    SCOPED_TRACE(failing);
    const std::string folder = temp_folder("outputs-fail");
    const CommandResult r =
        run_shell("GESMI_TEST_FAIL_WRITE=" + failing + " $GESMI solve '" + mission() + "' -o '" + folder +
                  "/r.h5' --png --geojson --mines-csv");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(".tmp-"), std::string::npos) << "names a temporary: " << r.err;
    EXPECT_TRUE(fs::is_empty(folder)) << *names_in(folder).begin();
  }
  // The demo writes three commands' files: a failure in the last removes them all.
  const std::string parent = temp_folder("outputs-demo");
  const CommandResult demo = run_shell("GESMI_TEST_FAIL_WRITE=waterfall.png $GESMI demo -o '" + parent + "/d'");
  EXPECT_EQ(demo.exit_code, 2) << demo.err;
  EXPECT_FALSE(fs::exists(parent + "/d"));
}

TEST(OutputSafety, AFullDiskIsBadInputAndLeavesNothing) {
  // A file size limit makes every write past it fail, as a full disk does (gesmi
  // ignores the signal the kernel sends there, which would kill it without a word).
  const std::string folder = temp_folder("outputs-full");
  const CommandResult r = run_shell("ulimit -f 64; $GESMI solve '" + mission() + "' -o '" + folder + "/r.h5'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(folder + "/r.h5"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(".tmp-"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(folder));
  // A picture past the limit: one line too (libpng's own handlers would print another).
  const std::string solved = temp_folder("outputs-full-result") + "/r.h5";
  ASSERT_EQ(run_gesmi({"solve", mission(), "-o", solved}).exit_code, 0);
  const std::string pictures = temp_folder("outputs-full-png");
  const CommandResult png = run_shell("ulimit -f 16; $GESMI waterfall '" + solved + "' -o '" + pictures + "/w.png'");
  EXPECT_EQ(png.exit_code, 2) << png.err;
  EXPECT_EQ(line_count(png.err), 1) << png.err;
  EXPECT_TRUE(fs::is_empty(pictures));
  // A real small file system, where this machine allows mounting one: filled at
  // different points (the result, then each sibling), and by other commands.
  const std::string tiny = temp_folder("outputs-tmpfs");
  if (::mount("tmpfs", tiny.c_str(), "tmpfs", 0, "size=64k") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
  ::umount(tiny.c_str());
  const std::string scenario = source_dir() + "/missions/localization/triangle_two_hypotheses.yaml";
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"96k", {"solve", mission(), "-o", tiny + "/r.h5", "--png", "--geojson", "--mines-csv"}},
      {"1000k", {"solve", mission(), "-o", tiny + "/r.h5", "--png", "--geojson", "--mines-csv"}},
      {"1200k", {"solve", mission(), "-o", tiny + "/r.h5", "--png", "--geojson", "--mines-csv"}},
      {"1280k", {"solve", mission(), "-o", tiny + "/r.h5", "--png", "--geojson", "--mines-csv"}},
      {"64k", {"simulate", "--seed", "4", "--duration", "600", "-o", tiny + "/m.h5"}},
      {"64k", {"export", mission(), "-o", tiny + "/csv"}},
      {"64k", {"export", mission(), "--format", "gesmi-txt", "-o", tiny + "/log.txt"}},
      {"64k", {"kalman", mission(), "-o", tiny + "/k.h5"}},
      {"32k", {"localize", scenario, "-o", tiny + "/out"}},
  };
  for (const auto& [size, args] : runs) {
    SCOPED_TRACE(size + " " + args[0] + " " + args.back());
    ASSERT_EQ(::mount("tmpfs", tiny.c_str(), "tmpfs", 0, ("size=" + size).c_str()), 0);
    const CommandResult full = run_gesmi(args);
    const bool empty = fs::is_empty(tiny);
    ::umount(tiny.c_str());
    EXPECT_EQ(full.exit_code, 2) << full.err;
    EXPECT_EQ(line_count(full.err), 1) << full.err;
    EXPECT_EQ(full.err.find(".tmp-"), std::string::npos) << full.err;
    EXPECT_TRUE(empty);
  }
}

// Starts gesmi with the environment plus `extra`, returns its pid.
pid_t spawn_gesmi(const std::vector<std::string>& args, const std::string& extra) {
  std::vector<std::string> env_strings;
  for (char** e = environ; *e; ++e) env_strings.emplace_back(*e);
  env_strings.push_back(extra);
  std::vector<char*> env, argv;
  for (std::string& s : env_strings) env.push_back(s.data());
  env.push_back(nullptr);
  std::string binary = bin_dir() + "/gesmi";
  std::vector<std::string> arg_strings = args;
  argv.push_back(binary.data());
  for (std::string& a : arg_strings) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  EXPECT_EQ(posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), env.data()), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

TEST(OutputSafety, AnInterruptRemovesTheTemporariesAndExitsWith128PlusTheSignal) {
  for (const int sig : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(sig);
    const std::string folder = temp_folder("outputs-signal");
    const pid_t pid = spawn_gesmi({"solve", mission(), "-o", folder + "/r.h5", "--png"}, "GESMI_TEST_PAUSE_BEFORE_COMMIT=10");
    // Wait until both temporaries (the result, then the picture) are complete and the set holds them.
    const std::string temp = folder + "/r.envelope.png.tmp-" + std::to_string(pid);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(temp) && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_TRUE(fs::exists(temp));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::kill(pid, sig);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
    EXPECT_TRUE(fs::is_empty(folder)) << *names_in(folder).begin();
  }
}

TEST(OutputSafety, TemporariesOfDeadProcessesAreRemovedAndOthersKept) {
  const std::string folder = temp_folder("outputs-stale");
  // A pid that no longer runs: a child that has exited and been reaped.
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  ASSERT_GT(dead, 0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  const std::string stale = folder + "/r.h5.tmp-" + std::to_string(dead);
  const std::string alive = folder + "/r.h5.tmp-" + std::to_string(::getpid());
  std::ofstream(stale) << "half-written";
  std::ofstream(alive) << "being written by a running process";
  const CommandResult r = run_gesmi({"solve", mission(), "-o", folder + "/r.h5"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(alive));
}

TEST(OutputSafety, AFolderExportKilledBeforeItsEndLeavesNoFolderAndTheRerunWrites) {
  for (const std::string format : {"csv", "logger"}) {
    SCOPED_TRACE(format);
    const std::string parent = temp_folder("outputs-kill");
    const std::string folder = parent + "/export";
    const pid_t pid = spawn_gesmi({"export", mission(), "-o", folder, "--format", format}, "GESMI_TEST_PAUSE_BEFORE_COMMIT=10");
    // Killed by -9 (no handler runs) once its last file is complete.
    const std::string last = folder + ".tmp-" + std::to_string(pid) + "/import-command.txt.tmp-" + std::to_string(pid);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(last) && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_TRUE(fs::exists(last));
    ::kill(pid, SIGKILL);
    ASSERT_EQ(::waitpid(pid, nullptr, 0), pid);
    EXPECT_FALSE(fs::exists(folder));  // only the staging folder, under its temporary name
    EXPECT_EQ(names_in(parent).size(), 1u);
    const CommandResult skip = run_gesmi({"export", mission(), "-o", folder, "--format", format, "--skip-existing"});
    EXPECT_EQ(skip.exit_code, 0) << skip.err;
    EXPECT_TRUE(fs::exists(folder + "/import-command.txt"));
    EXPECT_EQ(names_in(parent), (std::set<std::string>{"export"}));  // the dead run's staging folder removed
  }
}

TEST(OutputSafety, AnEmptyFolderLeftWithTheTemporariesOfAKilledExportIsWrittenAgain) {
  const std::string folder = temp_folder("outputs-kill-empty");
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  ASSERT_GT(dead, 0);
  ASSERT_EQ(::waitpid(dead, nullptr, 0), dead);
  std::ofstream(folder + "/nav.csv.tmp-" + std::to_string(dead)) << "half-written";
  const CommandResult r = run_gesmi({"export", mission(), "-o", folder});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(folder + "/nav.csv.tmp-" + std::to_string(dead)));
  EXPECT_TRUE(fs::exists(folder + "/import-command.txt"));
}

}  // namespace
}  // namespace gesmi::test
