#include "solver/network/waterfall.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include "solver/mission/frame_scale.h"
#include "solver/network/frame_margins.h"
#include "solver/network/sensor_boxes.h"
#include "solver/network/sonar_ranges.h"
#include "solver/network/step_chunks.h"
#include "solver/network/waterfall_kernel.h"

namespace gesmi {
namespace {

bool same(const Interval& a, const Interval& b) { return a.lo() == b.lo() && a.hi() == b.hi(); }

}  // namespace

WaterfallBefore waterfall_before(const Waterfall& earlier, const TubeDomains& then, const TubeDomains& now) {
  WaterfallBefore before{earlier, {}, {}};
  if (then.size() != now.size() || then.mines.size() != now.mines.size()) return before;
  before.mine_kept.resize(now.mines.size());
  for (std::size_t i = 0; i < now.mines.size(); ++i)
    before.mine_kept[i] = same(now.mines[i][0], then.mines[i][0]) && same(now.mines[i][1], then.mines[i][1]) &&
                          same(now.mines[i][2], then.mines[i][2]);
  const std::size_t steps = now.size();
  before.position_kept.resize(steps);
  for_step_chunks(steps, step_chunk_count(steps), [&](std::size_t, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k)
      before.position_kept[k] = same(now.px[k], then.px[k]) && same(now.py[k], then.py[k]) && same(now.pz[k], then.pz[k]);
  });
  return before;
}

void Waterfall::append(const Waterfall& later) {
  step.insert(step.end(), later.step.begin(), later.step.end());
  mine.insert(mine.end(), later.mine.begin(), later.mine.end());
  lower.insert(lower.end(), later.lower.begin(), later.lower.end());
  upper.insert(upper.end(), later.upper.begin(), later.upper.end());
}

std::size_t Waterfall::first_cell_at(std::size_t k) const {
  const auto it = std::lower_bound(step.begin(), step.end(), static_cast<std::int64_t>(k),
                                   [](std::int32_t s, std::int64_t wanted) { return s < wanted; });
  return static_cast<std::size_t>(it - step.begin());
}

std::optional<std::size_t> Waterfall::cell(std::size_t k, std::size_t i) const {
  for (std::size_t c = first_cell_at(k); c < cells() && static_cast<std::size_t>(step[c]) == k; ++c)
    if (static_cast<std::size_t>(mine[c]) == i) return c;
  return std::nullopt;
}

double Waterfall::lo(std::size_t k, std::size_t i) const {
  const auto c = cell(k, i);
  return c ? lower[*c] : std::numeric_limits<double>::quiet_NaN();
}

double Waterfall::hi(std::size_t k, std::size_t i) const {
  const auto c = cell(k, i);
  return c ? upper[*c] : std::numeric_limits<double>::quiet_NaN();
}

