#pragma once
// Sweeps of a chain x(k+1) = x(k) + v(k) over flat arrays: the innermost loop of
// the mission solver (one chain per axis) and of the 1-D benchmark.
//
// Two implementations with the same contract:
//  - chain_*_portable: Interval operations (round to nearest, then one step out);
//  - chain_*: a kernel that runs in the upward rounding mode for the duration of
//    the sweep (chain_sweep_kernel.cpp, compiled with -frounding-math), computing
//    lower bounds as -((-a) - b). Same enclosure guarantee, tighter by up to one
//    ulp per operation, and about twice as fast because the loop-carried
//    dependency has no bit manipulation (docs/intervals.md, docs/performance.md).
// The rounding mode is restored before returning; nothing else runs meanwhile.

#include <array>
#include <cstddef>
#include <span>

#include "solver/interval/interval.h"
#include "solver/tube/steps_to_sweep.h"

namespace gesmi {

/// Result of a sweep: the first index whose domain became empty, if any, and the
/// largest narrowing of a bound of x (0 when nothing changed, inf when a bound
/// became finite or the sweep emptied a domain).
struct SweepResult {
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t first_empty = kNone;
  double max_shrink = 0.0;
  std::size_t last = 0;  // last index of x the sweep updated
  bool consistent() const { return first_empty == kNone; }
};

/// Forward: x(k+1) := x(k+1) ∩ (x(k) + v(k)) for k = 0 .. n-2 (v has n-1 entries).
SweepResult chain_forward(std::span<Interval> x, std::span<const Interval> v);
/// Backward: x(k) := x(k) ∩ (x(k+1) - v(k)) then v(k) := v(k) ∩ (x(k+1) - x(k)), k = n-2 .. 0.
SweepResult chain_backward(std::span<Interval> x, std::span<Interval> v);

/// The three chains of a tube (one per axis) swept together: one loop over the three,
/// about a fifth faster than three sweeps (docs/performance.md, "Three chains swept
/// together"). Each chain ends bit for bit as chain_forward (chain_backward) leaves it,
/// up to the first chain, in axis order, that empties: that one is the result, as one sweep per chain would find it.
/// The chains after it may be left partly swept (those that emptied at the same step
/// normalised). Otherwise the result is the largest narrowing over the three.
struct ChainsSweepResult {
  SweepResult sweep;
  int chain = -1;  // the chain that emptied, or -1
  bool consistent() const { return sweep.consistent(); }
};
ChainsSweepResult chains_forward(const std::array<std::span<Interval>, 3>& x,
                                 const std::array<std::span<const Interval>, 3>& v);
ChainsSweepResult chains_backward(const std::array<std::span<Interval>, 3>& x,
                                  const std::array<std::span<Interval>, 3>& v);

/// The same sweeps over the steps `steps` marks (steps_to_sweep.h) and those a change
/// carries into, clearing their marks and marking for the other direction what they
/// narrow: the same bounds, result and first emptied chain as the sweeps above when
/// every narrowing of a position between sweeps was told to `steps`
/// (std::invalid_argument if `steps` is for another number of samples).
ChainsSweepResult chains_forward(const std::array<std::span<Interval>, 3>& x,
                                 const std::array<std::span<const Interval>, 3>& v, StepsToSweep& steps);
ChainsSweepResult chains_backward(const std::array<std::span<Interval>, 3>& x,
                                  const std::array<std::span<Interval>, 3>& v, StepsToSweep& steps);

/// Work-list spreads: from x(from) forward (or backward), stopping after the first
/// step whose bounds moved by no more than stop_below (a domain that no longer
/// shrinks stops the spread: beyond it nothing can change).
SweepResult chain_forward_from(std::span<Interval> x, std::span<const Interval> v, std::size_t from, double stop_below);
SweepResult chain_backward_from(std::span<Interval> x, std::span<Interval> v, std::size_t from, double stop_below);

SweepResult chain_forward_portable(std::span<Interval> x, std::span<const Interval> v);
SweepResult chain_backward_portable(std::span<Interval> x, std::span<Interval> v);

}  // namespace gesmi
