// Upward-rounding sweep kernels. This file is compiled with -frounding-math (see
// solver/CMakeLists.txt) so that the compiler neither folds nor reorders floating
// point operations under a round-to-nearest assumption. The loops are in separate
// non-inlined functions, so every load and store of the arrays (hence every
// operation on them) happens between the two mode switches.
//
// In upward mode a + b and a - b are rounded up; a lower bound RD(a + b) is
// obtained exactly as -((-a) - b). Intersection is max/min of the bounds; an
// empty result (lo > hi) stops the sweep and is normalised by the caller.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "solver/interval/upward_rounding.h"
#include "solver/tube/chain_sweep.h"

namespace gesmi {
namespace {

constexpr int kChains = 3;

// The arrays of the three chains (v const for the forward sweep).
template <class Step>
struct ChainArrays {
  Interval* x[kChains];
  Step* v[kChains];
};

// The loop-carried values are the negated lower bound and the upper bound, so the
// dependency chain is one rounded-up addition and one min per step. The largest
// narrowing of a bound is tracked off that chain (a NaN from inf - inf is ignored
// by std::max's argument order).
[[gnu::noinline]] std::size_t full_forward_loop(Interval* x, const Interval* v, std::size_t n, double& max_shrink) {
  double neg_lo = -x[0].lo(), hi = x[0].hi();
  double shrink = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Interval old = x[k + 1];
    neg_lo = std::min(-old.lo(), neg_lo - v[k].lo());  // -max(lo', RD(lo + v.lo))
    hi = std::min(old.hi(), hi + v[k].hi());           // min(hi', RU(hi + v.hi))
    x[k + 1] = Interval::from_bounds(-neg_lo, hi);
    shrink = std::max(shrink, std::max(-neg_lo - old.lo(), old.hi() - hi));
    if (!(-neg_lo <= hi)) {
      max_shrink = kInf;
      return k + 1;
    }
  }
  max_shrink = shrink;
  return SweepResult::kNone;
}

[[gnu::noinline]] std::size_t full_backward_loop(Interval* x, Interval* v, std::size_t n, double& max_shrink) {
  double neg_lo = -x[n - 1].lo(), hi = x[n - 1].hi();
  double shrink = 0.0;
  for (std::size_t k = n - 1; k-- > 0;) {
    const double next_neg_lo = neg_lo, next_hi = hi;
    const Interval old = x[k];
    neg_lo = std::min(-old.lo(), next_neg_lo + v[k].hi());  // -max(lo, RD(next.lo - v.hi))
    hi = std::min(old.hi(), next_hi - v[k].lo());           // min(hi, RU(next.hi - v.lo))
    x[k] = Interval::from_bounds(-neg_lo, hi);
    shrink = std::max(shrink, std::max(-neg_lo - old.lo(), old.hi() - hi));
    const double step_lo = std::max(v[k].lo(), -(hi + next_neg_lo));  // RD(next.lo - hi)
    const double step_hi = std::min(v[k].hi(), next_hi + neg_lo);      // RU(next.hi - lo)
    v[k] = Interval::from_bounds(step_lo, step_hi);
    if (!(-neg_lo <= hi) || !(step_lo <= step_hi)) {
      max_shrink = kInf;
      return k;
    }
  }
  max_shrink = shrink;
  return SweepResult::kNone;
}

// One chain's step of the joint loops below, full or over marked steps (one piece of
// code for both). Forward: x(k+1) := x(k+1) ∩ (x(k) + v(k)), x(k) carried as (-lo, hi),
// which become x(k+1)'s. Returns whether x(k+1) moved; `empty` when it emptied.
[[gnu::always_inline]] inline bool forward_step(double& neg_lo, double& hi, Interval& next, const Interval& step,
                                                double& shrink, bool& empty) {
  const Interval old = next;
  neg_lo = std::min(-old.lo(), neg_lo - step.lo());  // -max(lo', RD(lo + v.lo))
  hi = std::min(old.hi(), hi + step.hi());           // min(hi', RU(hi + v.hi))
  next = Interval::from_bounds(-neg_lo, hi);
  shrink = std::max(shrink, std::max(-neg_lo - old.lo(), old.hi() - hi));
  empty = !(-neg_lo <= hi);
  return (-neg_lo != old.lo()) | (hi != old.hi());
}

// Backward: x(k) := x(k) ∩ (x(k+1) - v(k)) then v(k) := v(k) ∩ (x(k+1) - x(k)), x(k+1)
// carried as (-lo, hi), which become x(k)'s. Sets whether x(k) and v(k) moved, and
// `empty` when either emptied.
[[gnu::always_inline]] inline void backward_step(double& neg_lo, double& hi, Interval& here, Interval& step,
                                                 double& shrink, bool& empty, bool& here_moved, bool& step_moved) {
  const double next_neg_lo = neg_lo, next_hi = hi;
  const Interval old = here, old_step = step;
  neg_lo = std::min(-old.lo(), next_neg_lo + old_step.hi());  // -max(lo, RD(next.lo - v.hi))
  hi = std::min(old.hi(), next_hi - old_step.lo());           // min(hi, RU(next.hi - v.lo))
  here = Interval::from_bounds(-neg_lo, hi);
  shrink = std::max(shrink, std::max(-neg_lo - old.lo(), old.hi() - hi));
  const double step_lo = std::max(old_step.lo(), -(hi + next_neg_lo));  // RD(next.lo - hi)
  const double step_hi = std::min(old_step.hi(), next_hi + neg_lo);      // RU(next.hi - lo)
  step = Interval::from_bounds(step_lo, step_hi);
  empty = !(-neg_lo <= hi) || !(step_lo <= step_hi);
  here_moved = (-neg_lo != old.lo()) | (hi != old.hi());
  step_moved = (step_lo != old_step.lo()) | (step_hi != old_step.hi());
}

// The three chains of a tube swept in one loop: the same operations, chain by chain,
// as the loops above, but the three chains' loop-carried dependencies overlap (each
// chain's narrowing tracked apart, so that no dependency runs across them). Stops at
// the first step where some chain emptied and sets that step's chains in `emptied`.
[[gnu::noinline]] std::size_t forward_loop3(const ChainArrays<const Interval>& c, std::size_t n, double (&max_shrink)[kChains],
                                            unsigned& emptied) {
  Interval* x[kChains] = {c.x[0], c.x[1], c.x[2]};  // (copies: not reloaded after each store)
  const Interval* v[kChains] = {c.v[0], c.v[1], c.v[2]};
  double neg_lo[kChains], hi[kChains], shrink[kChains];
  for (int a = 0; a < kChains; ++a) {
    neg_lo[a] = -x[a][0].lo();
    hi[a] = x[a][0].hi();
    shrink[a] = 0.0;
  }
  for (std::size_t k = 0; k + 1 < n; ++k) {
    unsigned empty_now = 0;
#pragma GCC unroll 3
    for (int a = 0; a < kChains; ++a) {
      bool empty;
      forward_step(neg_lo[a], hi[a], x[a][k + 1], v[a][k], shrink[a], empty);
      empty_now |= static_cast<unsigned>(empty) << a;
    }
    if (empty_now != 0) {
      emptied = empty_now;
      return k + 1;
    }
  }
  for (int a = 0; a < kChains; ++a) max_shrink[a] = shrink[a];
  return SweepResult::kNone;
}

[[gnu::noinline]] std::size_t backward_loop3(const ChainArrays<Interval>& c, std::size_t n, double (&max_shrink)[kChains],
                                             unsigned& emptied) {
  Interval* x[kChains] = {c.x[0], c.x[1], c.x[2]};  // (copies: not reloaded after each store)
  Interval* v[kChains] = {c.v[0], c.v[1], c.v[2]};
  double neg_lo[kChains], hi[kChains], shrink[kChains];
  for (int a = 0; a < kChains; ++a) {
    neg_lo[a] = -x[a][n - 1].lo();
    hi[a] = x[a][n - 1].hi();
    shrink[a] = 0.0;
  }
  for (std::size_t k = n - 1; k-- > 0;) {
    unsigned empty_now = 0;
#pragma GCC unroll 3
    for (int a = 0; a < kChains; ++a) {
      bool empty, here_moved, step_moved;
      backward_step(neg_lo[a], hi[a], x[a][k], v[a][k], shrink[a], empty, here_moved, step_moved);
      empty_now |= static_cast<unsigned>(empty) << a;
    }
    if (empty_now != 0) {
      emptied = empty_now;
      return k;
    }
  }
  for (int a = 0; a < kChains; ++a) max_shrink[a] = shrink[a];
  return SweepResult::kNone;
}

// The joint loops over the steps StepsToSweep marks (steps_to_sweep.h): from each
// marked step, a run of the same operations as the loops above goes on while it narrows
// a position (that carries into the next step) or reaches a marked step; between runs,
// memchr finds the next mark. A step taken clears its mark; a narrowed position marks
// the steps of the other direction that read it.

// The first marked step at or after `from` (of `steps`), or `steps`.
std::size_t next_marked(const std::uint8_t* marks, std::size_t from, std::size_t steps) {
  if (from >= steps) return steps;
  const void* found = std::memchr(marks + from, 1, steps - from);
  return found ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(found) - marks) : steps;
}

