#include "solver/network/waterfall/look_again.h"

#include <algorithm>

namespace gesmi {

std::vector<LookAgainWindow> look_again_windows(const Waterfall& w, std::span<const double> time,
                                                const MissionNetwork& network, const TubeDomains& domains) {
  std::vector<double> mark_time;
  for (const Detection& det : network.detections) mark_time.push_back(det.time);
  return look_again_windows(w, time, mark_time, domains.candidates);
}

std::vector<LookAgainWindow> look_again_windows(const Waterfall& w, std::span<const double> time,
                                                std::span<const double> mark_time,
                                                std::span<const std::uint64_t> mark_candidates) {
  std::vector<LookAgainWindow> windows;
  for (std::size_t i = 0; i < w.mines; ++i) {
    const auto explained = [&](double t0, double t1) {
      for (std::size_t j = 0; j < mark_time.size(); ++j)
        if ((mark_candidates[j] >> i & 1) && mark_time[j] >= t0 && mark_time[j] <= t1) return true;
      return false;
    };
    // The steps where mine i can appear, in order, with their cells.
    std::vector<std::size_t> cells;
    for (std::size_t c = 0; c < w.cells(); ++c)
      if (static_cast<std::size_t>(w.mine[c]) == i) cells.push_back(c);
    const auto step_of = [&](std::size_t n) { return static_cast<std::size_t>(w.step[cells[n]]); };
    for (std::size_t n = 0; n < cells.size(); ++n) {
      LookAgainWindow win;
      win.mine = static_cast<int>(i);
      win.k_start = step_of(n);
      win.range_lo = w.lower[cells[n]];
      win.range_hi = w.upper[cells[n]];
      // Extend over feasible steps, bridging gaps shorter than kMaxGap seconds (one
      // look at the record covers them): the next feasible step joins when the last
      // step before it is within kMaxGap of the window's current end.
      constexpr double kMaxGap = 1.0;
      while (n + 1 < cells.size()) {
        const std::size_t k = step_of(n), next = step_of(n + 1);
        if (next != k + 1 && !(time[next - 1] - time[k] <= kMaxGap)) break;
        ++n;
        win.range_lo = std::min(win.range_lo, w.lower[cells[n]]);
        win.range_hi = std::max(win.range_hi, w.upper[cells[n]]);
      }
      win.k_end = step_of(n);
      win.t_start = time[win.k_start];
      win.t_end = time[win.k_end];
      // A detection between two samples at the window's edges still belongs to it.
      const double t0 = win.k_start > 0 ? time[win.k_start - 1] : win.t_start;
      const double t1 = win.k_end + 1 < w.steps ? time[win.k_end + 1] : win.t_end;
      if (!explained(t0, t1)) windows.push_back(win);
    }
  }
  std::stable_sort(windows.begin(), windows.end(), [](const LookAgainWindow& a, const LookAgainWindow& b) {
    const double da = a.t_end - a.t_start, db = b.t_end - b.t_start;
    if (da != db) return da < db;
    if (a.mine != b.mine) return a.mine < b.mine;
    return a.t_start < b.t_start;
  });
  return windows;
}

}  // namespace gesmi
