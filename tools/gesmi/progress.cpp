#include "tools/gesmi/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace gesmi::cli {

Progress::Progress(std::string label) : label_(std::move(label)), enabled_(::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() { finish(); }

void Progress::update(double fraction, const std::string& status) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - started_ < std::chrono::milliseconds(300)) return;
  if (drawn_ && now - last_ < std::chrono::milliseconds(50) && fraction < 1.0) return;
  last_ = now;
  constexpr int kWidth = 30;
  std::string bar;
  if (fraction >= 0.0) {
    const int filled = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * kWidth + 0.5);
    bar = "[" + std::string(static_cast<std::size_t>(filled), '#') + std::string(static_cast<std::size_t>(kWidth - filled), ' ') + "] ";
  }
  std::fprintf(stderr, "\r\033[K%s %s%s", label_.c_str(), bar.c_str(), status.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (!enabled_ || !drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

}  // namespace gesmi::cli
