#include "solver/network/waterfall/waterfall.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include "solver/mission/frame_scale.h"
#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/network/waterfall/sonar_ranges.h"
#include "solver/network/step_chunks.h"
#include "solver/network/waterfall/waterfall_kernel.h"

namespace gesmi {
namespace {

bool same(const Interval& a, const Interval& b) { return a.lo() == b.lo() && a.hi() == b.hi(); }

// The mines whose box has not changed since `before`, if any: none unless `before` is a
// waterfall of these steps and mines.
std::vector<unsigned char> kept_mines(const WaterfallBefore* before, std::size_t steps, std::size_t mines) {
  std::vector<unsigned char> mine_kept(mines, 0);
  if (before && before->waterfall.steps == steps && before->waterfall.mines == mines &&
      before->position_kept.size() == steps && before->mine_kept.size() == mines)
    mine_kept = before->mine_kept;
  return mine_kept;
}

// The buffers of one block of steps, reused from block to block.
struct BlockBuffers {
  std::vector<Interval> cells;  // the block's cells by step, then mine (empty: none)
  std::vector<KernelStep> kernel_steps;
  std::vector<std::size_t> kernel_step_at;  // each kernel step's offset in the block
  std::vector<KernelPair> pairs;
  std::vector<KernelCell> kernel_cells;
  std::vector<std::pair<std::size_t, std::size_t>> portable;  // (step, mine)
  std::vector<std::size_t> near_mines;
};

// The cells of one waterfall: which steps have a mine in reach, then the cells of any
// range of steps (several ranges at once, on their own threads).
class WaterfallCells {
 public:
  WaterfallCells(const SensorModel& model, const TubeDomains& domains, const SensorBoxes& boxes,
                 const WaterfallBefore* before)
      : model_(model), domains_(domains), boxes_(boxes), before_(before), steps_(domains.size()),
        mines_(domains.mines.size()),
        geometry_{model.along_track_tolerance, model.mine_depth_band, model.sonar_max_range, model.sonar_side},
        mine_kept_(kept_mines(before, steps_, mines_)),
        any_kept_(std::find(mine_kept_.begin(), mine_kept_.end(), 1) != mine_kept_.end()),
        kernel_mines_(mines_), mine_in_kernel_(mines_) {
    for (std::size_t i = 0; i < mines_; ++i) {
      mine_in_kernel_[i] = kernel_takes(domains.mines[i]);
      for (int a = 0; a < 3; ++a) {
        kernel_mines_[i].lo[a] = domains.mines[i][a].lo();
        kernel_mines_[i].hi[a] = domains.mines[i][a].hi();
      }
    }
  }

  // Per step: its cells kept from `before` (its positions unchanged), and some mine in
  // reach under the margins `boxes` reads now.
  void find_steps_in_reach(std::size_t chunks) {
    kept_steps_.assign(steps_, 0);
    in_reach_.assign(steps_, 0);
    for_step_chunks(steps_, chunks, [&](std::size_t, std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        kept_steps_[k] = any_kept_ && same_positions(k);
        const Vec3I p = domains_.position(k);
        const double reach = reach_with(slack_at(k));
        for (std::size_t i = 0; i < mines_ && !in_reach_[k]; ++i) in_reach_[k] = near(i, kept_steps_[k], p, reach);
      }
    });
  }
  const std::vector<unsigned char>& in_reach() const { return in_reach_; }

