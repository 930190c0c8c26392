#include "tools/gesmi/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace gesmi::cli {

namespace {
constexpr auto kDelay = std::chrono::milliseconds(300);
constexpr auto kPeriod = std::chrono::milliseconds(100);
}  // namespace

Progress::Progress(std::string label, bool quiet)
    : label_(std::move(label)), enabled_(!quiet && ::isatty(STDERR_FILENO) == 1) {
  if (enabled_) redrawer_ = std::thread([this] { redraw_until_finished(); });
}

Progress::~Progress() { finish(); }

void Progress::update(double fraction, const std::string& status) {
  if (!enabled_) return;
  const std::lock_guard lock(mutex_);
  fraction_ = fraction;
  status_ = status;
}

void Progress::redraw_until_finished() {
  std::unique_lock lock(mutex_);
  if (wake_.wait_for(lock, kDelay, [this] { return finished_; })) return;
  while (!finished_) {
    draw();
    wake_.wait_for(lock, kPeriod, [this] { return finished_; });
  }
}

void Progress::draw() {
  constexpr int kWidth = 30;
  std::string bar;
  if (fraction_ >= 0.0) {
    const int filled = static_cast<int>(std::clamp(fraction_, 0.0, 1.0) * kWidth + 0.5);
    bar = "[" + std::string(static_cast<std::size_t>(filled), '#') +
          std::string(static_cast<std::size_t>(kWidth - filled), ' ') + "] ";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  std::fprintf(stderr, "\r\033[K%s %s%s (%.1f s)", label_.c_str(), bar.c_str(), status_.c_str(), seconds);
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (!enabled_) return;
  {
    const std::lock_guard lock(mutex_);
    if (finished_) return;
    finished_ = true;
  }
  wake_.notify_all();
  if (redrawer_.joinable()) redrawer_.join();
  if (drawn_) {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  }
}

}  // namespace gesmi::cli
