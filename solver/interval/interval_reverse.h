#pragma once
// Reverse (backward) operators: the building blocks of forward-backward contractors.
//
// bwd_f(y, x...) narrows each argument x to the hull of its values for which
// f(x...) can lie in y, given the other arguments. It never enlarges an argument,
// and returns false when one became empty (then all are set empty).
// The 1788-style names (sqr_rev, mul_rev_to_pair, ...) are the same operations
// with the argument order of IEEE Std 1788-2015.

#include <utility>

#include "solver/interval/interval.h"

namespace gesmi {

bool bwd_add(const Interval& y, Interval& x1, Interval& x2);  // y = x1 + x2
bool bwd_sub(const Interval& y, Interval& x1, Interval& x2);  // y = x1 - x2
bool bwd_mul(const Interval& y, Interval& x1, Interval& x2);  // y = x1 * x2
bool bwd_div(const Interval& y, Interval& x1, Interval& x2);  // y = x1 / x2
bool bwd_neg(const Interval& y, Interval& x);                 // y = -x
bool bwd_sqr(const Interval& y, Interval& x);                 // y = x^2
bool bwd_sqrt(const Interval& y, Interval& x);                // y = sqrt(x)
bool bwd_pow(const Interval& y, Interval& x, int n);          // y = x^n
bool bwd_exp(const Interval& y, Interval& x);                 // y = exp(x)
bool bwd_log(const Interval& y, Interval& x);                 // y = log(x)
bool bwd_abs(const Interval& y, Interval& x);                 // y = |x|
bool bwd_sin(const Interval& y, Interval& x);                 // y = sin(x), periodic
bool bwd_cos(const Interval& y, Interval& x);                 // y = cos(x), periodic
bool bwd_tan(const Interval& y, Interval& x);                 // y = tan(x), periodic
bool bwd_atan(const Interval& y, Interval& x);                // y = atan(x)
bool bwd_atan2(const Interval& theta, Interval& y, Interval& x);  // theta = atan2(y, x)
bool bwd_min(const Interval& y, Interval& x1, Interval& x2);  // y = min(x1, x2)
bool bwd_max(const Interval& y, Interval& x1, Interval& x2);  // y = max(x1, x2)

/// {x : b*x = c for some b in B, c in C} as at most two intervals, lower one first
/// (IEEE 1788 mulRevToPair). The second is empty when one interval suffices.
std::pair<Interval, Interval> mul_rev_to_pair(const Interval& b, const Interval& c);
/// Hull of {x in X : b*x in C for some b in B} (IEEE 1788 mulRev).
Interval mul_rev(const Interval& b, const Interval& c, const Interval& x = Interval::entire());

// IEEE 1788 reverse functions: hull of {x in X : f(x) in C}.
Interval sqr_rev(const Interval& c, const Interval& x = Interval::entire());
Interval abs_rev(const Interval& c, const Interval& x = Interval::entire());
Interval pow_rev(const Interval& c, const Interval& x, int n);
Interval sin_rev(const Interval& c, const Interval& x = Interval::entire());
Interval cos_rev(const Interval& c, const Interval& x = Interval::entire());
Interval tan_rev(const Interval& c, const Interval& x = Interval::entire());

}  // namespace gesmi
