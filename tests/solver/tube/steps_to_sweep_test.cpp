// Sweeps over the marked steps (steps_to_sweep.h) leave the bounds that full sweeps
// leave, with the same result, through rounds of sweeps with narrowings in between,
// and name the same first emptied chain.

#include "solver/tube/steps_to_sweep.h"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <span>
#include <stdexcept>
#include <vector>

#include "solver/tube/chain_sweep.h"

namespace gesmi {
namespace {

// Three chains with wide priors here and there, narrow fixes, and steps of a few
// centimetres whose sums are inexact.
struct Tube {
  std::array<std::vector<Interval>, 3> x, v;
  Tube(std::mt19937_64& rng, std::size_t n) {
    std::uniform_real_distribution<double> centre(-0.3, 0.3), half(0.0, 0.05), wide(5.0, 50.0);
    for (std::size_t a = 0; a < 3; ++a) {
      v[a].resize(n - 1);
      x[a].assign(n, Interval::entire());
      double at = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        if (k > 0) {
          const double c = centre(rng) + 1e-7 * centre(rng), h = half(rng);
          v[a][k - 1] = Interval(c - h, c + h);
          at += c;
        }
        if (k % 89 == 0) x[a][k] = Interval(at - wide(rng), at + wide(rng));
        if (k % 97 == 0 || k % 97 == 1) x[a][k] = Interval(at - 0.005, at + 0.005);
      }
      x[a][0] = Interval(-0.5, 0.5);
    }
  }
  std::array<std::span<Interval>, 3> positions() { return {x[0], x[1], x[2]}; }
  std::array<std::span<Interval>, 3> steps() { return {v[0], v[1], v[2]}; }
  std::array<std::span<const Interval>, 3> steps_const() { return {v[0], v[1], v[2]}; }
};

// The same numbers (a zero's sign aside: the marked sweeps may keep the other one).
void expect_same_bounds(const Tube& full, const Tube& marked, const char* when) {
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t k = 0; k < full.x[a].size(); ++k) {
      ASSERT_EQ(full.x[a][k].lo(), marked.x[a][k].lo()) << when << ": chain " << a << " sample " << k;
      ASSERT_EQ(full.x[a][k].hi(), marked.x[a][k].hi()) << when << ": chain " << a << " sample " << k;
    }
    for (std::size_t k = 0; k < full.v[a].size(); ++k) {
      ASSERT_EQ(full.v[a][k].lo(), marked.v[a][k].lo()) << when << ": chain " << a << " step " << k;
      ASSERT_EQ(full.v[a][k].hi(), marked.v[a][k].hi()) << when << ": chain " << a << " step " << k;
    }
  }
}

void expect_same_result(const ChainsSweepResult& full, const ChainsSweepResult& marked, const char* when) {
  EXPECT_EQ(full.chain, marked.chain) << when;
  EXPECT_EQ(full.sweep.first_empty, marked.sweep.first_empty) << when;
  EXPECT_EQ(full.sweep.max_shrink, marked.sweep.max_shrink) << when;
}

// A fix or detection between sweeps: one sample of one chain narrowed around a point
// inside it, in both tubes, and told to the marks.
void narrow_somewhere(std::mt19937_64& rng, Tube& full, Tube& marked, StepsToSweep& steps) {
  const std::size_t n = full.x[0].size();
  const std::size_t k = std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  const std::size_t a = std::uniform_int_distribution<std::size_t>(0, 2)(rng);
  const Interval now = full.x[a][k];
  if (!now.is_bounded()) return;
  const double inside = now.lo() + std::uniform_real_distribution<double>(0.2, 0.8)(rng) * now.width();
  const Interval box(inside - 0.01, inside + 0.01);
  full.x[a][k] = intersect(full.x[a][k], box);
  marked.x[a][k] = intersect(marked.x[a][k], box);
  steps.narrowed(k);
}

