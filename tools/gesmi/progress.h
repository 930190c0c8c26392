#pragma once
// A one-line progress display on stderr, shown only when stderr is a terminal
// (quiet in pipes, logs and tests) and only once the command has run for 0.3 s (a
// quick command draws nothing). Redrawn at most every 50 ms.

#include <chrono>
#include <string>

namespace gesmi::cli {

class Progress {
 public:
  explicit Progress(std::string label);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// fraction in [0, 1] (or < 0 when unknown) and a short status text.
  void update(double fraction, const std::string& status);
  /// Clears the line.
  void finish();
  bool enabled() const { return enabled_; }

 private:
  std::string label_;
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace gesmi::cli
