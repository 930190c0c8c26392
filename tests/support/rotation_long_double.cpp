#include "tests/support/rotation_long_double.h"

#include <cmath>

namespace gesmi::test {

RotationLd::RotationLd(long double roll, long double pitch, long double heading) {
  const long double cf = std::cos(roll), sf = std::sin(roll), ct = std::cos(pitch), st = std::sin(pitch);
  const long double cp = std::cos(heading), sp = std::sin(heading);
  const long double m[3][3] = {{cp * ct, cp * st * sf - sp * cf, cp * st * cf + sp * sf},
                               {sp * ct, sp * st * sf + cp * cf, sp * st * cf - cp * sf},
                               {-st, ct * sf, ct * cf}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[i][j] = m[i][j];
}

void RotationLd::to_world(const long double v[3], long double out[3]) const {
  for (int i = 0; i < 3; ++i) out[i] = r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2];
}

void RotationLd::to_body(const long double v[3], long double out[3]) const {
  for (int i = 0; i < 3; ++i) out[i] = r[0][i] * v[0] + r[1][i] * v[1] + r[2][i] * v[2];
}

}  // namespace gesmi::test
