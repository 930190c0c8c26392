#include "solver/network/mission_solver.h"

#include <cmath>
#include <string>

#include "solver/network/detail/mission_propagation.h"

namespace gesmi {

std::string SolverOptions::validate() const {
  if (max_sweeps < 1 || max_sweeps > kMaxSweeps) return "max-sweeps: must be between 1 and " + std::to_string(kMaxSweeps);
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) return "tolerance: must be a finite number >= 0";
  return {};
}

SolverReport solve(const MissionNetwork& network, TubeDomains& domains, const SolverOptions& options) {
  SolverReport report;
  detail::MissionPropagation propagation(network, domains);
  while (report.sweeps < options.max_sweeps) {
    const std::optional<double> move = propagation.sweep(report.inconsistency);
    ++report.sweeps;
    if (!move) return report;
    report.last_move = *move;
    if (options.on_sweep) options.on_sweep(report.sweeps, *move);
    if (*move <= options.tolerance) {
      report.converged = true;
      return report;
    }
  }
  return report;
}

}  // namespace gesmi
