#include "solver/network/sensors/step_regimes.h"

#include <algorithm>
#include <cmath>

#include "solver/interval/rounding.h"
#include "solver/network/sensors/readings_check.h"
#include "solver/network/sensors/sensor_boxes.h"

namespace gesmi {
namespace {

constexpr int kRounds = 3;  // of depth chain and check, until the fall-backs stop changing

// The step k holds a GPS fix (fixes are taken at the surface).
void flag_fixes(const Mission& m, std::vector<std::uint8_t>& flags) {
  for (const double t : m.gps_time) {
    const auto after = std::upper_bound(m.time.begin(), m.time.end(), t);
    if (after == m.time.begin()) continue;
    if (after == m.time.end()) {
      if (t == m.time.back() && m.size() > 1) flags[m.size() - 2] |= StepRegimes::kSurface;
      continue;
    }
    const std::size_t k = static_cast<std::size_t>(after - m.time.begin()) - 1;
    flags[k] |= StepRegimes::kSurface;
    if (t == m.time[k] && k > 0) flags[k - 1] |= StepRegimes::kSurface;
  }
}

// Surface flags from the lowest depths `lo` the robot can be at each sample: a step is
// in the surface regime when the shallowest point between its samples, moving at no
// more than the surface speed, reaches the layer; or when it holds a fix.
std::vector<std::uint8_t> surface_flags(const Mission& m, const SensorModel& model, const std::vector<double>& lo) {
  std::vector<std::uint8_t> flags(m.size() - 1, 0);
  const double v = model.surface_max_speed;
  for (std::size_t k = 0; k < flags.size(); ++k) {
    const double a = lo[k], b = lo[k + 1], reach = v * (m.time[k + 1] - m.time[k]);
    const double shallowest = 0.5 * (a + b - reach);
    const double margin = outward(std::fabs(a) + std::fabs(b) + reach);
    if (shallowest - margin <= model.surface_layer_depth) flags[k] |= StepRegimes::kSurface;
  }
  flag_fixes(m, flags);
  return flags;
}

// The barometer's boxes (SensorBoxes::depth's, from the kernel).
IntervalArray depth_boxes_of(const Mission& m, const SensorModel& model) {
  std::vector<Interval> boxes(m.size());
  depth_boxes(m, model, boxes.data());
  IntervalArray out(m.size());
  for (std::size_t k = 0; k < m.size(); ++k) out.set(k, boxes[k]);
  return out;
}

// The lowest depth at each sample the barometer's boxes and the vertical increments
// allow together: one forward and one backward pass over the chain (its exact
// projection). The barometer's boxes alone where they do not meet (the solve reports
// that inconsistency).
std::vector<double> depth_chain_lows(const Mission& m, const IntervalArray& dz, const IntervalArray& boxes) {
  const std::size_t n = m.size();
  IntervalArray z(n);  // forward, then (in place) the chain's projection
  double lo = boxes.lo[0], hi = boxes.hi[0];
  z.lo[0] = lo;
  z.hi[0] = hi;
  for (std::size_t k = 1; k < n; ++k) {
    const double step_lo = lo + dz.lo[k - 1], step_hi = hi + dz.hi[k - 1];
    const double margin = outward(std::fabs(step_lo) + std::fabs(step_hi));
    lo = std::max(boxes.lo[k], step_lo - margin);
    hi = std::min(boxes.hi[k], step_hi + margin);
    if (!(lo <= hi)) return boxes.lo;
    z.lo[k] = lo;
    z.hi[k] = hi;
  }
  for (std::size_t k = n - 1; k-- > 0;) {
    const double step_lo = lo - dz.hi[k], step_hi = hi - dz.lo[k];
    const double margin = outward(std::fabs(step_lo) + std::fabs(step_hi));
    lo = std::max(z.lo[k], step_lo - margin);
    hi = std::min(z.hi[k], step_hi + margin);
    if (!(lo <= hi)) return boxes.lo;
    z.lo[k] = lo;
  }
  return std::move(z.lo);
}

StepRegimeReport report_of(const Mission& m, const StepRegimes& regimes, StepRegimeReport checked) {
  for (std::size_t k = 0; k < regimes.steps(); ++k) {
    if (regimes.surface(k)) ++checked.surface_steps;
    if (!regimes.fallback(k)) continue;
    ++checked.fallback_steps;
    if ((k == 0 || !regimes.fallback(k - 1)) && checked.fallback_times.size() < StepRegimeReport::kShownTimes)
      checked.fallback_times.push_back(m.time[k]);
  }
  return checked;
}

}  // namespace

double StepRegimes::largest_speed(const SensorModel& model) const {
  double largest = 0.0;
  for (std::size_t k = 0; k < flags_.size(); ++k)
    if (fallback(k)) largest = std::max(largest, speed(model, k));
  return largest;
}

StepRegimes classify_steps(const Mission& mission, const SensorModel& model) {
  if (mission.size() < 2) return StepRegimes(std::vector<std::uint8_t>(mission.size() > 0 ? mission.size() - 1 : 0, 0));
  // The barometer's boxes alone give regimes that hold whatever the robot did (the
  // surface bounds are the wider ones); the depth chain under them narrows the depths,
  // hence the surface steps; the check under those finds the fall-backs, which widen the
  // chain in turn (their increments the speed box), until they stop growing.
  const IntervalArray boxes = depth_boxes_of(mission, model);
  const StepRegimes conservative(surface_flags(mission, model, boxes.lo));
  ReadingsEvidence evidence = gather_evidence(mission, model, conservative);
  std::vector<std::uint8_t> fallback(conservative.steps(), 0), flags;
  for (int round = 0; round < kRounds; ++round) {
    flags = surface_flags(mission, model, depth_chain_lows(mission, evidence.dz, boxes));
    std::vector<std::uint8_t> found(flags.size(), 0);
    flag_contradicted(evidence, model, StepRegimes(flags), found);
    bool grew = false;
    for (std::size_t k = 0; k < found.size(); ++k) {
      if (!found[k] || fallback[k]) continue;
      grew = true;
      fallback[k] = StepRegimes::kFallback;
      evidence.dz.set(k, speed_step(mission, k, conservative.speed(model, k)));
    }
    if (!grew) break;
  }
  StepRegimeReport checked;
  report_speeds(evidence, mission, model, StepRegimes(flags), checked);
  for (std::size_t k = 0; k < flags.size(); ++k) flags[k] |= fallback[k];
  StepRegimes regimes(std::move(flags));
  regimes.set_report(report_of(mission, regimes, std::move(checked)));
  return regimes;
}

}  // namespace gesmi
