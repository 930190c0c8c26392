// Randomized oracle for the reverse operators: for 10^5 adversarial cases per
// operator, a point p in X (and q in X2) is drawn, MPFI encloses f(p) at 128 bits,
// Y is that enclosure rounded outward to doubles (often not widened at all, the
// hardest case), and bwd_f(Y, X) must keep p: p is a solution since f(p) is in Y.
// The result must also stay inside X (contractance).

#include <gtest/gtest.h>

#include <functional>

#include "solver/interval/interval_reverse.h"
#include "tests/oracle/mpfi_support.h"

namespace gesmi::oracle {
namespace {

using MpfiUnary = std::function<void(mpfi_ptr, mpfi_srcptr)>;
using MpfiBinary = std::function<void(mpfi_ptr, mpfi_srcptr, mpfi_srcptr)>;

// The oracle's enclosure of f(point...) as doubles, widened by a few random steps
// half of the time.
Interval tight_image(Adversary& adv, const Mpfi& image) {
  if (mpfi_nan_p(image.get())) return Interval::empty();
  double lo = image.lo_down(), hi = image.hi_up();
  if (adv.pick(2)) {
    lo = step_down(lo, adv.pick(4));
    hi = step_up(hi, adv.pick(4));
  }
  return Interval(lo, hi);
}

struct UnaryOp {
  const char* name;
  std::function<bool(const Interval&, Interval&)> backward;
  MpfiUnary image;
  std::function<double(Adversary&)> point;  // an adversarial point of the domain
};

void run(const UnaryOp& op) {
  Tally t{op.name};
  Adversary adv(kSeed ^ std::hash<std::string>{}(op.name));
  Mpfi in, out;
  for (int attempt = 0; t.cases < kCases && attempt < 2 * kCases; ++attempt) {
    const double p = op.point(adv);
    Interval x = adv.interval_from(adv.pick(2) ? p : adv.any(), adv.pick(2) ? p : adv.any());
    x = hull(x, p);  // x contains p
    in.set(Interval(p));
    op.image(out, in.get());
    const Interval y = tight_image(adv, out);
    if (y.is_empty()) continue;  // p outside the domain
    const Interval x0 = x;
    const bool ok = op.backward(y, x);
    t.check_kept(ok && x.contains(p) && x0.is_superset(x),
                 std::string(op.name) + " lost p = " + str(Interval(p)) + " from x = " + str(x0) + ", y = " + str(y) +
                     " -> " + str(x));
  }
  t.report();
  EXPECT_EQ(t.failures, 0) << t.first_failure;
}

double trig_point(Adversary& a) { return a.pick(3) ? a.near_half_pi_multiple() : a.any(); }
double non_negative_point(Adversary& a) { return a.pick(4) == 0 ? a.near(1.0, 64) : std::fabs(a.any()); }
double positive_point(Adversary& a) {  // the domain of log excludes 0
  const double v = non_negative_point(a);
  return v == 0.0 ? std::numeric_limits<double>::denorm_min() : v;
}

TEST(MpfiReverseOracle, UnaryReversesKeepEverySolution) {
  const UnaryOp ops[] = {
      {"bwd_sqr", bwd_sqr, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_sqr(r, x); }, [](Adversary& a) { return a.any(); }},
      {"bwd_sqrt", bwd_sqrt, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_sqrt(r, x); }, non_negative_point},
      {"bwd_abs", bwd_abs, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_abs(r, x); }, [](Adversary& a) { return a.any(); }},
      {"bwd_exp", bwd_exp, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_exp(r, x); },
       [](Adversary& a) { return a.pick(2) ? a.near(709.782712893384, 1 << 16) : a.any(); }},
      {"bwd_log", bwd_log, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_log(r, x); }, positive_point},
      {"bwd_sin", bwd_sin, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_sin(r, x); }, trig_point},
      {"bwd_cos", bwd_cos, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_cos(r, x); }, trig_point},
      {"bwd_tan", bwd_tan, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_tan(r, x); }, trig_point},
      {"bwd_atan", bwd_atan, [](mpfi_ptr r, mpfi_srcptr x) { mpfi_atan(r, x); }, [](Adversary& a) { return a.any(); }},
  };
  for (const UnaryOp& op : ops) run(op);
}

TEST(MpfiReverseOracle, PowerReverseKeepsEverySolution) {
  for (const int n : {-7, -4, -3, -2, -1, 2, 3, 4, 5, 8, 13}) {
    const std::string name = "bwd_pow" + std::to_string(n);
    const UnaryOp op{name.c_str(), [n](const Interval& y, Interval& x) { return bwd_pow(y, x, n); },
                     [n](mpfi_ptr r, mpfi_srcptr x) {
                       if (n < 0 && mpfr_zero_p(&x->left)) return mpfi_set_d(r, std::nan(""));  // 0^-n: no value
                       mpfr_pow_si(&r->left, &x->left, n, MPFR_RNDD);
                       mpfr_pow_si(&r->right, &x->left, n, MPFR_RNDU);
                       return 0;
                     },
                     [](Adversary& a) { return a.pick(2) ? a.any() : a.uniform(-4.0, 4.0); }};
    run(op);
  }
}

