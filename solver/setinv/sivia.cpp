#include "solver/setinv/sivia.h"

#include <cmath>

namespace gesmi::detail {

std::pair<std::size_t, double> widest_dimension(std::span<const Interval> box, const std::vector<double>& scale) {
  std::size_t best = 0;
  double best_width = -1.0;
  for (std::size_t k = 0; k < box.size(); ++k) {
    const double w = box[k].width() * (scale.empty() ? 1.0 : scale[k]);
    if (w > best_width) {
      best_width = w;
      best = k;
    }
  }
  return {best, best_width};
}

bool can_bisect(std::span<const Interval> box, const std::vector<double>& scale) {
  const Interval& side = box[widest_dimension(box, scale).first];
  const double m = side.mid();
  return side.lo() < m && m < side.hi();
}

Box wrap_prior(const Box& prior, const SiviaOptions& options) {
  Box box = prior;
  if (options.periodic_dimension >= 0) {
    Interval& theta = box[static_cast<std::size_t>(options.periodic_dimension)];
    // Beyond one period every angle is already covered: exploring more only
    // duplicates solutions.
    if (theta.is_bounded() && theta.width() > options.period)
      theta = Interval(theta.lo(), theta.lo() + options.period);
  }
  return box;
}

}  // namespace gesmi::detail

namespace gesmi {

double finest_epsilon(std::span<const Box> priors, const std::vector<double>& scale) {
  double finest = 0.0;
  for (const Box& box : priors)
    for (std::size_t k = 0; k < box.size(); ++k) {
      const double magnitude = box[k].mag();
      if (!std::isfinite(magnitude)) continue;
      const double spacing = std::nextafter(magnitude, kInf) - magnitude;
      finest = std::max(finest, 2.0 * spacing * (scale.empty() ? 1.0 : scale[k]));
    }
  return finest;
}

}  // namespace gesmi
