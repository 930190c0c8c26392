// The margin the sensor kernel puts around libmvec's sines and cosines
// (solver/model/vector_sin_cos.h): every value y that sin_cos_many returns must lie
// within kVectorLibmRelative |y| + kVectorLibmAbsolute of the exact sin or cos, here
// MPFR's at 128 bits, the difference and the margin computed in MPFR too. The angles:
// attitude readings (within +-4 pi), the doubles at and next to multiples of pi/2
// (zeros and extrema of sin and cos, k up to 6e5, below kVectorLibmLargest), tiny and
// subnormal angles, zeros, and large ones up to kVectorLibmLargest. Every angle goes
// through both of sin_cos_many's paths: in one call over all of them (four lanes with
// AVX2) and in calls of three (two lanes, then the odd one). Making the margin half an
// ulp (0x1p-54) fails this test at most of the points.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "solver/model/vector_sin_cos.h"
#include "tests/oracle/mpfr_number.h"

namespace gesmi {
namespace {

constexpr std::uint64_t kLibmvecSeed = 0x6c69626d766563ULL;  // "libmvec"

using Mpfr = oracle::MpfrNumber;

std::vector<double> angles() {
  std::mt19937_64 rng(kLibmvecSeed);
  std::uniform_real_distribution<double> attitude(-4.0 * M_PI, 4.0 * M_PI), unit(0.0, 1.0);
  std::vector<double> x;
  for (int i = 0; i < 60000; ++i) x.push_back(attitude(rng));
  // Around multiples of pi/2: the double nearest k pi/2 and its neighbours.
  const long double half_pi = 1.5707963267948966192313216916397514L;
  for (int i = 0; i < 6000; ++i) {
    const long double k = i < 2000 ? static_cast<long double>(i - 1000)
                                   : std::round(static_cast<long double>((unit(rng) - 0.5) * 1.2e6));
    const double c = static_cast<double>(k * half_pi);
    for (const double p : {std::nextafter(c, -INFINITY), c, std::nextafter(c, INFINITY)}) x.push_back(p);
  }
  // Tiny angles down to the subnormals, both signs, and the zeros.
  for (int i = 0; i < 4000; ++i) {
    const double magnitude = std::ldexp(1.0 + unit(rng), -static_cast<int>(rng() % 1074));
    x.push_back(rng() % 2 ? magnitude : -magnitude);
  }
  x.insert(x.end(), {0.0, -0.0, 0x1p-1074, -0x1p-1074, 0x1p-1022, 1e-8, -1e-8});
  // Large angles up to kVectorLibmLargest, where the argument reduction matters.
  for (int i = 0; i < 10000; ++i) x.push_back((unit(rng) * 2.0 - 1.0) * kVectorLibmLargest);
  return x;
}

struct VectorTally {
  int values = 0, failures = 0;
  double worst_ulps = 0.0;  // the largest error seen, in ulps of the result
  std::string first_failure, worst_at;
};

// y against the exact function of x: within the margin, and the error in ulps.
void check(double x, double y, bool cosine, const char* path, VectorTally& t) {
  Mpfr exact, error, margin, mx;
  mpfr_set_d(mx, x, MPFR_RNDN);  // exact
  if (cosine)
    mpfr_cos(exact, mx, MPFR_RNDN);
  else
    mpfr_sin(exact, mx, MPFR_RNDN);
  mpfr_set_d(error, y, MPFR_RNDN);
  mpfr_sub(error, error, exact, MPFR_RNDN);
  mpfr_abs(error, error, MPFR_RNDN);
  mpfr_set_d(margin, std::fabs(y), MPFR_RNDN);
  mpfr_mul_d(margin, margin, kVectorLibmRelative, MPFR_RNDN);  // a power of two: exact
  mpfr_add_d(margin, margin, kVectorLibmAbsolute, MPFR_RNDN);  // 128 bits: exact enough
  ++t.values;
  const double ulp = y == 0.0 ? 0x1p-1074 : std::nextafter(std::fabs(y), INFINITY) - std::fabs(y);
  const double ulps = mpfr_get_d(error, MPFR_RNDU) / ulp;
  if (ulps > t.worst_ulps) {
    t.worst_ulps = ulps;
    t.worst_at = std::string(cosine ? "cos " : "sin ") + oracle::hex(x);
  }
  if (mpfr_cmp(error, margin) > 0 && t.failures++ == 0)
    t.first_failure = std::string(cosine ? "cos(" : "sin(") + oracle::hex(x) + ") = " + oracle::hex(y) + " (" + path +
                      "), " + std::to_string(ulps) + " ulps from the exact value";
}

TEST(VectorSinCosOracle, EveryValueIsWithinItsMarginOfTheExactOne) {
  const std::vector<double> x = angles();
  const std::size_t n = x.size();
  std::vector<double> sine(n), cosine(n);
  sin_cos_many(x.data(), n, sine.data(), cosine.data());
  VectorTally t;
  for (std::size_t i = 0; i < n; ++i) {
    check(x[i], sine[i], false, "one call", t);
    check(x[i], cosine[i], true, "one call", t);
  }
  // Calls of three: the two-lane path, then the odd one.
  for (std::size_t i = 0; i + 3 <= n; i += 3) {
    double s[3], c[3];
    sin_cos_many(x.data() + i, 3, s, c);
    for (std::size_t j = 0; j < 3; ++j) {
      check(x[i + j], s[j], false, "calls of three", t);
      check(x[i + j], c[j], true, "calls of three", t);
    }
  }
  std::printf("sin_cos_many: %d values, %d outside the margin; the largest error %.3f ulps (%s); seed %#llx\n", t.values,
              t.failures, t.worst_ulps, t.worst_at.c_str(), static_cast<unsigned long long>(kLibmvecSeed));
  EXPECT_EQ(t.failures, 0) << t.first_failure;
  EXPECT_GT(t.values, 300000);
}

TEST(VectorSinCosOracle, NoCallWritesBeyondItsCount) {
  const double x[5] = {0.1, 0.2, 0.3, 0.4, 0.5};
  for (std::size_t n = 0; n <= 5; ++n) {
    double s[6], c[6];
    for (double& v : s) v = -7.0;
    for (double& v : c) v = -7.0;
    sin_cos_many(x, n, s, c);
    for (std::size_t i = 0; i < 6; ++i) {
      EXPECT_EQ(s[i] == -7.0, i >= n) << "n = " << n << ", sine " << i;
      EXPECT_EQ(c[i] == -7.0, i >= n) << "n = " << n << ", cosine " << i;
    }
  }
}

}  // namespace
}  // namespace gesmi
