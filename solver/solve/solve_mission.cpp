#include "solver/solve/solve_mission.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "solver/network/frame/frame_margins.h"
#include "solver/network/sensors/sensor_priors.h"
#include "solver/network/inconsistency_text.h"
#include "solver/solve/warm_start.h"

namespace gesmi {
namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

// A network constraint id (detection j, or detections.size() + anchor a) as a row.
ConstraintRef constraint_of(const MissionNetwork& net, std::size_t id) {
  const std::size_t m = net.detections.size();
  return id < m ? ConstraintRef::mark(net.detections[id].mark) : ConstraintRef::gps_fix(net.anchors[id - m].fix.source_index);
}

void take_propagation(SolveReport& report, const SolverReport& r) {
  report.sweeps = r.sweeps;
  report.converged = r.converged;
  report.consistent = r.consistent();
  report.inconsistency = r.inconsistency;
}

// The single marks or fixes whose removal restores consistency (q = 1).
std::vector<ConstraintRef> diagnose(const MissionNetwork& net, const TubeDomains& sensor, const SolverOptions& options) {
  OutlierOptions o;
  o.max_outliers = 1;
  o.mode = OutlierMode::minimal;  // only the hypotheses are wanted
  o.solver = options;
  o.solver.on_sweep = nullptr;
  TubeDomains scratch;
  const OutlierReport r = solve_with_outliers(net, sensor, scratch, o);
  std::vector<ConstraintRef> explaining;
  if (r.minimal_outliers == 1)
    for (const auto& h : r.hypotheses) explaining.push_back(constraint_of(net, h[0]));
  return explaining;
}

// What every mode reads besides the mission: its GPS fixes, its steps' regimes and the
// readings' check (step_regimes.h), and the speed bound the frame's margins take
// (frame_margins.h; the largest of the DVL's and the regimes').
struct SolveInputs {
  std::vector<PositionFix> fixes;
  StepRegimes regimes;
  double max_speed = 0.0;
};

SolveInputs solve_inputs(const Mission& mission) {
  SolveInputs in{gps_fixes(mission), classify_steps(mission, mission.model), 0.0};
  if (has_frame_margins(mission)) in.max_speed = std::max(speed_bound(mission), in.regimes.largest_speed(mission.model));
  return in;
}

MissionNetwork network_in(const Mission& mission, const SolveInputs& in, const FrameMargins& frame) {
  return build_network(mission, mission.model, in.fixes, frame, in.regimes);
}

// Builds the network and the sensor domains under a frame, the time counted as "build".
struct Pass {
  MissionNetwork net;
  TubeDomains sensor;
};

Pass build_pass(const Mission& mission, const SolveInputs& in, const SensorPriors& priors, const FrameMargins& frame,
                MissionSolution& s) {
  const auto start = Clock::now();
  Pass pass{network_in(mission, in, frame), sensor_domains_in(priors, frame)};
  s.timings_ms["build"] += elapsed_ms(start);
  return pass;
}

SensorPriors build_priors(const Mission& mission, const SolveInputs& in, MissionSolution& s) {
  const auto start = Clock::now();
  SensorPriors priors = frameless_sensor_priors(mission, mission.model, in.regimes);
  s.timings_ms["build"] += elapsed_ms(start);
  return priors;
}

// The diagnosis of an inconsistent cold solve: which single mark or fix is wrong.
// Margins from the fixes, or over a tube that trusted every datum, would presume the
// answer, so it takes the zone's (sound whichever datum is wrong); and the priors are
// built again (the passes took their vertical part, and dropped them).
void diagnose_cold(const Mission& mission, const std::vector<PositionFix>& fixes, const SolverOptions& options,
                   MissionSolution& s) {
  const auto start = Clock::now();
  const StepRegimes regimes = classify_steps(mission, mission.model);
  const SensorPriors priors = frameless_sensor_priors(mission, mission.model, regimes);
  const FrameMargins zone = zone_frame(mission);
  s.report.explained_by =
      diagnose(build_network(mission, mission.model, fixes, zone, regimes), sensor_domains_in(priors, zone), options);
  s.timings_ms["diagnose"] = elapsed_ms(start);
}

// The first pass's margins: at the farthest the fixes let the robot be when they are
// true (frame_margins.h), else anywhere in the frame's zone.
FrameMargins first_frame(const Mission& mission, const SolveInputs& in, bool fixes_true, FrameMarginValues& margins) {
  if (!fixes_true || !has_frame_margins(mission)) return zone_frame(mission);
  margins = frame_margins_from_fixes(mission, in.max_speed);
  return margins.view(mission);
}

// The per-sample margins over a first pass's tube (frame_margins.h), replacing that
// pass's, or none when the mission has no frame margins or that pass found no solution.
bool narrow_frame(const Mission& mission, const SolveInputs& in, const TubeDomains& tube, bool consistent,
                  FrameMarginValues& margins, FrameMargins& frame, MissionSolution& s) {
  if (!consistent || !has_frame_margins(mission)) return false;
  const auto start = Clock::now();
  margins = {};  // (the first pass is done with them: not both in memory at once)
  margins = frame_margins_over(mission, tube, in.max_speed);
  frame = margins.view(mission);
  s.report.beyond_frame_zone = margins.beyond_zone;
  s.timings_ms["build"] += elapsed_ms(start);
  return true;
}

void solve_cold(const Mission& mission, const SolveInputs& in, const SolveOptions& options, MissionSolution& s,
                MissionNetwork& net) {
  SensorPriors priors = build_priors(mission, in, s);
  FrameMarginValues margins;  // the first pass's, then the second's
  FrameMargins frame = first_frame(mission, in, true, margins);
  auto start = Clock::now();
  // The depth boxes and vertical increments move from the priors into the domains.
  net = network_in(mission, in, frame);
  s.domains = take_sensor_domains(priors, frame);
  add_network_priors(s.domains, net);
  // The network and the domains hold the first pass's margins now: not kept in memory
  // during the propagation.
  margins = {};
  frame = zone_frame(mission);
  s.timings_ms["build"] += elapsed_ms(start);
  start = Clock::now();
  take_propagation(s.report, solve(net, s.domains, options.propagation));
  s.timings_ms["propagate"] = elapsed_ms(start);
  if (narrow_frame(mission, in, s.domains, s.report.consistent, margins, frame, s)) {
    const int first_sweeps = s.report.sweeps;
    // The first pass's enclosure holds under its looser frame: narrowed in place (no
    // copy of the domains) by the sensor domains and network priors under this one.
    start = Clock::now();
    net = network_in(mission, in, frame);
    narrow_to_frame(s.domains, priors, frame);
    intersect_network_priors(s.domains, net);
    // Neither the priors nor the margins are kept in memory during the second
    // propagation (a diagnosis builds its own).
    priors = {};
    margins = {};
    frame = zone_frame(mission);
    s.timings_ms["build"] += elapsed_ms(start);
    start = Clock::now();
    take_propagation(s.report, solve(net, s.domains, options.propagation));
    s.timings_ms["propagate"] += elapsed_ms(start);
    s.report.sweeps += first_sweeps;
  }
  if (s.report.consistent || !options.diagnose) return;
  priors = {};
  diagnose_cold(mission, in.fixes, options.propagation, s);
}

void solve_outliers(const Mission& mission, const SolveInputs& in, const SolveOptions& options, MissionSolution& s,
                    MissionNetwork& net) {
  OutlierOptions o;
  o.max_outliers = options.max_outliers;
  o.mode = options.outlier_mode;
  o.trust_fixes = options.trust_gps;
  o.solver = options.propagation;
  const SensorPriors priors = build_priors(mission, in, s);
  FrameMarginValues margins;  // the first pass's, then the second's
  FrameMargins frame = first_frame(mission, in, options.trust_gps, margins);
  Pass pass = build_pass(mission, in, priors, frame, s);
  auto start = Clock::now();
  OutlierReport r = solve_with_outliers(pass.net, pass.sensor, s.domains, o);
  s.timings_ms["propagate"] = elapsed_ms(start);
  // The enclosure of either mode holds the truth under that mode's premise, and so do
  // the margins over it; the second pass solves afresh under them.
  if (narrow_frame(mission, in, s.domains, r.consistent(), margins, frame, s)) {
    pass = build_pass(mission, in, priors, frame, s);
    start = Clock::now();
    r = solve_with_outliers(pass.net, pass.sensor, s.domains, o);
    s.timings_ms["propagate"] += elapsed_ms(start);
  }
  net = std::move(pass.net);
  SolveReport& report = s.report;
  report.mode = options.outlier_mode == OutlierMode::relaxed ? SolveMode::outliers : SolveMode::minimal_outliers;
  report.consistent = r.consistent();
  report.converged = r.consistent();
  report.sweeps = r.consistent() ? r.full_solves : r.first_solve.sweeps;
  if (!r.consistent()) report.inconsistency = r.first_solve.inconsistency;
  report.minimal_outliers = r.minimal_outliers;
  report.removal_sets = r.removal_sets;
  report.consistent_removal_sets = r.consistent_removal_sets;
  for (const auto& h : r.hypotheses) {
    std::vector<ConstraintRef> refs;
    for (const std::size_t id : h) refs.push_back(constraint_of(net, id));
    report.hypotheses.push_back(refs);
  }
  for (std::size_t j = 0; j < net.detections.size(); ++j) s.mark_outlier[net.detections[j].mark] = r.detection_outlier[j];
  for (std::size_t a = 0; a < net.anchors.size(); ++a) s.gps_outlier[net.anchors[a].fix.source_index] = r.fix_outlier[a];
}

// `spent`: null, or *options.warm_from given up by the caller (its increments are taken).
void solve_warm(const Mission& mission, const SolveInputs& in, const SolveOptions& options, MissionSolution& s,
                MissionNetwork& net, MissionSolution* spent) {
  const MissionSolution& previous = *options.warm_from;
  std::string why = warm_start_problem(mission, previous);
  if (why.empty()) {
    // The previous tube holds the truth: the added marks take the margins over it.
    const auto start = Clock::now();
    const FrameMarginValues margins = frame_margins_over(mission, previous.domains, in.max_speed);
    net = network_in(mission, in, margins.view(mission));
    s.report.beyond_frame_zone = margins.beyond_zone;
    s.timings_ms["build"] += elapsed_ms(start);
    why = detail::added_marks_problem(mission, net, previous);
  }
  if (!why.empty()) {
    s.report.cold_fallback = why;
    s.report.beyond_frame_zone = 0.0;  // (the cold solve finds its own)
    solve_cold(mission, in, options, s, net);
    return;
  }
  // Only now: a fallback to a cold solve builds the sensor enclosures; a warm rerun none.
  // The times of an earlier result given up (compared above, not read again) are freed
  // before the earlier domains are copied (at 10^7 steps the rerun's peak).
  if (spent) std::vector<double>().swap(spent->time);
  detail::WarmDomains warm = detail::warm_domains(net, previous, spent);
  s.report.mode = SolveMode::warm;
  s.domains = std::move(warm.domains);
  const auto start = Clock::now();
  const IncrementalReport r = propagate_from(net, s.domains, warm.added, options.propagation);
  s.timings_ms["propagate"] = elapsed_ms(start);
  take_propagation(s.report, r.solver);
  s.report.work_items = r.work_items;
}

std::string wording(const SolveReport& report, const SolveOptions& options, const MissionNetwork& net) {
  std::string text = describe(*report.inconsistency, net);
  if (report.mode == SolveMode::outliers || report.mode == SolveMode::minimal_outliers)
    text = "more than " + std::to_string(options.max_outliers) + " of the " +
           (options.trust_gps ? "marks" : "marks and GPS fixes") + " are wrong (removing any " +
           std::to_string(options.max_outliers) + " of them leaves the data inconsistent); with all the data: " + text;
  if (report.explained_by) text += describe_diagnosis(*report.explained_by);
  return text;
}

// Every mode's solve; `spent`: see solve_warm.
MissionSolution solve_in_mode(const Mission& mission, const SolveOptions& options, MissionSolution* spent) {
  MissionSolution s;
  s.mark_time = mission.mark_time;
  s.mark_range = mission.mark_range;
  s.mark_mine = mission.mark_mine;
  s.mark_side = mission.mark_side;
  s.mine_count = mission.mine_count;
  s.model = mission.model;
  s.mark_outlier.assign(mission.mark_count(), 0);
  s.gps_outlier.assign(mission.gps_time.size(), 0);

  const auto stage = [&](const char* name, double fraction) {
    if (options.on_stage) options.on_stage(name, fraction);
  };
  stage("sensor enclosures", -1.0);
  auto start = Clock::now();
  const SolveInputs in = solve_inputs(mission);
  s.report.regimes = in.regimes.report();
  MissionNetwork net;
  s.timings_ms["build"] = elapsed_ms(start);
  if (options.warm_from)
    solve_warm(mission, in, options, s, net, spent);
  else if (options.max_outliers >= 0)
    solve_outliers(mission, in, options, s, net);
  else
    solve_cold(mission, in, options, s, net);

  // Copied once the passes are done: not held during the first pass's build, the
  // solve's peak (and at 10^6 steps it fills a hole the priors left in the heap).
  s.time = mission.time;
  s.candidates.assign(mission.mark_count(), 0);
  if (s.domains.candidates.size() == net.detections.size())
    for (std::size_t j = 0; j < net.detections.size(); ++j) s.candidates[net.detections[j].mark] = s.domains.candidates[j];
  if (!s.report.consistent) s.report.message = wording(s.report, options, net);
  if (options.waterfall) {
    start = Clock::now();
    // A warm rerun's earlier waterfall is copied where nothing it depends on changed.
    const MissionSolution* previous = s.report.mode == SolveMode::warm ? options.warm_from : nullptr;
    std::optional<WaterfallBefore> before;
    if (previous) {
      before.emplace(waterfall_before(previous->waterfall, previous->domains, s.domains));
      // Compared: an earlier result given up has its tube freed before the waterfall's peak.
      if (spent)
        for (std::vector<Interval>* v : {&spent->domains.px, &spent->domains.py, &spent->domains.pz})
          std::vector<Interval>().swap(*v);
    }
    stage("waterfall", 0.0);
    s.waterfall = compute_waterfall(mission, mission.model, s.domains, before ? &*before : nullptr, in.max_speed,
                                    [&](double fraction) { stage("waterfall", fraction); });
    s.timings_ms["waterfall"] = elapsed_ms(start);
  }
  return s;
}

}  // namespace

const char* solve_mode_name(SolveMode mode) {
  switch (mode) {
    case SolveMode::cold: return "cold";
    case SolveMode::warm: return "warm";
    case SolveMode::outliers: return "outliers";
    case SolveMode::minimal_outliers: return "minimal-outliers";
  }
  return "cold";
}

std::string SolveOptions::validate() const {
  if (const std::string why = propagation.validate(); !why.empty()) return why;
  if (max_outliers < -1 || max_outliers > 8)
    return std::string(outlier_mode == OutlierMode::minimal ? "minimal-outliers" : "max-outliers") + ": must be between 0 and 8";
  if (warm_from && max_outliers >= 0) return "from and --max-outliers cannot be combined";
  if (trust_gps && max_outliers < 0) return "trust-gps goes with --max-outliers or --minimal-outliers";
  return {};
}

MissionSolution solve_mission(const Mission& mission, const SolveOptions& options) {
  return solve_in_mode(mission, options, nullptr);
}

MissionSolution solve_mission(const Mission& mission, SolveOptions options, MissionSolution&& previous) {
  options.warm_from = &previous;
  return solve_in_mode(mission, options, &previous);
}

}  // namespace gesmi
