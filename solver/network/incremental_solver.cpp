#include "solver/network/incremental_solver.h"

#include <algorithm>
#include <deque>

#include "solver/network/detail/mission_propagation.h"

namespace gesmi {
namespace {

// Work items: detection j is item j, off-grid anchor a is item detections + a.
class WorkList {
 public:
  explicit WorkList(std::size_t items) : queued_(items, 0) {}
  void push(std::size_t item) {
    if (queued_[item]) return;
    queued_[item] = 1;
    queue_.push_back(item);
  }
  bool empty() const { return queue_.empty(); }
  std::size_t pop() {
    const std::size_t item = queue_.front();
    queue_.pop_front();
    queued_[item] = 0;
    return item;
  }

 private:
  std::vector<char> queued_;
  std::deque<std::size_t> queue_;
};

}  // namespace

std::vector<std::size_t> carry_candidates(const MissionNetwork& net, TubeDomains& d,
                                          std::span<const std::uint64_t> previous_by_mark) {
  std::vector<std::size_t> added;
  for (std::size_t j = 0; j < net.detections.size(); ++j) {
    const std::size_t mark = net.detections[j].mark;
    if (mark < previous_by_mark.size())
      d.candidates[j] = previous_by_mark[mark] & net.detections[j].allowed;
    else
      added.push_back(j);
  }
  return added;
}

IncrementalReport propagate_from(const MissionNetwork& net, TubeDomains& d, std::span<const std::size_t> added,
                                 const SolverOptions& options) {
  IncrementalReport report;
  detail::MissionPropagation prop(net, d);
  const std::size_t n_det = net.detections.size();
  WorkList work(n_det + net.anchors.size());
  for (const std::size_t j : added) work.push(j);
  // A move below this stops a spread; far below the solver's tolerance so that the
  // result matches a cold solve to within that tolerance.
  const double stop_below = 0.01 * options.tolerance;

  // Queue every constraint sitting on samples [first, last] (except `self`).
  const auto queue_range = [&](std::size_t first, std::size_t last, std::size_t self) {
    for (std::size_t j = 0; j < n_det; ++j) {
      const std::size_t k = net.detections[j].at.k;
      if (j != self && k + 1 >= first && k <= last) work.push(j);
    }
    for (std::size_t a = 0; a < net.anchors.size(); ++a) {
      const Anchor& anchor = net.anchors[a];
      if (!anchor.at.on_grid && n_det + a != self && anchor.at.k + 1 >= first && anchor.at.k <= last) work.push(n_det + a);
    }
  };

  std::optional<Inconsistency>& failure = report.solver.inconsistency;
  std::vector<Vec3I> mines_before(d.mines.size());  // reused: no allocation per item
  while (!work.empty()) {
    const std::size_t item = work.pop();
    ++report.work_items;
    const bool is_detection = item < n_det;
    const TimeLocation& at = is_detection ? net.detections[item].at : net.anchors[item - n_det].at;
    const Vec3I q_before = at.position(d);
    std::copy(d.mines.begin(), d.mines.end(), mines_before.begin());
    double move = 0.0;
    const bool ok = is_detection ? prop.detection(item, move, failure) : prop.anchor(net.anchors[item - n_det], move, failure);
    if (!ok) return report;
    report.solver.last_move = std::max(report.solver.last_move, move);
    if (detail::largest_move(q_before, at.position(d)) > stop_below) {
      std::size_t first = at.k, last = at.k;
      for (const std::size_t k : {at.k, at.on_grid ? at.k : at.k + 1}) {
        std::size_t f = k, l = k;
        if (!prop.spread(k, stop_below, f, l, failure)) return report;
        first = std::min(first, f);
        last = std::max(last, l);
      }
      report.samples_touched += last - first + 1;
      queue_range(first, last, item);
    }
    for (std::size_t i = 0; i < d.mines.size(); ++i) {
      if (detail::largest_move(mines_before[i], d.mines[i]) <= stop_below) continue;
      for (std::size_t j = 0; j < n_det; ++j)
        if (j != item && (d.candidates[j] >> i & 1)) work.push(j);
    }
  }
  report.solver.converged = true;
  report.solver.sweeps = 0;
  return report;
}

}  // namespace gesmi
