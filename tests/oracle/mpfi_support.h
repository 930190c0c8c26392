#pragma once
// Shared pieces of the MPFI oracle tests: an RAII MPFI interval, conversion from
// gesmi::Interval (exact: every double is an MPFR number), the containment check
// and its tightness measure, and an adversarial generator of doubles and
// intervals (huge and tiny magnitudes, subnormals, signed zeros, infinities,
// values near multiples of pi/2, near +-pi, near the overflow of exp, near 1).

#include <mpfi.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "solver/interval/interval.h"
#include "tests/oracle/mpfr_number.h"  // kPrecision

namespace gesmi::oracle {

inline constexpr std::uint64_t kSeed = 0x6765736d69ULL;  // "gesmi"
inline constexpr int kCases = 100000;                    // per operation

class Mpfi {
 public:
  Mpfi() { mpfi_init2(x_, kPrecision); }
  explicit Mpfi(const Interval& v) : Mpfi() { set(v); }
  Mpfi(const Mpfi&) = delete;
  Mpfi& operator=(const Mpfi&) = delete;
  ~Mpfi() { mpfi_clear(x_); }
  /// Exact: the bounds of a non-empty Interval are doubles or infinities.
  void set(const Interval& v) {
    mpfr_set_d(&x_->left, v.lo() == 0.0 ? 0.0 : v.lo(), MPFR_RNDD);  // -0 is 0: no sign games
    mpfr_set_d(&x_->right, v.hi() == 0.0 ? 0.0 : v.hi(), MPFR_RNDU);
  }
  mpfi_ptr get() { return x_; }
  mpfi_srcptr get() const { return x_; }
  operator mpfi_ptr() { return x_; }  // NOLINT: reads like the C API
  double lo_down() const { return mpfr_get_d(&x_->left, MPFR_RNDD); }
  double hi_up() const { return mpfr_get_d(&x_->right, MPFR_RNDU); }

 private:
  mpfi_t x_;
};

inline std::int64_t ordinal(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
}
inline double ulps(double a, double b) {  // steps from a up to b (negative when b < a)
  if (a == b) return 0.0;
  if (std::isinf(a) || std::isinf(b)) return kInf;
  if (b < a) return -ulps(b, a);
  // Up to 2^64 - 2 steps between the finite doubles: the difference of the ordinals
  // overflows int64 but is exact in uint64 (modular, and it is non-negative here).
  return static_cast<double>(static_cast<std::uint64_t>(ordinal(b)) - static_cast<std::uint64_t>(ordinal(a)));
}

inline std::string str(const Interval& x) {
  if (x.is_empty()) return "[empty]";
  char b[96];
  std::snprintf(b, sizeof b, "[%a, %a]", x.lo(), x.hi());
  return b;
}

/// Results of one operation: cases, containment failures, excess width in ulps
/// over the oracle rounded outward to doubles, and the first failure.
struct Tally {
  explicit Tally(std::string operation) : name(std::move(operation)) {}
  std::string name;
  int cases = 0, failures = 0;
  std::vector<double> excess;
  std::string first_failure;
  double worst_excess = 0.0;
  std::string worst_input;  // printed when wider than a few libm steps
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  /// ours must contain the oracle's enclosure of the exact range.
  void check(const Interval& ours, const Mpfi& oracle, const std::string& input) {
    ++cases;
    // An inverted oracle (left > right) would accept almost any result.
    if (mpfi_is_empty(oracle.get())) return fail(input + " -> " + str(ours) + ": the oracle gave no enclosure");
    const bool ok = !ours.is_empty() && mpfr_cmp_d(&oracle.get()->left, ours.lo()) >= 0 &&
                    mpfr_cmp_d(&oracle.get()->right, ours.hi()) <= 0;
    if (!ok) return fail(input + " -> " + str(ours) + ", oracle [" + std::to_string(oracle.lo_down()) + ", " +
                         std::to_string(oracle.hi_up()) + "]");
    excess.push_back(ulps(ours.lo(), oracle.lo_down()) + ulps(oracle.hi_up(), ours.hi()));
    if (excess.back() > worst_excess) {
      worst_excess = excess.back();
      worst_input = input + " -> " + str(ours) + ", oracle " + str(Interval(oracle.lo_down(), oracle.hi_up()));
    }
  }
  /// The exact result is empty: ours must be too.
  void check_empty(const Interval& ours, const std::string& input) {
    ++cases;
    if (!ours.is_empty()) fail(input + " -> " + str(ours) + ", expected empty");
  }
  /// A point that must stay (reverse operators).
  void check_kept(bool kept, const std::string& input) {
    ++cases;
    if (!kept) fail(input);
  }
  void fail(const std::string& what) {
    if (failures++ == 0) first_failure = what;
  }
  /// One line for the log (docs/intervals.md quotes these figures).
  void report() const {
    std::vector<double> e = excess;
    std::sort(e.begin(), e.end());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string widths;
    if (!e.empty()) {
      const auto text = [](double u) {  // up to 2^64 ulps: past long long, printed as a double
        char b[32];
        std::snprintf(b, sizeof b, "%.0f", u);
        return std::isinf(u) ? std::string("inf") : std::string(b);
      };
      widths = ", excess median " + text(e[e.size() / 2]) + " max " + text(e.back()) + " ulps";
    }
    std::printf("oracle %-10s %7d cases, %d failures%s, %.2f s (seed %#llx)\n", name.c_str(), cases, failures,
                widths.c_str(), seconds, static_cast<unsigned long long>(kSeed));
    if (worst_excess > 4 * kLibmSteps) std::printf("  widest: %s\n", worst_input.c_str());
  }
};

/// Adversarial doubles and intervals.
class Adversary {
 public:
  explicit Adversary(std::uint64_t seed) : rng_(seed) {}