// One past the last marked step before `end`, or 0.
std::size_t end_of_marked(const std::uint8_t* marks, std::size_t end) {
  if (end == 0) return 0;
  const void* found = memrchr(marks, 1, end);
  return found ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(found) - marks) + 1 : 0;
}

[[gnu::noinline]] std::size_t marked_forward_loop3(const ChainArrays<const Interval>& c, std::size_t n,
                                                   std::uint8_t* take, std::uint8_t* take_backward,
                                                   double (&max_shrink)[kChains], unsigned& emptied) {
  Interval* x[kChains] = {c.x[0], c.x[1], c.x[2]};
  const Interval* v[kChains] = {c.v[0], c.v[1], c.v[2]};
  double shrink[kChains] = {0.0, 0.0, 0.0};
  const std::size_t steps = n - 1;
  for (std::size_t k = next_marked(take, 0, steps); k < steps; k = next_marked(take, k, steps)) {
    double neg_lo[kChains], hi[kChains];
    for (int a = 0; a < kChains; ++a) {
      neg_lo[a] = -x[a][k].lo();
      hi[a] = x[a][k].hi();
    }
    for (;;) {
      take[k] = 0;
      unsigned empty_now = 0;
      bool narrowed = false;
#pragma GCC unroll 3
      for (int a = 0; a < kChains; ++a) {
        bool empty;
        narrowed |= forward_step(neg_lo[a], hi[a], x[a][k + 1], v[a][k], shrink[a], empty);
        empty_now |= static_cast<unsigned>(empty) << a;
      }
      if (empty_now != 0) {
        emptied = empty_now;
        return k + 1;
      }
      ++k;
      if (narrowed) {  // x(k) now: backward steps k - 1 and k read it (step `steps`: the spare)
        take_backward[k - 1] = 1;
        take_backward[k] = 1;
      }
      if (k == steps || !(narrowed || take[k])) break;
    }
  }
  for (int a = 0; a < kChains; ++a) max_shrink[a] = shrink[a];
  return SweepResult::kNone;
}