  // Steps [first, last) of chunk `chunk` into `part`, one block of steps at a time: their
  // near pairs and boxes gathered in the caller's rounding mode, the kernel over all
  // pairs at once, what it leaves on SonarPlane.
  void compute_rows(std::size_t chunk, std::size_t first, std::size_t last,
                    const std::function<void(double)>& on_progress, Waterfall& part) const {
    constexpr std::size_t kRowsPerBlock = 512;
    BlockBuffers buffers;
    std::size_t earlier = any_kept_ ? before_->waterfall.first_cell_at(first) : 0;
    for (std::size_t block = first; block < last; block += kRowsPerBlock) {
      // The first chunk runs on the calling thread: it reports for all (they keep pace).
      if (chunk == 0 && on_progress && (block - first) % 8192 == 0)
        on_progress(static_cast<double>(block - first) / static_cast<double>(last - first));
      const std::size_t block_end = std::min(last, block + kRowsPerBlock);
      compute_block(block, block_end, earlier, buffers);
      for (std::size_t k = block; k < block_end; ++k)
        for (std::size_t i = 0; i < mines_; ++i) {
          const Interval& cell = buffers.cells[(k - block) * mines_ + i];
          if (!cell.is_empty()) part.add(k, i, cell.lo(), cell.hi());
        }
    }
  }

 private:
  // The step's position boxes and its neighbours' are those of `before`.
  bool same_positions(std::size_t k) const {
    for (std::size_t j = k == 0 ? 0 : k - 1; j <= std::min(k + 1, steps_ - 1); ++j)
      if (!before_->position_kept[j]) return false;
    return true;
  }
  // The frame's slack at step k, and the sonar's reach with it: the slack moves each axis
  // of the offset, so the distance by at most sqrt(3) < 2 times it.
  double slack_at(std::size_t k) const { return sonar_frame_slack(boxes_.frame_scale(k), model_.sonar_max_range); }
  double reach_with(double slack) const { return add_up(model_.sonar_max_range, 2.0 * slack); }
  // Whether a mine's cell at a step is computed: not kept from `before`, and in reach.
  bool near(std::size_t i, bool kept_step, const Vec3I& p, double reach) const {
    return !(kept_step && mine_kept_[i]) && !boxes_beyond(p, domains_.mines[i], reach);
  }
  // The portable plane at step k, for what the kernel does not take.
  SonarPlane plane_at(std::size_t k) const {
    SonarPlane plane;
    plane.attitude = make_attitude(boxes_.roll(k), boxes_.pitch(k), boxes_.heading(k));
    plane.altitude = boxes_.altitude(k);
    plane.along_tolerance = model_.along_track_tolerance;
    plane.depth_band = model_.mine_depth_band;
    plane.frame_slack = sonar_frame_slack(boxes_.frame_scale(k), model_.sonar_max_range);
    return plane;
  }

  // The cells of steps [block, block_end) into buffers.cells; `earlier` follows
  // `before`'s cells.
  void compute_block(std::size_t block, std::size_t block_end, std::size_t& earlier, BlockBuffers& buffers) const {
    buffers.cells.assign((block_end - block) * mines_, Interval::empty());
    buffers.kernel_steps.clear();
    buffers.kernel_step_at.clear();
    buffers.pairs.clear();
    buffers.portable.clear();
    for (std::size_t k = block; k < block_end; ++k) {
      const bool kept_step = kept_steps_[k];
      Interval* row = buffers.cells.data() + (k - block) * mines_;  // no cells without mines
      if (kept_step) copy_kept_cells(k, earlier, row);
      if (!in_reach_[k]) continue;
      gather_near_pairs(k, block, kept_step, buffers);
    }
    compute_kernel_cells(block, buffers);
    compute_portable_cells(block, buffers);
  }

  // Step k's cells of the kept mines, from `before` (its cells from `earlier` on).
  void copy_kept_cells(std::size_t k, std::size_t& earlier, Interval* row) const {
    const Waterfall& w = before_->waterfall;
    while (earlier < w.cells() && static_cast<std::size_t>(w.step[earlier]) < k) ++earlier;
    for (std::size_t c = earlier; c < w.cells() && static_cast<std::size_t>(w.step[c]) == k; ++c)
      if (mine_kept_[static_cast<std::size_t>(w.mine[c])])
        row[static_cast<std::size_t>(w.mine[c])] = Interval(w.lower[c], w.upper[c]);
  }

