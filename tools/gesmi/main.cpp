// gesmi: guaranteed estimation of seamarks with intervals. Dispatches to subcommands.

#include <malloc.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "io/format_error.h"
#include "io/files/provenance.h"
#include "io/io_version.h"
#include "io/text/message_text.h"
#include "tools/gesmi/command.h"

namespace gesmi::cli {

std::vector<Command>& registry() {
  static std::vector<Command> all;
  return all;
}
bool register_command(const Command& command) {
  registry().push_back(command);
  return true;
}
const std::vector<Command>& commands() { return registry(); }

namespace {

void print_help() {
  std::printf("gesmi - guaranteed estimation of seamarks with intervals\n\nusage: gesmi <command> [options]\n\ncommands:\n");
  std::vector<Command> sorted = commands();
  std::sort(sorted.begin(), sorted.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  for (const Command& c : sorted)
    std::printf("  %-12.*s %.*s\n", static_cast<int>(c.name.size()), c.name.data(), static_cast<int>(c.summary.size()),
                c.summary.data());
  std::printf("\n'gesmi <command> --help' describes a command; 'gesmi --version' prints the version. Exit codes: 0 ok, "
              "2 bad input, 3 inconsistent data.\n");
}

// A solve frees and allocates arrays of many MiB all along. glibc by default maps each
// block of 128 kB or more on its own and unmaps it when freed, so that its pages are
// faulted in again at the next allocation; here blocks up to 32 MiB come from the heap,
// which is never trimmed, with one arena for every thread (mallopt(3)).
void keep_freed_memory_for_reuse() {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, -1);
  mallopt(M_ARENA_MAX, 1);
}

// A file size limit (ulimit -f) makes the kernel kill a writer past it with SIGXFSZ,
// silently and leaving its temporary file. Ignored, the write fails with EFBIG instead,
// which every writer reports and cleans up after as it does a full disk.
void fail_writes_past_the_file_size_limit() { std::signal(SIGXFSZ, SIG_IGN); }

// Every message leaves through here: one line whatever it holds (control characters
// and bytes that are not UTF-8 from paths or input are escaped; io/text/message_text.h).
void report(const std::string& who, const std::string& message) {
  std::fprintf(stderr, "%s: %s\n", who.c_str(), gesmi::io::one_line(message).c_str());
}

}  // namespace
}  // namespace gesmi::cli

int main(int argc, char** argv) {
  using namespace gesmi::cli;
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help();
    return args.empty() ? kExitBadInput : kExitOk;
  }
  if (args[0] == "--version" || args[0] == "-V") {
    std::printf("gesmi %.*s\n", static_cast<int>(gesmi::io::version().size()), gesmi::io::version().data());
    return kExitOk;
  }
  const auto& all = commands();
  const auto found = std::find_if(all.begin(), all.end(), [&](const Command& c) { return c.name == args[0]; });
  if (found == all.end()) {
    report("gesmi", "unknown command " + gesmi::io::quoted_input(args[0]) + "; 'gesmi --help' lists the commands");
    return kExitBadInput;
  }
  const std::string who = "gesmi " + args[0];
  keep_freed_memory_for_reuse();
  fail_writes_past_the_file_size_limit();
  gesmi::io::set_command_line(args);  // recorded in every file this run writes
  try {
    return found->run(std::span<const std::string>(args).subspan(1));
  } catch (const UsageError& e) {
    report(who, e.what());
    return kExitBadInput;
  } catch (const gesmi::io::FormatError& e) {
    report(who, e.what());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    report(who, "out of memory");
    return kExitInternal;
  } catch (const std::exception& e) {
    report(who, std::string("internal error: ") + e.what() + " (please report it)");
    return kExitInternal;
  }
}