[[gnu::noinline]] std::size_t marked_backward_loop3(const ChainArrays<Interval>& c, std::size_t n,
                                                    std::uint8_t* take, std::uint8_t* take_forward,
                                                    double (&max_shrink)[kChains], unsigned& emptied) {
  Interval* x[kChains] = {c.x[0], c.x[1], c.x[2]};
  Interval* v[kChains] = {c.v[0], c.v[1], c.v[2]};
  double shrink[kChains] = {0.0, 0.0, 0.0};
  for (std::size_t end = end_of_marked(take, n - 1); end > 0; end = end_of_marked(take, end)) {
    std::size_t k = end - 1;
    double neg_lo[kChains], hi[kChains];
    for (int a = 0; a < kChains; ++a) {
      neg_lo[a] = -x[a][k + 1].lo();
      hi[a] = x[a][k + 1].hi();
    }
    for (;;) {
      take[k] = 0;
      unsigned empty_now = 0;
      bool narrowed = false, step_narrowed = false;
#pragma GCC unroll 3
      for (int a = 0; a < kChains; ++a) {
        bool empty, here_moved, step_moved;
        backward_step(neg_lo[a], hi[a], x[a][k], v[a][k], shrink[a], empty, here_moved, step_moved);
        narrowed |= here_moved;
        step_narrowed |= step_moved;
        empty_now |= static_cast<unsigned>(empty) << a;
      }
      if (empty_now != 0) {
        emptied = empty_now;
        return k;
      }
      if (narrowed || step_narrowed) take_forward[k] = 1;  // forward step k reads x(k) and v(k)
      if (k == 0) {
        end = 0;
        break;
      }
      --k;
      if (!(narrowed || take[k])) {  // (a narrowed x(k + 1) carries into step k)
        end = k + 1;
        break;
      }
    }
  }
  for (int a = 0; a < kChains; ++a) max_shrink[a] = shrink[a];
  return SweepResult::kNone;
}