  // Step k's pairs with the mines in reach: for the kernel when it takes both, portable
  // otherwise.
  void gather_near_pairs(std::size_t k, std::size_t block, bool kept_step, BlockBuffers& buffers) const {
    // Again with the step's own margins, narrowed since find_steps_in_reach().
    const Vec3I p = domains_.position(k);
    const double slack = slack_at(k), reach = reach_with(slack);
    buffers.near_mines.clear();
    for (std::size_t i = 0; i < mines_; ++i)
      if (near(i, kept_step, p, reach)) buffers.near_mines.push_back(i);
    if (buffers.near_mines.empty()) return;  // no attitude to build where no mine is in reach
    KernelStep step;
    const bool taken =
        prepare_kernel_step(p, boxes_.roll(k), boxes_.pitch(k), boxes_.heading(k), boxes_.altitude(k), slack, step);
    if (taken) {
      buffers.kernel_steps.push_back(step);
      buffers.kernel_step_at.push_back(k - block);
    }
    for (const std::size_t i : buffers.near_mines) {
      if (taken && mine_in_kernel_[i])
        buffers.pairs.push_back(
            {static_cast<std::uint32_t>(buffers.kernel_steps.size() - 1), static_cast<std::uint32_t>(i)});
      else
        buffers.portable.emplace_back(k, i);
    }
  }

  // The kernel's cells; the pairs it leaves undecided become portable.
  void compute_kernel_cells(std::size_t block, BlockBuffers& buffers) const {
    buffers.kernel_cells.resize(buffers.pairs.size());
    kernel_sonar_ranges(geometry_, buffers.kernel_steps, kernel_mines_, buffers.pairs, buffers.kernel_cells);
    for (std::size_t j = 0; j < buffers.pairs.size(); ++j) {
      const std::size_t offset = buffers.kernel_step_at[buffers.pairs[j].step], i = buffers.pairs[j].mine;
      if (buffers.kernel_cells[j].verdict == KernelVerdict::ranges)
        buffers.cells[offset * mines_ + i] = Interval(buffers.kernel_cells[j].lo, buffers.kernel_cells[j].hi);
      else if (buffers.kernel_cells[j].verdict == KernelVerdict::undecided)
        buffers.portable.emplace_back(block + offset, i);
    }
  }

  void compute_portable_cells(std::size_t block, BlockBuffers& buffers) const {
    std::size_t planned = steps_;  // the step whose portable plane is built
    SonarPlane plane;
    for (const auto& [k, i] : buffers.portable) {
      if (k != planned) {
        plane = plane_at(k);
        planned = k;
      }
      buffers.cells[(k - block) * mines_ + i] =
          sonar_ranges(plane, domains_.position(k), domains_.mines[i], model_.sonar_side, model_.sonar_max_range);
    }
  }

  const SensorModel& model_;
  const TubeDomains& domains_;
  const SensorBoxes& boxes_;
  const WaterfallBefore* before_;
  std::size_t steps_, mines_;
  SonarGeometry geometry_;
  std::vector<unsigned char> mine_kept_;  // the mines whose box has not changed since `before`
  bool any_kept_;
  std::vector<KernelMine> kernel_mines_;
  std::vector<char> mine_in_kernel_;
  std::vector<unsigned char> kept_steps_, in_reach_;  // per step (find_steps_in_reach())
};

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
  WaterfallCells waterfall_cells(model, domains, boxes, before);
  const std::size_t chunks = step_chunk_count(steps);
  waterfall_cells.find_steps_in_reach(chunks);
  if (has_frame_margins(mission))
    narrow_margins_over(margins, mission, domains, max_speed ? *max_speed : speed_bound(mission),
                        waterfall_cells.in_reach());
  // Steps [first, last) of each chunk into their own part, joined in step order.
  std::vector<Waterfall> parts(chunks);
  for_step_chunks(steps, chunks, [&](std::size_t chunk, std::size_t first, std::size_t last) {
    waterfall_cells.compute_rows(chunk, first, last, on_progress, parts[chunk]);
  });
  Waterfall w;
  w.steps = steps;
  w.mines = mines;
  for (const Waterfall& part : parts) w.append(part);
  return w;
}

}  // namespace gesmi
