#pragma once
// A one-line progress display on stderr over a whole command, shown only when stderr
// is a terminal (quiet in pipes, logs and tests) and only once the command has run for
// 0.3 s (a quick command draws nothing). A background thread redraws it every 100 ms
// with the elapsed time, so a long phase without updates (simulating 10^7 samples,
// reading a large log) still shows that the command is alive.

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace gesmi::cli {

class Progress {
 public:
  /// `quiet` (a command's --quiet) keeps it off on a terminal too.
  explicit Progress(std::string label, bool quiet = false);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// fraction in [0, 1] (or < 0 when unknown) and a short status text naming the phase.
  void update(double fraction, const std::string& status);
  /// Stops redrawing and clears the line.
  void finish();
  bool enabled() const { return enabled_; }

 private:
  void redraw_until_finished();
  void draw();  // with mutex_ held

  std::string label_;
  bool enabled_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool finished_ = false, drawn_ = false;
  double fraction_ = -1.0;
  std::string status_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::thread redrawer_;
};

}  // namespace gesmi::cli
