#include "solver/ctc/propagation.h"

#include <cmath>
#include <string>

namespace gesmi {

std::string PropagationOptions::validate() const {
  if (!(relative_tolerance >= 0.0) || !std::isfinite(relative_tolerance)) return "relative tolerance must be a finite number >= 0";
  if (max_sweeps < 1) return "the sweep limit must be at least 1";
  return {};
}

bool shrank_significantly(const Box& before, const Box& after, double relative_tolerance) {
  for (std::size_t i = 0; i < before.size(); ++i) {
    const Interval& b = before[i];
    const Interval& a = after[i];
    if (a.is_empty()) return !b.is_empty();
    if (a == b) continue;
    const double wb = b.width(), wa = a.width();
    if (!std::isfinite(wb)) return true;  // an unbounded domain became smaller
    if (wb - wa > relative_tolerance * wb) return true;
  }
  return false;
}

PropagationReport propagate(const std::vector<CtcAny>& contractors, Box& box, const PropagationOptions& options) {
  PropagationReport report;
  Box before(box.size());
  while (report.sweeps < options.max_sweeps) {
    before = box;
    for (const CtcAny& c : contractors) {
      c.contract(box);
      if (is_empty(box)) {
        normalize_empty(box);
        report.empty = true;
        ++report.sweeps;
        report.converged = true;
        return report;
      }
    }
    ++report.sweeps;
    if (!shrank_significantly(before, box, options.relative_tolerance)) {
      report.converged = true;
      return report;
    }
  }
  return report;
}

}  // namespace gesmi
