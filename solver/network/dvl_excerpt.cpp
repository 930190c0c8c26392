#include "solver/network/dvl_excerpt.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "solver/network/time_location.h"

namespace gesmi {

DvlSample DvlSample::of(const Mission& m, std::size_t k) {
  const std::vector<double>* readings[3] = {&m.vx, &m.vy, &m.vz};
  const std::vector<double>* widths[3] = {&m.half_widths.vx, &m.half_widths.vy, &m.half_widths.vz};
  if (k >= m.vx.size() || k >= m.vy.size() || k >= m.vz.size())
    throw std::logic_error("sample " + std::to_string(k) + " has no DVL reading (released by a solve or the smoother? MissionReadings)");
  DvlSample s;
  for (int i = 0; i < 3; ++i) {
    s.reading[i] = (*readings[i])[k];
    s.given[i] = !widths[i]->empty();
    if (s.given[i]) s.half_width[i] = (*widths[i])[k];
  }
  return s;
}

DvlExcerpt::DvlExcerpt(const Mission& mission, std::span<const double> times) {
  const std::vector<double>& grid = mission.time;
  for (const double t : times) {
    // What TimeLocation::locate reads: that sample and the one before.
    const std::size_t k = TimeLocation::sample_at_or_after(grid, t);
    if (k < grid.size()) index_.push_back(k);
    if (k > 0) index_.push_back(k - 1);
  }
  std::sort(index_.begin(), index_.end());
  index_.erase(std::unique(index_.begin(), index_.end()), index_.end());
  samples_.reserve(index_.size());
  for (const std::size_t k : index_) samples_.push_back(DvlSample::of(mission, k));
}

const DvlSample& DvlExcerpt::at(std::size_t k) const {
  const auto it = std::lower_bound(index_.begin(), index_.end(), k);
  if (it == index_.end() || *it != k)
    throw std::logic_error("the DVL reading of sample " + std::to_string(k) + " is not in the excerpt kept");
  return samples_[static_cast<std::size_t>(it - index_.begin())];
}

}  // namespace gesmi
