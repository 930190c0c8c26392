#pragma once
// The body-to-world rotation R = Rz(psi) Ry(theta) Rx(phi) written out as the
// textbook ZYX matrix in long double: an oracle independent of
// solver/model/euler.h (which applies three plane rotations in the number type).

namespace gesmi::test {

struct RotationLd {
  long double r[3][3];

  RotationLd(long double roll, long double pitch, long double heading);
  /// out = R v (body to world).
  void to_world(const long double v[3], long double out[3]) const;
  /// out = R^T v (world to body).
  void to_body(const long double v[3], long double out[3]) const;
};

}  // namespace gesmi::test
