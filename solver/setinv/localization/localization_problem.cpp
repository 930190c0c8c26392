#include "solver/setinv/localization/localization_problem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "solver/setinv/localization/localization_data.h"
#include "solver/setinv/localization/bearing_contractor.h"
#include "solver/setinv/localization/range_contractor.h"
#include "solver/setinv/outliers/hypotheses.h"
#include "solver/setinv/outliers/outlier_refinement.h"
#include "solver/model/angles.h"

namespace gesmi {
namespace {

/// Remark 4's test for a x + b y <= c on the position of a box.
struct HalfPlanes {
  const std::vector<HalfPlane>& planes;
  IBool operator()(const Box& box) const {
    IBool all(true);
    for (const HalfPlane& h : planes) all = all && leq(Interval(h.a) * box[0] + Interval(h.b) * box[1], Interval(h.c));
    return all;
  }
};

LocalizationData make_data(const LocalizationProblem& p) {
  return LocalizationData(RangeData(p.map.walls, p.range_sensors, p.ranges),
                          BearingData(p.map.walls, p.map.landmarks, p.bearing_sensors, p.bearings));
}

SiviaOptions sivia_options_of(const LocalizationProblem& problem) {
  SiviaOptions o;
  o.epsilon = problem.epsilon;
  o.scale = {1.0, 1.0, problem.theta_scale};
  o.periodic_dimension = 2;
  o.period = kTwoPi;
  o.max_boxes = problem.max_boxes;
  o.max_seconds = problem.max_seconds;
  return o;
}

/// SIVIA(q) with the contractors (Remark 5 of seed 004), each valid for S_q.
SiviaResult solve_fixed(const LocalizationProblem& problem, LocalizationData& data, int q, const SiviaOptions& options) {
  const HalfPlanes prior{problem.constraints};
  if (!problem.use_contractors) return sivia_q(data, q, problem.priors, options, prior);
  const CtcPair<CtcRangeRelaxed, CtcBearingRelaxed> ctc{
      CtcRangeRelaxed(problem.map.walls, problem.range_sensors, problem.ranges),
      CtcBearingRelaxed(problem.map.landmarks, problem.bearing_sensors, problem.bearings)};
  return sivia_q(data, q, problem.priors, options, prior, ctc.with_outliers(q));
}

LocalizationProblem without_datum(LocalizationProblem p, std::size_t i) {
  if (i < p.ranges.size())
    p.ranges.erase(p.ranges.begin() + static_cast<std::ptrdiff_t>(i));
  else
    p.bearings.erase(p.bearings.begin() + static_cast<std::ptrdiff_t>(i - p.ranges.size()));
  if (i < p.file_numbers.size()) p.file_numbers.erase(p.file_numbers.begin() + static_cast<std::ptrdiff_t>(i));
  return p;
}

std::string check_angle(double a, const std::string& what) {
  return std::isfinite(a) ? std::string() : what + " must be finite";
}

}  // namespace

bool box_holds_pose(std::span<const Interval> box, const Pose<double>& pose) {
  if (!box[0].contains(pose.x) || !box[1].contains(pose.y)) return false;
  const double turns = std::round((box[2].mid() - pose.theta) / kTwoPi);
  return box[2].contains(pose.theta + turns * kTwoPi);
}

std::string LocalizationProblem::validate() const {
  if (datum_count() == 0) return "no measurements";
  if (priors.empty()) return "no prior box";
  if (!file_numbers.empty() && file_numbers.size() != datum_count()) return "one file number per measurement";
  for (const Box& b : priors) {
    if (b.size() != 3) return "prior boxes must have 3 components (x, y, theta)";
    for (const Interval& x : b)
      if (!x.is_bounded() || x.is_empty()) return "prior boxes must be bounded and non-empty";
  }
  for (const RangeMeasurement& m : ranges) {
    if (m.sensor >= range_sensors.size()) return "range measurement of an unknown sensor";
    const RangeSensor& s = range_sensors[m.sensor];
    if (m.no_echo()) {
      if (!s.has_max_range()) return "range sensor " + s.name + ": 'no echo' needs a max_range";
    } else if (!(m.range > 0.0) || !std::isfinite(m.range)) {
      return "ranges must be positive and finite";
    } else if (m.range > s.max_range) {
      return "range sensor " + s.name + ": a range beyond max_range is 'no echo'";
    }
  }
  for (const BearingMeasurement& m : bearings) {
    if (m.sensor >= bearing_sensors.size()) return "bearing measurement of an unknown sensor";
    if (auto e = check_angle(m.bearing, "bearings"); !e.empty()) return e;
  }
  for (const RangeSensor& s : range_sensors) {
    if (!(s.half_aperture > 0.0 && s.half_aperture < std::numbers::pi / 4) || !(s.precision >= 0.0 && s.precision < 1.0))
      return "range sensor " + s.name + ": half aperture must be in (0, 45) degrees and precision in [0, 1)";
    if (!(s.max_range > 0.0) || !(s.blind_distance >= 0.0) || !(s.blind_distance < s.max_range))
      return "range sensor " + s.name + ": need 0 <= blind distance < max range";
  }
  for (const BearingSensor& s : bearing_sensors)
    if (!(s.precision >= 0.0 && s.precision < std::numbers::pi / 2))
      return "bearing sensor " + s.name + ": precision must be in [0, 90) degrees";
  if (!(epsilon > 0.0) || !(epsilon_min > 0.0) || epsilon_min > epsilon) return "need 0 < epsilon_min <= epsilon";
  if (outliers < 0 || outliers > static_cast<int>(datum_count())) return "outliers must be between 0 and the number of measurements";
  if (extra_outliers < 0) return "extra outliers must not be negative";
  if (!(theta_scale > 0.0) || !std::isfinite(theta_scale)) return "theta_scale must be positive and finite";
  return {};
}

LocalizationResult localize(const LocalizationProblem& problem,
                            const std::function<void(const SiviaProgress&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  LocalizationData data = make_data(problem);
  const HalfPlanes prior{problem.constraints};
  SiviaOptions sivia_options = sivia_options_of(problem);
  sivia_options.progress = progress;
  LocalizationResult result;
  if (problem.policy == OutlierPolicy::fixed) {
    result.q = problem.outliers;
    result.epsilon = problem.epsilon;
    result.paving = solve_fixed(problem, data, problem.outliers, sivia_options);
    result.found = !result.paving.inner.empty() || !result.paving.boundary.empty();
  } else {
    GomneOptions options;
    options.epsilon0 = problem.epsilon;
    options.epsilon_min = problem.epsilon_min;
    options.extra_outliers = problem.extra_outliers;
    options.max_outliers = problem.max_outliers;
    options.sivia = sivia_options;
    // Contractors before bisection (Remark 5 of seed 004), each valid for S_q.
    const CtcPair<CtcRangeRelaxed, CtcBearingRelaxed> ctc{
        CtcRangeRelaxed(problem.map.walls, problem.range_sensors, problem.ranges),
        CtcBearingRelaxed(problem.map.landmarks, problem.bearing_sensors, problem.bearings)};
    GomneResult g = problem.use_contractors ? gomne(data, problem.priors, options, prior, ctc)
                                            : gomne(data, problem.priors, options, prior);
    result.q = std::max(0, g.q_used);
    result.q_lower = std::min(g.q_lower, result.q);
    result.epsilon = g.epsilon;
    result.found = g.found;
    result.paving = std::move(g.paving);
    g.paving = SiviaResult{Paving(), Paving(), g.paving.report};
    result.gomne = std::move(g);
  }
  // Where phi is undetermined, bisect down to epsilon so that boxes split by outlier set.
  OutlierRefinementOptions refine_options;
  refine_options.q = result.q;
  refine_options.q_lower = result.q_lower;
  refine_options.epsilon = result.epsilon;
  refine_options.scale = sivia_options.scale;
  refine_options.max_boxes = problem.max_boxes;
  // What is left of the scenario's time (at least a millisecond: the refinement takes no zero limit).
  refine_options.max_seconds =
      std::max(1e-3, problem.max_seconds - std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  OutlierPaving refined = refine_by_outliers(data, result.paving, refine_options, prior);
  result.refinement_boxes = refined.boxes_evaluated;
  result.refinement_limit_hit = refined.limit_hit();
  ComponentOptions component_options;  // theta wraps, in hypotheses and in the sets' hulls alike
  component_options.periodic_dimension = 2;
  component_options.period = kTwoPi;
  component_options.periodic_origin = problem.priors.front()[2].lo();
  result.outlier_sets = partition_by_outlier_set(refined, component_options);
  for (PavingComponent& c : hypothesis_components(refined, component_options)) {
    LocalizationHypothesis h;
    h.outliers = component_outliers(data, refined, c, result.q, prior);
    Pose<double> at{c.hull[0].mid(), c.hull[1].mid(), c.hull[2].mid()};
    if (!h.outliers.point.empty()) at = {h.outliers.point[0].mid(), h.outliers.point[1].mid(), h.outliers.point[2].mid()};
    h.range_walls = data.ranges().associate(at);
    h.bearing_landmarks = data.bearings().associate(at);
    if (problem.truth) {
      for (std::size_t i : c.inner) h.contains_truth = h.contains_truth || box_holds_pose(refined.inner.box(i), *problem.truth);
      for (std::size_t i : c.boundary)
        h.contains_truth = h.contains_truth || box_holds_pose(refined.boundary.box(i), *problem.truth);
    }
    result.truth_enclosed = result.truth_enclosed || h.contains_truth;
    h.component = std::move(c);
    result.hypotheses.push_back(std::move(h));
  }
  result.paving.inner = std::move(refined.inner);
  result.paving.boundary = std::move(refined.boundary);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::vector<DatumSafety> localization_safety(const LocalizationProblem& problem, const LocalizationResult& result) {
  const double inner = result.paving.inner.volume(), outer = inner + result.paving.boundary.volume();
  SiviaOptions options = sivia_options_of(problem);
  options.epsilon = result.epsilon > 0.0 ? result.epsilon : problem.epsilon;
  std::vector<DatumSafety> out;
  for (std::size_t i = 0; i < problem.datum_count(); ++i) {
    const LocalizationProblem reduced = without_datum(problem, i);
    LocalizationData data = make_data(reduced);
    const SiviaResult r = solve_fixed(reduced, data, std::min(result.q, static_cast<int>(reduced.datum_count())), options);
    out.push_back(datum_safety_from(r, inner, outer));
  }
  return out;
}

}  // namespace gesmi
