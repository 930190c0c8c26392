// Soundness of the narrow-angle sine and cosine of solver/model/euler.h (the
// first-order Taylor form with the Lagrange remainder r^2/2, and the general
// interval functions above r = 0.05), and of the libm margin kLibmSteps, against
// MPFR at 128 bits: at every sampled point x of an input interval X, and at every
// real multiple of pi/2 inside X (where the extrema 0, +-1 are reached), the exact
// value must lie inside the enclosure. The inputs are adversarial: intervals
// centred on, or ending at, the extrema of sin and cos (k pi / 2 up to k = 1e15),
// radius exactly 0.05 and just below (the largest Taylor remainder), degenerate and
// few-ulp intervals, and ordinary random ones. Halving the remainder, or removing
// the libm steps, leaves the exact value outside at the extrema.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "solver/model/euler.h"
#include "tests/oracle/mpfr_number.h"

namespace gesmi {
namespace {

constexpr std::uint64_t kEulerSeed = 0x65756c6572ULL;  // "euler"

using Mpfr = oracle::MpfrNumber;

// The exact sin or cos of the double x, rounded outward to doubles.
Interval exact_at(double x, bool cosine) {
  Mpfr v, y;
  mpfr_set_d(v, x, MPFR_RNDN);  // exact
  if (cosine)
    mpfr_cos(y, v, MPFR_RNDN);
  else
    mpfr_sin(y, v, MPFR_RNDN);
  // 128 bits: the value is within 2^-128 relative of the exact one, far inside
  // the outward rounding to 53 bits (except for exact doubles, kept exact).
  return Interval(y.down(), y.up());
}

struct EulerTally {
  int intervals = 0, points = 0, extrema = 0, failures = 0;
  double worst_excess = 0.0;  // enclosure width minus exact range width, over r^2
  std::string worst_input;
  std::string first_failure;
};

// The exact values at the real multiples of k pi / 2 inside X: sin and cos are
// 0 or +-1 there. MPFR decides which multiples lie inside.
void check_extrema(const Interval& x, const SinCos<Interval>& e, EulerTally& t) {
  Mpfr half_pi, q, kpi;
  mpfr_const_pi(half_pi, MPFR_RNDN);
  mpfr_div_ui(half_pi, half_pi, 2, MPFR_RNDN);
  mpfr_set_d(q, x.lo(), MPFR_RNDN);
  mpfr_div(q, q, half_pi, MPFR_RNDD);
  mpfr_floor(q, q);
  for (int i = 0; i < 8; ++i) {  // a width below 2 pi holds at most 5 multiples
    mpfr_mul(kpi, q, half_pi, MPFR_RNDN);
    if (mpfr_cmp_d(kpi, x.hi()) > 0) break;
    if (mpfr_cmp_d(kpi, x.lo()) >= 0) {
      // k mod 4 gives (sin, cos): 0 -> (0, 1), 1 -> (1, 0), 2 -> (0, -1), 3 -> (-1, 0).
      Mpfr r;
      mpfr_fmod_ui(r, q, 4, MPFR_RNDN);
      long k = mpfr_get_si(r, MPFR_RNDN);
      if (k < 0) k += 4;
      static constexpr double kSin[] = {0.0, 1.0, 0.0, -1.0}, kCos[] = {1.0, 0.0, -1.0, 0.0};
      ++t.extrema;
      if (!e.sin.contains(kSin[k]) || !e.cos.contains(kCos[k])) {
        if (t.failures++ == 0)
          t.first_failure = "X = [" + oracle::hex(x.lo()) + ", " + oracle::hex(x.hi()) +
                            "] holds k pi/2 with k mod 4 = " + std::to_string(k) + ": sin " + std::to_string(kSin[k]) +
                            " cos " + std::to_string(kCos[k]) + " not in sin [" + oracle::hex(e.sin.lo()) + ", " +
                            oracle::hex(e.sin.hi()) + "], cos [" + oracle::hex(e.cos.lo()) + ", " +
                            oracle::hex(e.cos.hi()) + "]";
      }
    }
    mpfr_add_ui(q, q, 1, MPFR_RNDN);
  }
}

// Checks sin_cos(X) at the end points, the midpoint, `random_points` points of X,
// the doubles next to each multiple of pi/2 inside X, and the real multiples.
void check_interval(const Interval& x, int random_points, std::mt19937_64& rng, EulerTally& t) {
  const SinCos<Interval> e = sin_cos(x);
  ++t.intervals;
  std::vector<double> points = {x.lo(), x.hi(), x.mid()};
  std::uniform_real_distribution<double> u(x.lo(), x.hi());
  for (int i = 0; i < random_points; ++i) points.push_back(std::clamp(u(rng), x.lo(), x.hi()));
  // Doubles around the multiples of pi/2 in X (long double is enough to find them).
  const long double half_pi = 1.5707963267948966192313216916397514L;
  for (long double k = std::floor(x.lo() / half_pi); k * half_pi <= x.hi() + 1e-3L; k += 1) {
    const double c = static_cast<double>(k * half_pi);
    for (const double p : {std::nextafter(c, -kInf), c, std::nextafter(c, kInf)})
      if (x.contains(p)) points.push_back(p);
  }
  Interval sin_range = Interval::empty(), cos_range = Interval::empty();
  for (const double p : points) {
    ++t.points;
    const Interval s = exact_at(p, false), c = exact_at(p, true);
    sin_range = hull(sin_range, s);
    cos_range = hull(cos_range, c);
    if (!e.sin.is_superset(s) || !e.cos.is_superset(c)) {
      if (t.failures++ == 0)
        t.first_failure = "X = [" + oracle::hex(x.lo()) + ", " + oracle::hex(x.hi()) + "] at x = " + oracle::hex(p) +
                          ": exact sin [" + oracle::hex(s.lo()) + ", " + oracle::hex(s.hi()) + "] cos [" +
                          oracle::hex(c.lo()) + ", " + oracle::hex(c.hi()) + "], enclosures sin [" +
                          oracle::hex(e.sin.lo()) + ", " + oracle::hex(e.sin.hi()) + "] cos [" +
                          oracle::hex(e.cos.lo()) + ", " + oracle::hex(e.cos.hi()) + "]";
    }
  }
  check_extrema(x, e, t);
  const double r = x.rad();
  // Tightness of the Taylor form relative to its remainder, for angles (|x| < 8;
  // far out, a few-ulp interval has no midpoint between its ends and r is its width).
  if (r > 1e-6 && r <= 0.05 && x.mag() < 8.0) {
    const double excess = std::max(e.sin.width() - sin_range.width(), e.cos.width() - cos_range.width());
    if (excess / (r * r) > t.worst_excess) {
      t.worst_excess = excess / (r * r);
      t.worst_input = "[" + oracle::hex(x.lo()) + ", " + oracle::hex(x.hi()) + "]";
    }
  }
}

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

// A centre near a multiple of pi/2 (k up to 1e15), a few ulps to 1e-3 away.
double near_extremum(std::mt19937_64& rng) {
  static const double magnitudes[] = {1.0, 10.0, 1e3, 1e6, 1e9, 1e15};
  const double k_max = magnitudes[rng() % 6];
  const double k = std::round(uniform(rng, -k_max, k_max));
  const double c = static_cast<double>(static_cast<long double>(k) * 1.5707963267948966192313216916397514L);
  switch (rng() % 3) {
    case 0: return c;
    case 1: return c + static_cast<double>(static_cast<int>(rng() % 17) - 8) * std::fabs(c) * 0x1p-52;
    default: return c + uniform(rng, -1e-3, 1e-3);
  }
}

TEST(EulerSinCosOracle, EnclosesTheExactSineAndCosineAtEveryPointAndExtremum) {
  const auto start = std::chrono::steady_clock::now();
  std::mt19937_64 rng(kEulerSeed);
  EulerTally t;
  // 1. Centred on an extremum, radius at the Taylor limit 0.05 and just below/above:
  //    the remainder term is then all that keeps the end points inside.
  for (int i = 0; i < 4000; ++i) {
    const double c = near_extremum(rng);
    const double radii[] = {0.05, std::nextafter(0.05, 0.0), 0.049, 0.03, 0.01, 1e-3, 1e-5, 0.0500001, 0.2};
    const double r = radii[rng() % 9];
    check_interval(Interval(c - r, c + r), 4, rng, t);
  }
  // 2. An end point on (or next to) an extremum, the other end up to 0.1 away.
  for (int i = 0; i < 3000; ++i) {
    const double c = near_extremum(rng), w = uniform(rng, 0.0, 0.1);
    check_interval(rng() % 2 ? Interval(c, c + w) : Interval(c - w, c), 4, rng, t);
  }
  // 3. Degenerate and few-ulp intervals anywhere (the libm margin alone).
  for (int i = 0; i < 4000; ++i) {
    const double c = rng() % 2 ? near_extremum(rng) : uniform(rng, -1e4, 1e4);
    const double w = static_cast<double>(rng() % 4) * std::fabs(c) * 0x1p-52;
    check_interval(Interval(c, c + w), 1, rng, t);
  }
  // 4. Ordinary sensor boxes: attitudes within +-pi, radius up to 0.06.
  for (int i = 0; i < 4000; ++i) {
    const double c = uniform(rng, -3.2, 3.2), r = uniform(rng, 0.0, 0.06);
    check_interval(Interval(c - r, c + r), 6, rng, t);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("sin_cos: %d intervals, %d points, %d real extrema inside, %d failures; worst excess width over the\n"
              "exact range of the sampled points: %.3f r^2; seed %#llx; %.2f s\n",
              t.intervals, t.points, t.extrema, t.failures, t.worst_excess, static_cast<unsigned long long>(kEulerSeed),
              seconds);
  EXPECT_EQ(t.failures, 0) << t.first_failure;
  EXPECT_GT(t.extrema, 1000);  // the adversarial cases were really generated
  // docs/model.md: "as tight as the exact range" up to the remainder: the Taylor
  // form is wider than the exact range by at most its two remainders (r^2) plus the
  // libm steps and the curvature the exact range loses near an extremum (r^2 / 2).
  EXPECT_LE(t.worst_excess, 1.6) << t.worst_input;
}

TEST(EulerSinCosOracle, TheConstantsPiHalfPiAndTwoPiEncloseTheRealConstants) {
  Mpfr pi;
  mpfr_const_pi(pi, MPFR_RNDN);
  const struct {
    Interval enclosure;
    double factor;
  } constants[] = {{Interval::pi(), 1.0}, {Interval::half_pi(), 0.5}, {Interval::two_pi(), 2.0}};
  for (const auto& c : constants) {
    Mpfr v;
    mpfr_mul_d(v, pi, c.factor, MPFR_RNDN);  // exact: a power of two
    EXPECT_GT(mpfr_cmp_d(v, c.enclosure.lo()), 0) << c.factor;  // pi is irrational: strictly inside
    EXPECT_LT(mpfr_cmp_d(v, c.enclosure.hi()), 0) << c.factor;
    EXPECT_EQ(std::nextafter(c.enclosure.lo(), kInf), c.enclosure.hi()) << "one ulp wide";
  }
}

}  // namespace
}  // namespace gesmi
