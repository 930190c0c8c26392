#include "solver/network/outliers/outlier_solver.h"

#include <algorithm>

#include "solver/network/reduced_network.h"
#include "solver/network/outliers/relaxed_enclosure.h"
#include "solver/network/outliers/subsets.h"

namespace gesmi {
namespace {

bool consistent(const MissionNetwork& net, const TubeDomains& sensor, TubeDomains& d, const SolverOptions& options,
                SolverReport* report = nullptr) {
  d = sensor;
  add_network_priors(d, net);
  const SolverReport r = solve(net, d, options);
  if (report) *report = r;
  return r.consistent();
}

void hull_into(TubeDomains& acc, const TubeDomains& d, bool first) {
  if (first) {
    acc = d;
    return;
  }
  combine_domains(acc, d, [](const Interval& a, const Interval& b) { return hull(a, b); });
}

// The removable constraint ids: every detection, and every fix unless trusted.
std::vector<std::size_t> removable_ids(const MissionNetwork& net, bool trust_fixes) {
  std::vector<std::size_t> ids;
  const std::size_t m = net.detections.size();
  for (std::size_t j = 0; j < m + (trust_fixes ? 0 : net.anchors.size()); ++j) ids.push_back(j);
  return ids;
}

}  // namespace

MissionNetwork without_constraints(const MissionNetwork& net, const std::vector<std::size_t>& removed) {
  MissionNetwork sub;
  sub.time = net.time;
  sub.mine_count = net.mine_count;
  const std::size_t m = net.detections.size();
  for (std::size_t j = 0; j < m; ++j)
    if (!std::binary_search(removed.begin(), removed.end(), j)) sub.detections.push_back(net.detections[j]);
  for (std::size_t a = 0; a < net.anchors.size(); ++a)
    if (!std::binary_search(removed.begin(), removed.end(), m + a)) sub.anchors.push_back(net.anchors[a]);
  return sub;
}

std::string OutlierOptions::validate() const {
  if (max_outliers < 0) return "the number of outliers must be >= 0";
  return solver.validate();
}

OutlierReport solve_with_outliers(const MissionNetwork& net, const TubeDomains& sensor, TubeDomains& domains,
                                  const OutlierOptions& options) {
  OutlierReport report;
  const std::size_t m = net.detections.size();
  const std::vector<std::size_t> removable = removable_ids(net, options.trust_fixes);
  report.detection_outlier.assign(m, 0);
  report.fix_outlier.assign(net.anchors.size(), 0);
  ++report.full_solves;
  TubeDomains all_data;
  if (consistent(net, sensor, all_data, options.solver, &report.first_solve)) report.minimal_outliers = 0;

  // q*: raise q until some q removable constraints restore consistency.
  TubeDomains minimal_hull, trial, trial_reduced;
  std::vector<std::uint64_t> candidates(m, 0);
  ReducedNetwork reduced;
  const bool sensors_consistent = build_reduced_network(net, sensor, reduced);
  for (int q = 1; report.minimal_outliers < 0 && sensors_consistent && q <= options.max_outliers &&
                  static_cast<std::size_t>(q) <= removable.size();
       ++q) {
    for_each_subset(removable, static_cast<std::size_t>(q), [&](const std::vector<std::size_t>& removed) {
      ++report.hypotheses_screened;
      const MissionNetwork reduced_sub = without_constraints(reduced.net, removed);
      trial_reduced = reduced.domains;
      add_network_priors(trial_reduced, reduced_sub);
      if (!solve(reduced_sub, trial_reduced, options.solver).consistent()) return;
      ++report.full_solves;
      const MissionNetwork sub = without_constraints(net, removed);
      if (!consistent(sub, sensor, trial, options.solver)) return;
      hull_into(minimal_hull, trial, report.hypotheses.empty());
      // Candidates of the kept detections, by their index in the full network.
      for (std::size_t j = 0, kept = 0; j < m; ++j) {
        if (std::binary_search(removed.begin(), removed.end(), j))
          candidates[j] |= net.detections[j].allowed;
        else
          candidates[j] |= trial.candidates[kept++];
      }
      report.hypotheses.push_back(removed);
    });
    if (!report.hypotheses.empty()) report.minimal_outliers = q;
  }
  if (!report.consistent()) {
    domains = std::move(all_data);
    return report;
  }
  for (const std::size_t id : removable) {
    const bool everywhere = !report.hypotheses.empty() &&
                            std::all_of(report.hypotheses.begin(), report.hypotheses.end(),
                                        [&](const auto& h) { return std::binary_search(h.begin(), h.end(), id); });
    if (!everywhere) continue;
    if (id < m)
      report.detection_outlier[id] = 1;
    else
      report.fix_outlier[id - m] = 1;
  }

  if (options.mode == OutlierMode::minimal || options.max_outliers == 0) {
    if (report.minimal_outliers == 0) {
      domains = std::move(all_data);
    } else {
      minimal_hull.candidates = candidates;
      domains = std::move(minimal_hull);
    }
    return report;
  }
  // S_Q: every set of exactly Q removable constraints (fewer only shrink the set).
  const std::size_t q = std::min(static_cast<std::size_t>(options.max_outliers), removable.size());
  const RelaxedStats stats = relaxed_enclosure(net, sensor, removable, q, options.solver, domains);
  report.removal_sets = stats.removal_sets;
  report.consistent_removal_sets = stats.consistent_sets;
  return report;
}

}  // namespace gesmi