// Work-list spreads: the same steps, ending at the first step whose bounds moved
// by no more than stop_below. Kept apart from the full sweeps, whose loop the
// compiler schedules better without the extra exit (measured: 2.5 vs 5+ ns/step).
[[gnu::noinline]] SweepResult spread_forward_loop(Interval* x, const Interval* v, std::size_t from, std::size_t n,
                                           double stop_below) {
  SweepResult r;
  r.last = n - 1;
  double neg_lo = -x[from].lo(), hi = x[from].hi();
  double shrink = 0.0;
  for (std::size_t k = from; k + 1 < n; ++k) {
    const Interval old = x[k + 1];
    neg_lo = std::min(-old.lo(), neg_lo - v[k].lo());  // -max(lo', RD(lo + v.lo))
    hi = std::min(old.hi(), hi + v[k].hi());           // min(hi', RU(hi + v.hi))
    x[k + 1] = Interval::from_bounds(-neg_lo, hi);
    const double step_shrink = std::max(-neg_lo - old.lo(), old.hi() - hi);
    shrink = std::max(shrink, step_shrink);
    if (!(-neg_lo <= hi)) {
      r.first_empty = r.last = k + 1;
      r.max_shrink = kInf;
      return r;
    }
    if (!(step_shrink > stop_below)) {
      r.last = k + 1;
      break;
    }
  }
  r.max_shrink = shrink;
  return r;
}

[[gnu::noinline]] SweepResult spread_backward_loop(Interval* x, Interval* v, std::size_t from, double stop_below) {
  SweepResult r;
  r.last = 0;
  double neg_lo = -x[from].lo(), hi = x[from].hi();
  double shrink = 0.0;
  for (std::size_t k = from; k-- > 0;) {
    const double next_neg_lo = neg_lo, next_hi = hi;
    const Interval old = x[k];
    neg_lo = std::min(-old.lo(), next_neg_lo + v[k].hi());  // -max(lo, RD(next.lo - v.hi))
    hi = std::min(old.hi(), next_hi - v[k].lo());           // min(hi, RU(next.hi - v.lo))
    x[k] = Interval::from_bounds(-neg_lo, hi);
    const double step_shrink = std::max(-neg_lo - old.lo(), old.hi() - hi);
    shrink = std::max(shrink, step_shrink);
    const double step_lo = std::max(v[k].lo(), -(hi + next_neg_lo));  // RD(next.lo - hi)
    const double step_hi = std::min(v[k].hi(), next_hi + neg_lo);      // RU(next.hi - lo)
    v[k] = Interval::from_bounds(step_lo, step_hi);
    if (!(-neg_lo <= hi) || !(step_lo <= step_hi)) {
      r.first_empty = r.last = k;
      r.max_shrink = kInf;
      return r;
    }
    if (!(step_shrink > stop_below)) {
      r.last = k;
      break;
    }
  }
  r.max_shrink = shrink;
  return r;
}

void normalize_at(std::span<Interval> x, std::span<Interval> v, std::size_t k) {
  if (k == SweepResult::kNone) return;
  if (k < x.size() && x[k].is_empty()) x[k] = Interval::empty();
  if (k < v.size() && v[k].is_empty()) v[k] = Interval::empty();
}

SweepResult spread_forward(std::span<Interval> x, std::span<const Interval> v, std::size_t from, double stop_below) {
  if (from + 1 >= x.size()) return SweepResult{SweepResult::kNone, 0.0, from};
  if (x[from].is_empty()) return SweepResult{from, kInf, from};
  SweepResult result;
  {
    UpwardRounding upward;
    result = spread_forward_loop(x.data(), v.data(), from, x.size(), stop_below);
  }
  normalize_at(x, {}, result.first_empty);
  return result;
}

SweepResult spread_backward(std::span<Interval> x, std::span<Interval> v, std::size_t from, double stop_below) {
  if (from == 0 || from >= x.size()) return SweepResult{SweepResult::kNone, 0.0, 0};
  if (x[from].is_empty()) return SweepResult{from, kInf, from};
  SweepResult result;
  {
    UpwardRounding upward;
    result = spread_backward_loop(x.data(), v.data(), from, stop_below);
  }
  normalize_at(x, v, result.first_empty);
  return result;
}

}  // namespace

