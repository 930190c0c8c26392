#include "solver/network/tube_domains.h"

#include <algorithm>

namespace gesmi {

double TubeDomains::max_horizontal_width() const {
  double w = 0.0;
  for (std::size_t k = 0; k < px.size(); ++k) w = std::max({w, px[k].width(), py[k].width()});
  return w;
}

void intersect_with(TubeDomains& into, const TubeDomains& other) {
  const auto meet = [](std::vector<Interval>& a, const std::vector<Interval>& b) {
    for (std::size_t k = 0; k < a.size(); ++k) a[k] = intersect(a[k], b[k]);
  };
  meet(into.px, other.px);
  meet(into.py, other.py);
  meet(into.pz, other.pz);
  meet(into.dx, other.dx);
  meet(into.dy, other.dy);
  meet(into.dz, other.dz);
  for (std::size_t i = 0; i < into.mines.size(); ++i)
    for (int a = 0; a < 3; ++a) into.mines[i][a] = intersect(into.mines[i][a], other.mines[i][a]);
  for (std::size_t j = 0; j < into.candidates.size(); ++j) into.candidates[j] &= other.candidates[j];
}

}  // namespace gesmi