TEST(StepsToSweep, MarkedSweepsLeaveTheBoundsOfFullSweeps) {
  int rounds_swept = 0;  // (most seeds must keep a tube through many rounds)
  for (const std::size_t n : {std::size_t{2}, std::size_t{3}, std::size_t{60}, std::size_t{4000}}) {
    for (const std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(::testing::Message() << n << " samples, seed " << seed);
      std::mt19937_64 rng(seed);
      Tube full(rng, n);
      Tube marked = full;
      StepsToSweep steps(n);
      for (int round = 0; round < 12; ++round) {
        // (narrowings may leave no tube: then both sweeps must fail alike, and the rounds end)
        const ChainsSweepResult f = chains_forward(full.positions(), full.steps_const());
        const ChainsSweepResult fm = chains_forward(marked.positions(), marked.steps_const(), steps);
        expect_same_result(f, fm, "forward");
        expect_same_bounds(full, marked, "forward");
        if (!f.consistent()) break;
        const ChainsSweepResult b = chains_backward(full.positions(), full.steps());
        const ChainsSweepResult bm = chains_backward(marked.positions(), marked.steps(), steps);
        expect_same_result(b, bm, "backward");
        expect_same_bounds(full, marked, "backward");
        if (!b.consistent()) break;
        ++rounds_swept;
        // A few narrowings, or none (then the next sweeps have nothing to take).
        const int narrowings = round % 3 == 2 ? 0 : 1 + round % 4;
        for (int i = 0; i < narrowings; ++i) narrow_somewhere(rng, full, marked, steps);
      }
    }
  }
  EXPECT_GT(rounds_swept, 100);
}

TEST(StepsToSweep, MarkedSweepsNameTheSameFirstEmptiedChain) {
  const std::size_t n = 3000;
  for (const std::size_t impossible : {std::size_t{0}, std::size_t{5}, std::size_t{1500}, std::size_t{2998}}) {
    for (const bool forward : {true, false}) {
      std::mt19937_64 rng(11);
      Tube full(rng, n);
      Tube marked = full;
      StepsToSweep steps(n);
      for (int round = 0; round < 3; ++round) {  // sweeps until little moves
        chains_forward(full.positions(), full.steps_const());
        chains_forward(marked.positions(), marked.steps_const(), steps);
        chains_backward(full.positions(), full.steps());
        chains_backward(marked.positions(), marked.steps(), steps);
      }
      // Two detections on chain 1 that its step between them cannot join: each narrows
      // its sample to one end of it (a subset, as a contractor narrows).
      Interval& here = full.x[1][impossible];
      Interval& next = full.x[1][impossible + 1];
      ASSERT_GT(next.hi() - here.lo(), full.v[1][impossible].hi());
      here = Interval(here.lo(), here.lo());
      next = Interval(next.hi(), next.hi());
      marked.x[1][impossible] = here;
      marked.x[1][impossible + 1] = next;
      steps.narrowed(impossible);
      steps.narrowed(impossible + 1);
      const ChainsSweepResult r = forward ? chains_forward(full.positions(), full.steps_const())
                                          : chains_backward(full.positions(), full.steps());
      const ChainsSweepResult rm = forward ? chains_forward(marked.positions(), marked.steps_const(), steps)
                                           : chains_backward(marked.positions(), marked.steps(), steps);
      ASSERT_FALSE(r.consistent());
      expect_same_result(r, rm, forward ? "forward" : "backward");
      EXPECT_EQ(rm.chain, 1);
      EXPECT_TRUE(marked.x[1][rm.sweep.first_empty].is_empty());
      expect_same_bounds(full, marked, "emptied");
    }
  }
}

TEST(StepsToSweep, RefusesAnotherTubeAndAnotherSample) {
  std::mt19937_64 rng(5);
  Tube tube(rng, 100);
  StepsToSweep other(99);
  EXPECT_THROW(chains_forward(tube.positions(), tube.steps_const(), other), std::invalid_argument);
  EXPECT_THROW(chains_backward(tube.positions(), tube.steps(), other), std::invalid_argument);
  StepsToSweep steps(100);
  EXPECT_NO_THROW(steps.narrowed(99));
  EXPECT_THROW(steps.narrowed(100), std::out_of_range);
}

}  // namespace
}  // namespace gesmi
