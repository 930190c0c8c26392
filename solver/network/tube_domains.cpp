#include "solver/network/tube_domains.h"

#include <algorithm>

namespace gesmi {

double TubeDomains::max_horizontal_width() const {
  double w = 0.0;
  for (std::size_t k = 0; k < px.size(); ++k) w = std::max({w, px[k].width(), py[k].width()});
  return w;
}

void intersect_with(TubeDomains& into, const TubeDomains& other) {
  combine_domains(into, other, [](const Interval& a, const Interval& b) { return intersect(a, b); });
  for (std::size_t j = 0; j < into.candidates.size(); ++j) into.candidates[j] &= other.candidates[j];
}

}  // namespace gesmi
