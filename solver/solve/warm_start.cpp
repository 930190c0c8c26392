#include "solver/solve/warm_start.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "solver/solve/solve_mission.h"

namespace gesmi {

std::string warm_start_problem(const Mission& mission, const MissionSolution& previous) {
  if (!previous.report.consistent) return "that result is inconsistent; run a cold solve";
  if (previous.time != mission.time || previous.mine_count != mission.mine_count)
    return "it was computed on another mission";
  const std::size_t rows = previous.mark_count();
  if (rows > mission.mark_count() || previous.candidates.size() != rows)
    return "the mark table changed other than by added rows; run a cold solve";
  for (std::size_t j = 0; j < rows; ++j)
    if (previous.mark_time[j] != mission.mark_time[j] || previous.mark_range[j] != mission.mark_range[j] ||
        previous.mark_mine[j] != mission.mark_mine[j] || previous.mark_side[j] != mission.mark_side[j])
      return "the mark table changed other than by added rows; run a cold solve";
  const TubeDomains& d = previous.domains;
  if (d.size() != mission.size() || d.dx.size() + 1 != mission.size() ||
      d.mines.size() != static_cast<std::size_t>(mission.mine_count))
    return "it was computed on another mission";
  return {};
}

namespace detail {

std::string added_marks_problem(const Mission& mission, const MissionNetwork& network, const MissionSolution& previous) {
  // Symmetry breaking among unlabelled mines depends on the labelled ones: if the
  // added marks change it, the earlier domains assumed other labels.
  const std::vector<std::uint64_t> before = allowed_mines_of_marks(mission, previous.mark_count());
  for (const Detection& detection : network.detections)
    if (detection.mark < before.size() && detection.allowed != before[detection.mark])
      return "the added marks name a mine no mark named before";
  return {};
}

WarmDomains warm_domains(const MissionNetwork& network, const MissionSolution& previous, MissionSolution* spent) {
  if (spent && spent != &previous) throw std::logic_error("warm_domains: `spent` must be `previous` itself");
  WarmDomains warm;
  // The increments are half of the domains (480 MB at 10^7 steps): when given up, taken
  // out first, so that the copy leaves them, and put into the new domains.
  std::vector<Interval> taken[3];
  if (spent) {
    taken[0] = std::move(spent->domains.dx);
    taken[1] = std::move(spent->domains.dy);
    taken[2] = std::move(spent->domains.dz);
  }
  warm.domains = previous.domains;
  if (spent) {
    warm.domains.dx = std::move(taken[0]);
    warm.domains.dy = std::move(taken[1]);
    warm.domains.dz = std::move(taken[2]);
  }
  add_network_priors(warm.domains, network);    // mines and candidates reset...
  warm.domains.mines = previous.domains.mines;  // ...then the earlier mine boxes restored
  warm.added = carry_candidates(network, warm.domains, previous.candidates);
  return warm;
}

}  // namespace detail
}  // namespace gesmi
