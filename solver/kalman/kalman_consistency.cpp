#include "solver/kalman/kalman_consistency.h"

#include <boost/math/distributions/chi_squared.hpp>
#include <limits>

namespace gesmi {

double chi_square_quantile(double dof, double probability) {
  if (!(dof > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return boost::math::quantile(boost::math::chi_squared_distribution<double>(dof), probability);
}

void chi_square_band(double dof, double probability, double& low, double& high) {
  const double tail = 0.5 * (1.0 - probability);
  low = chi_square_quantile(dof, tail) / dof;
  high = chi_square_quantile(dof, 1.0 - tail) / dof;
}

}  // namespace gesmi
