#include "solver/setinv/outliers/gomne.h"

#include <cmath>

namespace gesmi {

std::string GomneOptions::validate(std::size_t dim) const {
  if (!(epsilon0 > 0.0) || !std::isfinite(epsilon0)) return "epsilon0 must be a positive finite number";
  if (!(epsilon_min > 0.0) || epsilon_min > epsilon0) return "epsilon_min must be positive and at most epsilon0";
  if (extra_outliers < 0) return "extra_outliers must not be negative";
  if (max_outliers < -1) return "max_outliers must be -1 (all data) or a count";
  SiviaOptions s = sivia;
  s.epsilon = epsilon0;
  return s.validate(dim);
}

}  // namespace gesmi