SweepResult chain_forward(std::span<Interval> x, std::span<const Interval> v) {
  if (x.size() < 2) return {};
  if (x[0].is_empty()) return SweepResult{0, kInf, 0};
  SweepResult result;
  {
    UpwardRounding upward;
    result.first_empty = full_forward_loop(x.data(), v.data(), x.size(), result.max_shrink);
  }
  result.last = result.consistent() ? x.size() - 1 : result.first_empty;
  normalize_at(x, {}, result.first_empty);
  return result;
}

SweepResult chain_backward(std::span<Interval> x, std::span<Interval> v) {
  if (x.size() < 2) return {};
  SweepResult result;
  {
    UpwardRounding upward;
    result.first_empty = full_backward_loop(x.data(), v.data(), x.size(), result.max_shrink);
  }
  result.last = result.consistent() ? 0 : result.first_empty;
  normalize_at(x, v, result.first_empty);
  return result;
}

SweepResult chain_forward_from(std::span<Interval> x, std::span<const Interval> v, std::size_t from, double stop_below) {
  return spread_forward(x, v, from, stop_below);
}

SweepResult chain_backward_from(std::span<Interval> x, std::span<Interval> v, std::size_t from, double stop_below) {
  return spread_backward(x, v, from, stop_below);
}

namespace {

// The chains one after the other: for lengths the joint loop does not take.
template <class Steps, class Sweep>
ChainsSweepResult one_by_one(const std::array<std::span<Interval>, kChains>& x, const std::array<Steps, kChains>& v,
                             Sweep sweep) {
  ChainsSweepResult result;
  for (int a = 0; a < kChains; ++a) {
    const SweepResult r = sweep(x[a], v[a]);
    if (!r.consistent()) return ChainsSweepResult{r, a};
    result.sweep.max_shrink = std::max(result.sweep.max_shrink, r.max_shrink);
    result.sweep.last = r.last;
  }
  return result;
}

template <class Steps>
bool same_lengths(const std::array<std::span<Interval>, kChains>& x, const std::array<Steps, kChains>& v) {
  const std::size_t n = x[0].size();
  if (n < 2) return false;
  for (int a = 0; a < kChains; ++a)
    if (x[a].size() != n || v[a].size() + 1 != n) return false;
  return true;
}

// After the joint loop stopped at step `at`, where the chains in `emptied` emptied:
// the chains before the first of those go on alone, as chain_forward/chain_backward
// would have swept them before reaching it; the first chain found empty is the result.
// Every chain emptied at `at` is normalised.
template <class Steps, class Rest>
ChainsSweepResult first_emptied(const std::array<std::span<Interval>, kChains>& x, const std::array<Steps, kChains>& v,
                                std::size_t at, unsigned emptied, Rest rest) {
  ChainsSweepResult result;
  for (int a = 0; a < kChains && result.chain < 0; ++a) {
    std::size_t first_empty = at;
    if (!(emptied >> a & 1)) {
      UpwardRounding upward;
      first_empty = rest(a);
    }
    if (first_empty != SweepResult::kNone) result = ChainsSweepResult{SweepResult{first_empty, kInf, first_empty}, a};
  }
  for (int a = 0; a < kChains; ++a)
    if (emptied >> a & 1 || a == result.chain) {
      const std::size_t k = a == result.chain ? result.sweep.first_empty : at;
      if (x[a][k].is_empty()) x[a][k] = Interval::empty();
      if constexpr (!std::is_const_v<typename Steps::element_type>)
        if (k < v[a].size() && v[a][k].is_empty()) v[a][k] = Interval::empty();
    }
  return result;
}

// The joint loop over the three chains; if some chain emptied, the chains before it
// go on alone (`alone(c, a, at)`: chain a from step `at`, the first empty step or
// kNone). `last` is the index a full sweep updates last.
template <class Steps, class Joint, class Alone>
ChainsSweepResult sweep_together(const std::array<std::span<Interval>, kChains>& x, const std::array<Steps, kChains>& v,
                                 Joint joint, Alone alone, std::size_t last) {
  const std::size_t n = x[0].size();
  const ChainArrays<typename Steps::element_type> c{{x[0].data(), x[1].data(), x[2].data()},
                                                    {v[0].data(), v[1].data(), v[2].data()}};
  double shrink[kChains];
  unsigned emptied = 0;
  std::size_t at;
  {
    UpwardRounding upward;
    at = joint(c, n, shrink, emptied);
  }
  if (at != SweepResult::kNone) return first_emptied(x, v, at, emptied, [&](int a) { return alone(c, a, at); });
  ChainsSweepResult result;
  result.sweep.max_shrink = std::max({shrink[0], shrink[1], shrink[2]});
  result.sweep.last = last;
  return result;
}

}  // namespace

