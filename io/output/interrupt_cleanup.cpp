#include "io/output/interrupt_cleanup.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace gesmi::io {
namespace {

constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;

struct Slot {
  std::atomic<bool> used{false};
  bool folder = false;
  char path[kPathBytes] = {};
};
Slot slots[kSlots];

extern "C" void remove_and_exit(int signal_number) {
  // The files first: a folder is only removed once empty.
  for (Slot& s : slots)
    if (s.used.load(std::memory_order_acquire) && !s.folder) ::unlink(s.path);
  for (int i = kSlots - 1; i >= 0; --i)
    if (slots[i].used.load(std::memory_order_acquire) && slots[i].folder) ::rmdir(slots[i].path);
  ::_exit(128 + signal_number);
}

void install_handlers() {
  static const bool installed = [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      // A signal the caller chose to ignore (nohup, a shell's background job) stays ignored.
      if (::sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
      struct sigaction action {};
      action.sa_handler = remove_and_exit;
      sigemptyset(&action.sa_mask);
      for (const int blocked : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, blocked);
      ::sigaction(sig, &action, nullptr);
    }
    return true;
  }();
  (void)installed;
}

}  // namespace

int track_temporary(const std::string& path, bool folder) {
  install_handlers();
  if (path.size() >= kPathBytes) return -1;
  for (int i = 0; i < kSlots; ++i) {
    Slot& s = slots[i];
    if (s.used.load(std::memory_order_acquire)) continue;
    std::memcpy(s.path, path.c_str(), path.size() + 1);
    s.folder = folder;
    s.used.store(true, std::memory_order_release);
    return i;
  }
  return -1;
}

void untrack_temporary(int slot) {
  if (slot >= 0 && slot < kSlots) slots[slot].used.store(false, std::memory_order_release);
}

}  // namespace gesmi::io