  std::uint64_t bits() { return rng_(); }
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int pick(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }
  double sign(double x) { return rng_() & 1 ? -x : x; }

  /// center (finite) moved by up to max_steps doubles either way, clamped to the
  /// finite doubles.
  double near(double center, int max_steps) {
    const std::int64_t k = pick(2 * max_steps + 1) - max_steps;
    constexpr std::int64_t kTop = 0x7FEFFFFFFFFFFFFFLL;  // ordinal of the largest double
    const std::int64_t o = std::clamp(ordinal(center) + k, -kTop, kTop);
    return o >= 0 ? std::bit_cast<double>(o) : -std::bit_cast<double>(-o);
  }

  /// A double from a mixture of ordinary and extreme magnitudes.
  double any() {
    constexpr double kMax = std::numeric_limits<double>::max();
    switch (pick(10)) {
      case 0: return uniform(-10.0, 10.0);
      case 1: {  // any finite double, every exponent equally likely
        double x;
        do x = std::bit_cast<double>(rng_()); while (!std::isfinite(x));
        return x;
      }
      case 2: return sign(near(kMax, 1000) * (pick(2) ? 1.0 : uniform(0.5, 1.0)));
      case 3: return sign(std::ldexp(uniform(1.0, 2.0), -1022 + pick(8)));             // tiny normal
      case 4: return sign(std::bit_cast<double>(rng_() & 0x000FFFFFFFFFFFFFULL));       // subnormal
      case 5: return pick(2) ? 0.0 : -0.0;
      case 6: return static_cast<double>(pick(21) - 10);
      case 7: return sign(std::ldexp(uniform(1.0, 2.0), pick(2000) - 1000));
      default: return uniform(-1e3, 1e3);
    }
  }

  /// k * pi/2 rounded, moved a few steps: where sin, cos and tan change behaviour.
  double near_half_pi_multiple() {
    double k;
    switch (pick(4)) {
      case 0: k = pick(9) - 4; break;                              // around 0, +-pi/2, +-pi, ...
      case 1: k = pick(2001) - 1000; break;
      case 2: k = std::ldexp(static_cast<double>(rng_() >> 12), -pick(40)); break;  // up to 2^52
      default: k = std::round(uniform(-1e15, 1e15)); break;
    }
    return near(k * 1.5707963267948966, 4);
  }

  /// An interval starting at a: degenerate, a few ulps, small, wide or up to b.
  Interval interval_from(double a, double b) {
    double lo = a, hi;
    switch (pick(6)) {
      case 0: hi = a; break;
      case 1: hi = step_up(a, pick(8) + 1); break;
      case 2: hi = a + std::fabs(a) * std::ldexp(uniform(0.0, 1.0), -pick(50)) + std::ldexp(1.0, -pick(1074)); break;
      case 3: hi = a + uniform(0.0, 10.0); break;
      default: hi = b; break;
    }
    if (hi < lo) std::swap(lo, hi);
    if (std::isnan(hi) || hi == -kInf) hi = lo;
    if (pick(20) == 0) lo = -kInf;
    if (pick(20) == 0) hi = kInf;
    return Interval(lo, hi);
  }
  Interval interval() { return interval_from(any(), any()); }

  /// A point of x (finite), often an end point.
  double point(const Interval& x) {
    const double lo = std::max(x.lo(), -std::numeric_limits<double>::max());
    const double hi = std::min(x.hi(), std::numeric_limits<double>::max());
    switch (pick(4)) {
      case 0: return lo;
      case 1: return hi;
      default: {
        const double t = lo + (hi - lo) * uniform(0.0, 1.0);  // may overflow for huge spans
        return std::isfinite(t) ? std::clamp(t, lo, hi) : (pick(2) ? lo : hi);
      }
    }
  }

 private:
  std::mt19937_64 rng_;
};

}  // namespace gesmi::oracle
