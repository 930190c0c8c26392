#include "solver/structured/structured_errors.h"

#include <stdexcept>

#include "solver/interval/rounding.h"

namespace gesmi {

StructuredErrors split_by_bias_share(const SensorModel& model, double share) {
  if (!(share >= 0.0 && share <= 1.0)) throw std::invalid_argument("bias share: must be within [0, 1]");
  StructuredErrors e;
  const double rest = add_up(sub_up(1.0, share), mul_up(share, model.dvl_relative));
  e.bias_bound[kHeadingBias] = mul_up(share, model.heading);
  for (std::size_t a = 0; a < 3; ++a) {
    e.bias_bound[kScaleBias + a] = mul_up(share, model.dvl_relative);
    e.bias_bound[kOffsetBias + a] = mul_up(share, model.dvl_absolute);
  }
  e.noise = model;
  e.noise.heading = mul_up(sub_up(1.0, share), model.heading);
  e.noise.dvl_relative = mul_up(rest, model.dvl_relative);
  e.noise.dvl_absolute = mul_up(rest, model.dvl_absolute);
  return e;
}

}  // namespace gesmi
