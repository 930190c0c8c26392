#include "solver/network/outlier_solver.h"

#include <algorithm>

#include "solver/network/reduced_network.h"

namespace gesmi {
namespace {

// The network without the constraints of `removed` (sorted ids).
MissionNetwork without(const MissionNetwork& net, const std::vector<std::size_t>& removed) {
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
  const auto merge = [](std::vector<Interval>& a, const std::vector<Interval>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = hull(a[k], b[k]);
  };
  merge(acc.px, d.px);
  merge(acc.py, d.py);
  merge(acc.pz, d.pz);
  merge(acc.dx, d.dx);
  merge(acc.dy, d.dy);
  merge(acc.dz, d.dz);
  for (std::size_t i = 0; i < acc.mines.size(); ++i)
    for (int c = 0; c < 3; ++c) acc.mines[i][c] = hull(acc.mines[i][c], d.mines[i][c]);
}

// Calls visit on every sorted subset of {0..n-1} of size q until visit returns false.
template <class Visit>
void for_each_subset(std::size_t n, std::size_t q, Visit visit) {
  if (q > n) return;
  std::vector<std::size_t> s(q);
  for (std::size_t i = 0; i < q; ++i) s[i] = i;
  while (true) {
    visit(s);
    std::size_t i = q;
    while (i > 0 && s[i - 1] == n - q + i - 1) --i;
    if (i == 0) return;
    ++s[i - 1];
    for (std::size_t j = i; j < q; ++j) s[j] = s[j - 1] + 1;
  }
}

}  // namespace

std::string OutlierOptions::validate() const {
  if (max_outliers < 0) return "the number of outliers must be >= 0";
  return solver.validate();
}

OutlierReport solve_with_outliers(const MissionNetwork& net, const TubeDomains& sensor, TubeDomains& domains,
                                  const OutlierOptions& options) {
  OutlierReport report;
  const std::size_t m = net.detections.size(), n = m + net.anchors.size();
  report.detection_outlier.assign(m, 0);
  report.fix_outlier.assign(net.anchors.size(), 0);
  ++report.full_solves;
  if (consistent(net, sensor, domains, options.solver, &report.first_solve)) {
    report.minimal_outliers = 0;
    return report;
  }
  const TubeDomains failed = domains;
  ReducedNetwork reduced;
  if (!build_reduced_network(net, sensor, reduced)) return report;

  TubeDomains result, trial, trial_reduced;
  std::vector<std::uint64_t> candidates(m, 0);
  for (int q = 1; q <= options.max_outliers && report.hypotheses.empty(); ++q) {
    for_each_subset(n, static_cast<std::size_t>(q), [&](const std::vector<std::size_t>& removed) {
      ++report.hypotheses_screened;
      const MissionNetwork reduced_sub = without(reduced.net, removed);
      trial_reduced = reduced.domains;
      add_network_priors(trial_reduced, reduced_sub);
      if (!solve(reduced_sub, trial_reduced, options.solver).consistent()) return;
      ++report.full_solves;
      const MissionNetwork sub = without(net, removed);
      if (!consistent(sub, sensor, trial, options.solver)) return;
      hull_into(result, trial, report.hypotheses.empty());
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
  if (report.hypotheses.empty()) {
    domains = failed;
    return report;
  }
  result.candidates = candidates;
  domains = std::move(result);
  for (std::size_t id = 0; id < n; ++id) {
    const bool everywhere = std::all_of(report.hypotheses.begin(), report.hypotheses.end(), [&](const auto& h) {
      return std::binary_search(h.begin(), h.end(), id);
    });
    if (!everywhere) continue;
    if (id < m)
      report.detection_outlier[id] = 1;
    else
      report.fix_outlier[id - m] = 1;
  }
  return report;
}

}  // namespace gesmi
