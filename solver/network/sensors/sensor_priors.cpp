#include "solver/network/sensors/sensor_priors.h"

#include <algorithm>

#include "solver/interval/rounding.h"
#include "solver/network/sensors/sensor_boxes.h"
#include "solver/network/sensors/sensor_kernel.h"
#include "solver/network/step_chunks.h"

namespace gesmi {

SensorPriors frameless_sensor_priors(const Mission& mission, const SensorModel& model, const StepRegimes& regimes) {
  const FrameMargins none{};
  const SensorBoxes boxes(mission, model, none, &regimes);
  const std::size_t n = mission.size();
  SensorPriors priors;
  priors.depth.resize(n);
  const std::size_t steps = n > 0 ? n - 1 : 0;
  priors.dx.resize(steps);
  priors.dy.resize(steps);
  priors.dz.resize(steps);
  priors.turn_north.resize(steps);
  priors.turn_east.resize(steps);
  depth_boxes(mission, model, priors.depth.data());
  if (n == 0) return priors;
  // Steps in chunks, one per core; each chunk keeps its own apart hulls, joined in step
  // order afterwards.
  const std::size_t chunks = step_chunk_count(steps);
  std::vector<std::vector<std::pair<std::size_t, Vec3I>>> apart(chunks);
  for_step_chunks(steps, chunks, [&](std::size_t chunk, std::size_t first, std::size_t last) {
    if (first == last) return;
    const auto scalar_step = [&](std::size_t k) {
      SensorBoxes::StepTurn turn;
      const Vec3I inc = boxes.step_increment(boxes.sample(k), boxes.sample(k + 1), k, &turn);
      priors.dx[k] = inc[0];
      priors.dy[k] = inc[1];
      priors.dz[k] = inc[2];
      priors.turn_north[k] = float_up(turn.north);
      priors.turn_east[k] = float_up(turn.east);
      if (turn.apart_hull) apart[chunk].emplace_back(k, *turn.apart_hull);
    };
    if (model.step_model == StepModel::rate_hull) {
      for (std::size_t k = first; k < last; ++k) scalar_step(k);
      return;
    }
    // The kernel takes nearly every step; SensorBoxes the few it leaves (sensor_kernel.h).
    const StepIncrementArrays out{priors.dx.data(), priors.dy.data(), priors.dz.data(), priors.turn_north.data(),
                                  priors.turn_east.data()};
    for (const std::size_t k : kernel_step_increments(mission, model, first, last, out, regimes)) scalar_step(k);
  });
  for (const auto& hulls : apart) priors.apart_hulls.insert(priors.apart_hulls.end(), hulls.begin(), hulls.end());
  return priors;
}

namespace {

// Calls use(k, dx, dy, dz) with each step's increments under `frame`.
template <class Use>
void framed_increments(const SensorPriors& priors, const FrameMargins& frame, Use use) {
  // A step turns by the larger heading margin of its two samples and scales by the
  // larger scale margin; its north and east increments then widen by these amounts.
  auto apart = priors.apart_hulls.begin();
  for (std::size_t k = 0; k < priors.dx.size(); ++k) {
    const double m = std::max(frame.heading.at(k), frame.heading.at(k + 1));
    const double s = std::max(frame.scale.at(k), frame.scale.at(k + 1));
    Interval dx = priors.dx[k], dy = priors.dy[k], dz = priors.dz.empty() ? Interval::entire() : priors.dz[k];
    double north = 0.0, east = 0.0;
    const bool widened = m != 0.0 || s != 0.0;
    if (widened) {
      north = frame_widening(m, s, priors.turn_east[k], priors.turn_north[k]);
      east = frame_widening(m, s, priors.turn_north[k], priors.turn_east[k]);
      dx = dx.inflated(north);
      dy = dy.inflated(east);
    }
    if (apart != priors.apart_hulls.end() && apart->first == k) {
      // Both boxes widen alike (the trapezoid above); where they still do not meet, the
      // step is empty and the solver reports it.
      const Vec3I& hull = apart->second;
      dx = intersect(dx, widened ? hull[0].inflated(north) : hull[0]);
      dy = intersect(dy, widened ? hull[1].inflated(east) : hull[1]);
      dz = intersect(dz, hull[2]);
      ++apart;
    }
    use(k, dx, dy, dz);
  }
}

// The domains of the framed increments, with the given depth boxes and vertical
// increments (those of the priors, copied or moved), intersected with the apart hulls'.
TubeDomains framed_domains(const SensorPriors& priors, const FrameMargins& frame, std::vector<Interval> depth,
                           std::vector<Interval> dz) {
  TubeDomains d;
  d.px.assign(depth.size(), Interval::entire());
  d.py.assign(depth.size(), Interval::entire());
  d.pz = std::move(depth);
  d.dz = std::move(dz);
  d.dx.resize(priors.dx.size());
  d.dy.resize(priors.dx.size());
  framed_increments(priors, frame, [&](std::size_t k, const Interval& dx, const Interval& dy, const Interval& framed_dz) {
    d.dx[k] = dx;
    d.dy[k] = dy;
    d.dz[k] = intersect(d.dz[k], framed_dz);  // (the priors' own dz, or the whole line once moved out)
  });
  return d;
}

}  // namespace

TubeDomains sensor_domains_in(const SensorPriors& priors, const FrameMargins& frame) {
  return framed_domains(priors, frame, priors.depth, priors.dz);
}

TubeDomains take_sensor_domains(SensorPriors& priors, const FrameMargins& frame) {
  std::vector<Interval> depth = std::move(priors.depth), dz = std::move(priors.dz);
  priors.depth = {};
  priors.dz = {};
  return framed_domains(priors, frame, std::move(depth), std::move(dz));
}

void narrow_to_frame(TubeDomains& d, const SensorPriors& priors, const FrameMargins& frame) {
  framed_increments(priors, frame, [&](std::size_t k, const Interval& dx, const Interval& dy, const Interval& dz) {
    d.dx[k] = intersect(d.dx[k], dx);
    d.dy[k] = intersect(d.dy[k], dy);
    d.dz[k] = intersect(d.dz[k], dz);
  });
}

}  // namespace gesmi
