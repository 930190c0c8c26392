// Randomized oracle for the forward interval operations: for 10^5 adversarial
// intervals per operation, gesmi's result must contain MPFI's enclosure of the
// exact range computed at 128 bits (MPFI rounds outward, so containing it means
// containing the exact range). The excess width over the oracle rounded outward
// to doubles is logged; + - * / sqr sqrt must be exact (0 ulps), being the
// correctly rounded directed results. Seed and figures are printed.

#include <gtest/gtest.h>

#include <functional>

#include "tests/oracle/mpfi_support.h"

namespace gesmi::oracle {
namespace {

using Unary = std::function<Interval(const Interval&)>;
using MpfiUnary = int (*)(mpfi_ptr, mpfi_srcptr);

// Runs a unary operation over `cases` intervals from `make`. The oracle sees x
// restricted to `domain` (the natural domain of the function, as in IEEE 1788).
void run_unary(Tally& t, const Unary& ours, MpfiUnary oracle, const std::function<Interval(Adversary&)>& make,
               const Interval& domain = Interval::entire(), bool open_at_zero = false) {
  Adversary adv(kSeed ^ std::hash<std::string>{}(t.name));
  t.start = std::chrono::steady_clock::now();
  Mpfi in, out;
  for (int i = 0; i < kCases; ++i) {
    const Interval x = make(adv);
    const Interval restricted = intersect(x, domain);
    const Interval result = ours(x);
    // The domain of log is open at 0: log([-1, 0]) is empty, not [-inf, -inf].
    if (restricted.is_empty() || (open_at_zero && restricted.hi() == 0.0)) {
      t.check_empty(result, str(x));
      continue;
    }
    in.set(restricted);
    oracle(out, in.get());
    t.check(result, out, str(x));
  }
  t.report();
}

Interval general(Adversary& a) { return a.interval(); }

TEST(MpfiForwardOracle, ArithmeticIsTheCorrectlyRoundedEnclosure) {
  struct Op {
    const char* name;
    std::function<Interval(const Interval&, const Interval&)> ours;
    int (*oracle)(mpfi_ptr, mpfi_srcptr, mpfi_srcptr);
  };
  const Op ops[] = {{"add", [](const Interval& x, const Interval& y) { return x + y; }, mpfi_add},
                    {"sub", [](const Interval& x, const Interval& y) { return x - y; }, mpfi_sub},
                    {"mul", [](const Interval& x, const Interval& y) { return x * y; }, mpfi_mul},
                    {"div", [](const Interval& x, const Interval& y) { return x / y; }, mpfi_div}};
  for (const Op& op : ops) {
    Tally t{op.name};
    Adversary adv(kSeed ^ std::hash<std::string>{}(op.name));
    Mpfi a, b, out;
    for (int i = 0; i < kCases; ++i) {
      Interval x = adv.interval(), y = adv.interval();
      if (adv.pick(4) == 0) y = adv.interval_from(adv.near(x.lo(), 3), x.hi());  // cancellation
      const Interval result = op.ours(x, y);
      const std::string input = str(x) + " " + op.name + " " + str(y);
      if (op.name == std::string("div") && y.lo() == 0.0 && y.hi() == 0.0) {
        t.check_empty(result, input);  // IEEE 1788: division by [0, 0] is empty
        continue;
      }
      if (op.name == std::string("div") && x.lo() == 0.0 && x.hi() == 0.0) {
        t.check(result, Mpfi(Interval(0.0)), input);  // 0 / y = 0 for every y != 0
        continue;
      }
      a.set(x);
      b.set(y);
      op.oracle(out, a.get(), b.get());
      t.check(result, out, input);
    }
    t.report();
    EXPECT_EQ(t.failures, 0) << op.name << ": " << t.first_failure;
    const bool exact = std::all_of(t.excess.begin(), t.excess.end(), [](double e) { return e == 0.0; });
    EXPECT_TRUE(exact) << op.name << ": not the correctly rounded enclosure";
  }
}

TEST(MpfiForwardOracle, SquareSquareRootAndAbsAreTight) {
  Tally sq{"sqr"};
  run_unary(sq, [](const Interval& x) { return sqr(x); }, mpfi_sqr, general);
  Tally rt{"sqrt"};
  run_unary(rt, [](const Interval& x) { return sqrt(x); }, mpfi_sqrt, general, Interval::pos_reals());
  Tally ab{"abs"};
  run_unary(ab, [](const Interval& x) { return abs(x); }, mpfi_abs, general);
  for (const Tally* t : {&sq, &rt, &ab}) {
    EXPECT_EQ(t->failures, 0) << t->name << ": " << t->first_failure;
    EXPECT_TRUE(std::all_of(t->excess.begin(), t->excess.end(), [](double e) { return e == 0.0; })) << t->name;
  }
}

// x^n for integer n by the monotonicity of t -> t^n on each sign, with MPFR's
// correctly rounded mpfr_pow_si at the end points (IEEE 1788 pown).
void oracle_pown(Mpfi& out, const Interval& x, long n) {
  const auto bound = [&](double t, mpfr_ptr r, mpfr_rnd_t rnd) {
    mpfr_set_d(r, t, MPFR_RNDN);
    mpfr_pow_si(r, r, n, rnd);
  };
  mpfr_ptr lo = &out.get()->left, hi = &out.get()->right;
  if (n == 0) return out.set(Interval(1.0));
  const bool even = n % 2 == 0, has_zero = x.contains(0.0);
  if (n > 0) {
    if (!even) return bound(x.lo(), lo, MPFR_RNDD), bound(x.hi(), hi, MPFR_RNDU);
    return bound(x.mig(), lo, MPFR_RNDD), bound(x.mag(), hi, MPFR_RNDU);
  }
  if (!has_zero || even) {  // decreasing in |t| on each side
    if (even) return bound(x.mag(), lo, MPFR_RNDD), bound(x.mig(), hi, MPFR_RNDU);
    return bound(x.hi(), lo, MPFR_RNDD), bound(x.lo(), hi, MPFR_RNDU);
  }
  // Odd negative power over an interval containing 0 (not [0, 0]).
  if (x.lo() < 0.0 && x.hi() > 0.0) return out.set(Interval::entire());
  if (x.lo() == 0.0) return bound(x.hi(), lo, MPFR_RNDD), mpfr_set_inf(hi, 1);
  return mpfr_set_inf(lo, -1), bound(x.lo(), hi, MPFR_RNDU);
}

TEST(MpfiForwardOracle, IntegerPowerEnclosesTheRange) {
  Tally t{"pown"};
  Adversary adv(kSeed ^ 7);
  Mpfi out;
  for (int i = 0; i < kCases; ++i) {
    const Interval x = adv.pick(2) ? adv.interval() : adv.interval_from(adv.uniform(-3.0, 3.0), adv.uniform(-3.0, 3.0));
    const int n = adv.pick(5) == 0 ? adv.pick(2001) - 1000 : adv.pick(17) - 8;
    const Interval result = pow(x, n);
    const std::string input = str(x) + " ^ " + std::to_string(n);
    if (n < 0 && x.lo() == 0.0 && x.hi() == 0.0) {
      t.check_empty(result, input);
      continue;
    }
    oracle_pown(out, x, n);
    t.check(result, out, input);
  }
  t.report();
  EXPECT_EQ(t.failures, 0) << t.first_failure;
}

TEST(MpfiForwardOracle, ExpAndLogEncloseTheRangeNearOverflowAndOne) {
  Tally e{"exp"};
  run_unary(e, [](const Interval& x) { return exp(x); }, mpfi_exp, [](Adversary& a) {
    switch (a.pick(4)) {
      case 0: return a.interval_from(a.near(709.782712893384, 1 << 20), a.uniform(709.0, 710.0));  // overflow
      case 1: return a.interval_from(a.near(-745.1332191019412, 1 << 20), a.uniform(-746.0, -700.0));  // underflow
      case 2: return a.interval_from(a.uniform(-800.0, 800.0), a.uniform(-800.0, 800.0));
      default: return a.interval();
    }
  });
  Tally l{"log"};
  run_unary(l, [](const Interval& x) { return log(x); }, mpfi_log, [](Adversary& a) {
    switch (a.pick(3)) {
      case 0: return a.interval_from(a.near(1.0, 64), a.near(1.0, 64));  // log near 1: tiny results
      case 1: return a.interval_from(std::fabs(a.any()), std::fabs(a.any()));
      default: return a.interval();
    }
  }, Interval::pos_reals(), true);
  for (const Tally* t : {&e, &l}) {
    EXPECT_EQ(t->failures, 0) << t->name << ": " << t->first_failure;
  }
}

Interval trig_argument(Adversary& a) {
  switch (a.pick(4)) {
    case 0: return a.interval_from(a.near_half_pi_multiple(), a.near_half_pi_multiple());
    case 1: {
      const double c = a.near_half_pi_multiple();  // a narrow interval around a critical point
      // Named first: std::minmax on temporaries returns references to them.
      const double p = a.near(c, 8), q = a.near(c, 8);
      return Interval(std::min(p, q), std::max(p, q));
    }
    case 2: return a.interval_from(a.near(a.pick(2) ? 3.141592653589793 : -3.141592653589793, 16), a.uniform(-4, 4));
    default: return a.interval();
  }
}

TEST(MpfiForwardOracle, SinCosTanEncloseTheRangeNearMultiplesOfHalfPi) {
  Tally s{"sin"}, c{"cos"}, tn{"tan"};
  run_unary(s, [](const Interval& x) { return sin(x); }, mpfi_sin, trig_argument);
  run_unary(c, [](const Interval& x) { return cos(x); }, mpfi_cos, trig_argument);
  run_unary(tn, [](const Interval& x) { return tan(x); }, mpfi_tan, trig_argument);
  for (const Tally* t : {&s, &c, &tn}) {
    EXPECT_EQ(t->failures, 0) << t->name << ": " << t->first_failure;
  }
}

TEST(MpfiForwardOracle, AtanEnclosesTheRange) {
  Tally t{"atan"};
  run_unary(t, [](const Interval& x) { return atan(x); }, mpfi_atan, general);
  EXPECT_EQ(t.failures, 0) << t.first_failure;
}

TEST(MpfiForwardOracle, Atan2EnclosesTheRangeInEveryQuadrantAndAtTheCut) {
  Tally t{"atan2"};
  Adversary adv(kSeed ^ 11);
  Mpfi a, b, out;
  mpfr_t py, px, angle;
  mpfr_inits2(kPrecision, py, px, angle, static_cast<mpfr_ptr>(nullptr));
  for (int i = 0; i < kCases; ++i) {
    Interval y = adv.interval(), x = adv.interval();
    if (adv.pick(3) == 0) {  // around the axes and the cut y = 0, x < 0
      y = adv.interval_from(adv.sign(adv.pick(2) ? 0.0 : adv.near(0.0, 3)), adv.uniform(-1.0, 1.0));
      x = adv.interval_from(adv.uniform(-5.0, 1.0), adv.uniform(-5.0, 1.0));
    }
    const Interval result = atan2(y, x);
    const std::string input = "atan2(" + str(y) + ", " + str(x) + ")";
    // Around the origin MPFI gives [-pi, pi], and on the cut y = [0, ...] with x < 0
    // it allows -pi; IEEE 1788 excludes the origin and gives atan2(0, x < 0) = +pi.
    // There, sampled points are checked instead.
    if ((y.contains(0.0) && x.contains(0.0)) || (y.lo() == 0.0 && x.lo() < 0.0)) {
      if (y.lo() == 0.0 && y.hi() == 0.0 && x.lo() == 0.0 && x.hi() == 0.0) {
        t.check_empty(result, input);
        continue;
      }
      // MPFI gives [-pi, pi] around the origin; IEEE 1788 excludes the origin, so
      // check sampled points instead (and the cut, where y = +0 means +pi).
      bool ok = !result.is_empty();
      for (int k = 0; k < 8 && ok; ++k) {
        const double py_d = adv.point(y), px_d = adv.point(x);
        if (py_d == 0.0 && px_d == 0.0) continue;
        mpfr_set_d(py, py_d == 0.0 ? 0.0 : py_d, MPFR_RNDN);
        mpfr_set_d(px, px_d, MPFR_RNDN);
        mpfr_atan2(angle, py, px, MPFR_RNDN);
        ok = mpfr_cmp_d(angle, result.lo()) >= 0 && mpfr_cmp_d(angle, result.hi()) <= 0;
      }
      t.check_kept(ok, input + " -> " + str(result));
      continue;
    }
    if (y.lo() < 0.0 && y.hi() == 0.0 && x.hi() < 0.0) {
      // The cut from below: y -> 0- gives -pi in the limit and y = 0 gives +pi, so
      // the range is exactly [-pi, pi]. MPFI returns an inverted interval here.
      mpfi_const_pi(a);
      mpfi_neg(b, a);
      mpfi_union(out, b, a);
      t.check(result, out, input);
      continue;
    }
    a.set(y);
    b.set(x);
    mpfi_atan2(out, a.get(), b.get());
    t.check(result, out, input);
  }
  mpfr_clears(py, px, angle, static_cast<mpfr_ptr>(nullptr));
  t.report();
  EXPECT_EQ(t.failures, 0) << t.first_failure;
}

}  // namespace
}  // namespace gesmi::oracle