ChainsSweepResult chains_forward(const std::array<std::span<Interval>, 3>& x,
                                 const std::array<std::span<const Interval>, 3>& v) {
  bool together = same_lengths(x, v);
  for (int a = 0; together && a < kChains; ++a) together = !x[a][0].is_empty();
  if (!together) return one_by_one(x, v, chain_forward);
  const std::size_t n = x[0].size();
  const auto alone = [n](const ChainArrays<const Interval>& c, int a, std::size_t at) {
    double rest_shrink;
    const std::size_t e = full_forward_loop(c.x[a] + at, c.v[a] + at, n - at, rest_shrink);
    return e == SweepResult::kNone ? e : at + e;
  };
  return sweep_together(x, v, forward_loop3, alone, n - 1);
}

ChainsSweepResult chains_backward(const std::array<std::span<Interval>, 3>& x, const std::array<std::span<Interval>, 3>& v) {
  if (!same_lengths(x, v)) return one_by_one(x, v, chain_backward);
  const auto alone = [](const ChainArrays<Interval>& c, int a, std::size_t at) {
    double rest_shrink;
    return full_backward_loop(c.x[a], c.v[a], at + 1, rest_shrink);
  };
  return sweep_together(x, v, backward_loop3, alone, 0);
}

namespace {

void require_steps_for(const std::array<std::span<Interval>, kChains>& x, const StepsToSweep& steps) {
  if (steps.samples() != x[0].size())
    throw std::invalid_argument("chains_forward/chains_backward: the marked steps are for another tube");
}

}  // namespace

ChainsSweepResult chains_forward(const std::array<std::span<Interval>, 3>& x,
                                 const std::array<std::span<const Interval>, 3>& v, StepsToSweep& steps) {
  require_steps_for(x, steps);
  bool together = same_lengths(x, v);
  for (int a = 0; together && a < kChains; ++a) together = !x[a][0].is_empty();
  if (!together) {  // (lengths the joint loop does not take: every step, then all marked)
    const ChainsSweepResult r = chains_forward(x, v);
    steps.mark_all();
    return r;
  }
  const std::size_t n = x[0].size();
  const auto alone = [n](const ChainArrays<const Interval>& c, int a, std::size_t at) {
    double rest_shrink;
    const std::size_t e = full_forward_loop(c.x[a] + at, c.v[a] + at, n - at, rest_shrink);
    return e == SweepResult::kNone ? e : at + e;
  };
  const auto marked = [&steps](const ChainArrays<const Interval>& c, std::size_t samples, double (&shrink)[kChains],
                               unsigned& emptied) {
    return marked_forward_loop3(c, samples, steps.forward(), steps.backward(), shrink, emptied);
  };
  const ChainsSweepResult r = sweep_together(x, v, marked, alone, n - 1);
  if (!r.consistent()) steps.mark_all();  // (the run stopped with marks half cleared)
  return r;
}

ChainsSweepResult chains_backward(const std::array<std::span<Interval>, 3>& x, const std::array<std::span<Interval>, 3>& v,
                                  StepsToSweep& steps) {
  require_steps_for(x, steps);
  if (!same_lengths(x, v)) {
    const ChainsSweepResult r = chains_backward(x, v);
    steps.mark_all();
    return r;
  }
  const auto alone = [](const ChainArrays<Interval>& c, int a, std::size_t at) {
    double rest_shrink;
    return full_backward_loop(c.x[a], c.v[a], at + 1, rest_shrink);
  };
  const auto marked = [&steps](const ChainArrays<Interval>& c, std::size_t samples, double (&shrink)[kChains],
                               unsigned& emptied) {
    return marked_backward_loop3(c, samples, steps.backward(), steps.forward(), shrink, emptied);
  };
  const ChainsSweepResult r = sweep_together(x, v, marked, alone, 0);
  if (!r.consistent()) steps.mark_all();  // (the run stopped with marks half cleared)
  return r;
}

}  // namespace gesmi
