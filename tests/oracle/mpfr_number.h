#pragma once
// An RAII MPFR number at 128 bits for the oracle tests that compare doubles with MPFR's
// sin and cos (euler_sin_cos_oracle_test, vector_sin_cos_oracle_test): far beyond
// double, so that the oracle's own error is negligible.

#include <mpfr.h>

namespace gesmi::oracle {

class MpfrNumber {
 public:
  static constexpr mpfr_prec_t kPrecision = 128;
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

}  // namespace gesmi::oracle
