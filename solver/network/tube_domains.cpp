#include "solver/network/tube_domains.h"

#include <algorithm>

namespace gesmi {

double TubeDomains::max_horizontal_width() const {
  double w = 0.0;
  for (std::size_t k = 0; k < px.size(); ++k) w = std::max({w, px[k].width(), py[k].width()});
  return w;
}

}  // namespace gesmi