struct BinaryOp {
  const char* name;
  std::function<bool(const Interval&, Interval&, Interval&)> backward;
  MpfiBinary image;  // f(p, q), NaN outside the domain
};

void run(const BinaryOp& op) {
  Tally t{op.name};
  Adversary adv(kSeed ^ std::hash<std::string>{}(op.name));
  Mpfi a, b, out;
  for (int attempt = 0; t.cases < kCases && attempt < 2 * kCases; ++attempt) {
    const bool near_axes = adv.pick(4) == 0;  // for atan2: the axes and the cut
    const double p = near_axes ? adv.sign(adv.pick(3) ? 0.0 : adv.near(0.0, 4)) : adv.any();
    const double q = near_axes ? adv.uniform(-4.0, 4.0) : adv.any();
    const Interval x1 = hull(adv.interval(), p), x2 = hull(adv.interval(), q);
    a.set(Interval(p));
    b.set(Interval(q));
    op.image(out, a.get(), b.get());
    const Interval y = tight_image(adv, out);
    if (y.is_empty()) continue;
    Interval r1 = x1, r2 = x2;
    const bool ok = op.backward(y, r1, r2);
    t.check_kept(ok && r1.contains(p) && r2.contains(q) && x1.is_superset(r1) && x2.is_superset(r2),
                 std::string(op.name) + " lost (" + str(Interval(p)) + ", " + str(Interval(q)) + ") from " + str(x1) +
                     " x " + str(x2) + ", y = " + str(y) + " -> " + str(r1) + " x " + str(r2));
  }
  t.report();
  EXPECT_EQ(t.failures, 0) << t.first_failure;
}

TEST(MpfiReverseOracle, BinaryReversesKeepEverySolution) {
  const BinaryOp ops[] = {
      {"bwd_add", bwd_add, [](mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) { mpfi_add(r, x, y); }},
      {"bwd_sub", bwd_sub, [](mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) { mpfi_sub(r, x, y); }},
      {"bwd_mul", bwd_mul, [](mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) { mpfi_mul(r, x, y); }},
      {"bwd_div", bwd_div,
       [](mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) {
         if (mpfr_zero_p(&y->left)) return static_cast<void>(mpfi_set_d(r, std::nan("")));  // x / 0: no value
         mpfi_div(r, x, y);
       }},
      {"bwd_min", bwd_min,
       [](mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) { mpfi_set(r, mpfr_cmp(&x->left, &y->left) <= 0 ? x : y); }},
      {"bwd_max", bwd_max,
       [](mpfi_ptr r, mpfi_srcptr x, mpfi_srcptr y) { mpfi_set(r, mpfr_cmp(&x->left, &y->left) >= 0 ? x : y); }},
      {"bwd_atan2", bwd_atan2,
       [](mpfi_ptr r, mpfi_srcptr y, mpfi_srcptr x) {
         if (mpfr_zero_p(&y->left) && mpfr_zero_p(&x->left)) return static_cast<void>(mpfi_set_d(r, std::nan("")));
         mpfr_atan2(&r->left, &y->left, &x->left, MPFR_RNDD);  // y = +0 on the cut gives +pi
         mpfr_atan2(&r->right, &y->left, &x->left, MPFR_RNDU);
       }},
  };
  for (const BinaryOp& op : ops) run(op);
}

TEST(MpfiReverseOracle, MulRevToPairKeepsEverySolution) {
  Tally t{"mulRevPair"};
  Adversary adv(kSeed ^ 13);
  Mpfi a, b, out;
  for (int i = 0; i < kCases; ++i) {
    const double p = adv.any(), q = adv.any();
    const Interval bb = hull(adv.interval(), q);  // p * q in c for this q in b
    a.set(Interval(p));
    b.set(Interval(q));
    mpfi_mul(out, a.get(), b.get());
    const Interval c = tight_image(adv, out);
    const auto [first, second] = mul_rev_to_pair(bb, c);
    // Lower piece first; they may touch at 0 when c / b underflows (cl / bl = -0).
    const bool ordered = second.is_empty() || first.hi() <= second.lo();
    t.check_kept((first.contains(p) || second.contains(p)) && ordered,
                 "mul_rev_to_pair(" + str(bb) + ", " + str(c) + ") lost " + str(Interval(p)) + " or misordered");
  }
  t.report();
  EXPECT_EQ(t.failures, 0) << t.first_failure;
}

}  // namespace
}  // namespace gesmi::oracle