Waterfall compute_waterfall(const Mission& mission, const SensorModel& model, const TubeDomains& domains,
                            const WaterfallBefore* before, std::optional<double> max_speed,
                            const std::function<void(double)>& on_progress) {
  // The tube holds the truth, so the frame's margins over it hold too. They are needed
  // only at the steps some mine is in reach of, found with the zone's margins first (no
  // sample's exceed them, so no such step is missed), then narrowed there (in place:
  // `boxes` reads them).
  FrameMarginValues margins = zone_margin_values(mission, domains.size());
  const SensorBoxes boxes(mission, model, margins.view(mission));
  const std::size_t steps = domains.size(), mines = domains.mines.size();
  const SonarGeometry geometry{model.along_track_tolerance, model.mine_depth_band, model.sonar_max_range,
                               model.sonar_side};
  // The mines whose box has not changed since `before`, if any.
  std::vector<unsigned char> mine_kept(mines, 0);
  if (before && before->waterfall.steps == steps && before->waterfall.mines == mines &&
      before->position_kept.size() == steps && before->mine_kept.size() == mines)
    mine_kept = before->mine_kept;
  // The step's position boxes and its neighbours' are those of `before`.
  const auto same_positions = [&](std::size_t k) {
    for (std::size_t j = k == 0 ? 0 : k - 1; j <= std::min(k + 1, steps - 1); ++j)
      if (!before->position_kept[j]) return false;
    return true;
  };
  const bool any_kept = std::find(mine_kept.begin(), mine_kept.end(), 1) != mine_kept.end();
  std::vector<KernelMine> kernel_mines(mines);
  std::vector<char> mine_in_kernel(mines);
  for (std::size_t i = 0; i < mines; ++i) {
    mine_in_kernel[i] = kernel_takes(domains.mines[i]);
    for (int a = 0; a < 3; ++a) {
      kernel_mines[i].lo[a] = domains.mines[i][a].lo();
      kernel_mines[i].hi[a] = domains.mines[i][a].hi();
    }
  }
  // The frame's slack at step k, and the sonar's reach with it: the slack moves each axis
  // of the offset, so the distance by at most sqrt(3) < 2 times it.
  const auto slack_at = [&](std::size_t k) { return sonar_frame_slack(boxes.frame_scale(k), model.sonar_max_range); };
  const auto reach_with = [&](double slack) { return add_up(model.sonar_max_range, 2.0 * slack); };
  // Whether a mine's cell at a step is computed: not kept from `before`, and in reach.
  const auto near = [&](std::size_t i, bool kept_step, const Vec3I& p, double reach) {
    return !(kept_step && mine_kept[i]) && !boxes_beyond(p, domains.mines[i], reach);
  };
  // Per step: its cells kept from `before` (its positions unchanged), and some mine in
  // reach under the zone's margins.
  std::vector<unsigned char> kept_steps(steps, 0), in_reach(steps, 0);
  const std::size_t chunks = step_chunk_count(steps);
  for_step_chunks(steps, chunks, [&](std::size_t, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      kept_steps[k] = any_kept && same_positions(k);
      const Vec3I p = domains.position(k);
      const double reach = reach_with(slack_at(k));
      for (std::size_t i = 0; i < mines && !in_reach[k]; ++i) in_reach[k] = near(i, kept_steps[k], p, reach);
    }
  });
  if (has_frame_margins(mission))
    narrow_margins_over(margins, mission, domains, max_speed ? *max_speed : speed_bound(mission), in_reach);
  // The portable plane at step k, for what the kernel does not take.
  const auto plane_at = [&](std::size_t k) {
    SonarPlane plane;
    plane.attitude = make_attitude(boxes.roll(k), boxes.pitch(k), boxes.heading(k));
    plane.altitude = boxes.altitude(k);
    plane.along_tolerance = model.along_track_tolerance;
    plane.depth_band = model.mine_depth_band;
    plane.frame_slack = sonar_frame_slack(boxes.frame_scale(k), model.sonar_max_range);
    return plane;
  };
  // Steps [first, last) of each chunk into their own part, joined in step order.
  std::vector<Waterfall> parts(chunks);
  const auto rows = [&](std::size_t chunk, std::size_t first, std::size_t last) {
    Waterfall& part = parts[chunk];
    // One block of steps at a time: their near pairs and boxes gathered in the caller's
    // rounding mode, the kernel over all pairs at once, what it leaves on SonarPlane.
    constexpr std::size_t kBlock = 512;
    std::vector<Interval> cells;  // the block's cells by step, then mine (empty: none)
    std::vector<KernelStep> kernel_steps;
    std::vector<std::size_t> kernel_step_at;  // each kernel step's offset in the block
    std::vector<KernelPair> pairs;
    std::vector<KernelCell> kernel_cells;
    std::vector<std::pair<std::size_t, std::size_t>> portable;  // (step, mine)
    std::vector<std::size_t> near_mines;
    std::size_t earlier = any_kept ? before->waterfall.first_cell_at(first) : 0;
    for (std::size_t block = first; block < last; block += kBlock) {
      // The first chunk runs on the calling thread: it reports for all (they keep pace).
      if (chunk == 0 && on_progress && (block - first) % 8192 == 0)
        on_progress(static_cast<double>(block - first) / static_cast<double>(last - first));
      const std::size_t block_end = std::min(last, block + kBlock);
      cells.assign((block_end - block) * mines, Interval::empty());
      kernel_steps.clear();
      kernel_step_at.clear();
      pairs.clear();
      portable.clear();
      for (std::size_t k = block; k < block_end; ++k) {
        const bool kept_step = kept_steps[k];
        Interval* row = cells.data() + (k - block) * mines;  // no cells without mines
        if (kept_step) {
          const Waterfall& w = before->waterfall;
          while (earlier < w.cells() && static_cast<std::size_t>(w.step[earlier]) < k) ++earlier;
          for (std::size_t c = earlier; c < w.cells() && static_cast<std::size_t>(w.step[c]) == k; ++c)
            if (mine_kept[static_cast<std::size_t>(w.mine[c])])
              row[static_cast<std::size_t>(w.mine[c])] = Interval(w.lower[c], w.upper[c]);
        }
        if (!in_reach[k]) continue;
        // Again with the step's own margins, narrowed above.
        const Vec3I p = domains.position(k);
        const double slack = slack_at(k), reach = reach_with(slack);
        near_mines.clear();
        for (std::size_t i = 0; i < mines; ++i)
          if (near(i, kept_step, p, reach)) near_mines.push_back(i);
        if (near_mines.empty()) continue;  // no attitude to build where no mine is in reach
        KernelStep step;
        const bool taken = prepare_kernel_step(p, boxes.roll(k), boxes.pitch(k), boxes.heading(k), boxes.altitude(k),
                                               slack, step);
        if (taken) {
          kernel_steps.push_back(step);
          kernel_step_at.push_back(k - block);
        }
        for (const std::size_t i : near_mines) {
          if (taken && mine_in_kernel[i])
            pairs.push_back({static_cast<std::uint32_t>(kernel_steps.size() - 1), static_cast<std::uint32_t>(i)});
          else
            portable.emplace_back(k, i);
        }
      }
      kernel_cells.resize(pairs.size());
      kernel_sonar_ranges(geometry, kernel_steps, kernel_mines, pairs, kernel_cells);
      for (std::size_t j = 0; j < pairs.size(); ++j) {
        const std::size_t offset = kernel_step_at[pairs[j].step], i = pairs[j].mine;
        if (kernel_cells[j].verdict == KernelVerdict::ranges)
          cells[offset * mines + i] = Interval(kernel_cells[j].lo, kernel_cells[j].hi);
        else if (kernel_cells[j].verdict == KernelVerdict::undecided)
          portable.emplace_back(block + offset, i);
      }
      std::size_t planned = steps;  // the step whose portable plane is built
      SonarPlane plane;
      for (const auto& [k, i] : portable) {
        if (k != planned) {
          plane = plane_at(k);
          planned = k;
        }
        cells[(k - block) * mines + i] =
            sonar_ranges(plane, domains.position(k), domains.mines[i], model.sonar_side, model.sonar_max_range);
      }
      for (std::size_t k = block; k < block_end; ++k)
        for (std::size_t i = 0; i < mines; ++i) {
          const Interval& cell = cells[(k - block) * mines + i];
          if (!cell.is_empty()) part.add(k, i, cell.lo(), cell.hi());
        }
    }
  };
  for_step_chunks(steps, chunks, rows);
  Waterfall w;
  w.steps = steps;
  w.mines = mines;
  for (const Waterfall& part : parts) w.append(part);
  return w;
}

}  // namespace gesmi
