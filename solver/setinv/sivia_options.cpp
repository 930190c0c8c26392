#include "solver/setinv/sivia_options.h"

#include <cmath>

namespace gesmi {

std::string SiviaOptions::validate(std::size_t dim) const {
  if (!(epsilon > 0.0) || !std::isfinite(epsilon)) return "epsilon must be a positive finite number";
  if (!scale.empty() && scale.size() != dim) return "scale must have one weight per dimension";
  for (double s : scale)
    if (!(s > 0.0) || !std::isfinite(s)) return "scale weights must be positive and finite";
  if (periodic_dimension < -1 || periodic_dimension >= static_cast<int>(dim))
    return "periodic_dimension must be -1 or a dimension of the box";
  if (!(period > 0.0) || !std::isfinite(period)) return "period must be positive and finite";
  if (!(max_seconds > 0.0)) return "max_seconds must be positive";
  if (max_boxes == 0) return "max_boxes must be positive";
  if (progress && progress_every == 0) return "progress_every must be positive";
  return {};
}

}  // namespace gesmi
