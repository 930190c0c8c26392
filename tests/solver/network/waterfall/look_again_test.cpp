// A detection the operator missed lies in a listed window of its mine, at a range
// inside the window's range interval; recorded detections leave no window.

#include "solver/network/waterfall/look_again.h"

#include <gtest/gtest.h>

#include "solver/network/mission_solver.h"
#include "tests/support/tiny_mission.h"

namespace gesmi {
namespace {

TEST(LookAgain, ListsTheWindowOfAMissedDetection) {
  for (const std::size_t missed : {std::size_t{0}, std::size_t{1}}) {
    test::TinyMission t = test::make_tiny_mission(10 + missed, test::TinyErrors::uniform);
    Mission& m = t.mission;
    const double missed_time = m.mark_time[missed];
    const std::size_t k_missed = static_cast<std::size_t>(std::lround(missed_time / 0.1));
    const Vec3d q(m.truth_x[k_missed], m.truth_y[k_missed], m.truth_z[k_missed]);
    const double missed_range = (q - Vec3d(m.truth_mines[0], m.truth_mines[1], m.truth_mines[2])).norm();
    m.mark_time.erase(m.mark_time.begin() + static_cast<long>(missed));
    m.mark_mine.erase(m.mark_mine.begin() + static_cast<long>(missed));
    m.mark_range.erase(m.mark_range.begin() + static_cast<long>(missed));
    m.mark_side.erase(m.mark_side.begin() + static_cast<long>(missed));

    const MissionNetwork net = build_network(m, m.model, t.fixes);
    TubeDomains d = initial_domains(m, m.model, net);
    ASSERT_TRUE(solve(net, d).consistent());
    const Waterfall w = compute_waterfall(m, m.model, d);
    const std::vector<LookAgainWindow> windows = look_again_windows(w, m.time, net, d);
    bool found = false;
    for (const LookAgainWindow& win : windows) {
      EXPECT_LE(win.t_start, win.t_end);
      if (win.mine == 0 && win.t_start <= missed_time && missed_time <= win.t_end) {
        found = true;
        EXPECT_LE(win.range_lo, missed_range);
        EXPECT_GE(win.range_hi, missed_range);
      }
      // The recorded detection is not in a listed window.
      EXPECT_FALSE(win.t_start <= m.mark_time[0] && m.mark_time[0] <= win.t_end);
    }
    EXPECT_TRUE(found) << "missed detection " << missed;
    for (std::size_t i = 1; i < windows.size(); ++i)
      EXPECT_LE(windows[i - 1].t_end - windows[i - 1].t_start, windows[i].t_end - windows[i].t_start);
  }
}

}  // namespace
}  // namespace gesmi
