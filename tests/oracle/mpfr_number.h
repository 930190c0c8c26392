#pragma once
// The oracle tests' precision, and an RAII MPFR number at it for those that compare
// doubles with MPFR's sin and cos (euler_sin_cos_oracle_test, vector_sin_cos_oracle_test).

#include <mpfr.h>

#include <cstdio>
#include <string>

namespace gesmi::oracle {

inline constexpr mpfr_prec_t kPrecision = 128;  // far beyond double: the oracle's own error is negligible

class MpfrNumber {
 public:
  MpfrNumber() { mpfr_init2(x_, kPrecision); }
  MpfrNumber(const MpfrNumber&) = delete;
  MpfrNumber& operator=(const MpfrNumber&) = delete;
  ~MpfrNumber() { mpfr_clear(x_); }
  operator mpfr_ptr() { return x_; }  // NOLINT: reads like the C API
  double down() { return mpfr_get_d(x_, MPFR_RNDD); }
  double up() { return mpfr_get_d(x_, MPFR_RNDU); }

 private:
  mpfr_t x_;
};

/// x in C's hexadecimal notation (exact), for the failure messages.
inline std::string hex(double x) {
  char text[40];
  std::snprintf(text, sizeof text, "%a", x);
  return text;
}

}  // namespace gesmi::oracle
