// 1-D chain x(k+1) = x(k) + v(k) of 10^6 steps with intersection: one forward and
// one backward sweep, with the upward-rounding kernel and the portable version.
// Target: <= 3 ns per step per sweep direction.

#include <benchmark/benchmark.h>

#include <array>
#include <span>
#include <vector>

#include "solver/tube/chain_sweep.h"

namespace {

using gesmi::Interval;

struct Chain {
  std::vector<Interval> x, v;
  explicit Chain(std::size_t n) : x(n), v(n - 1) {
    x[0] = Interval(0.0);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double s = 0.1 * static_cast<double>(k % 7) - 0.3;
      v[k] = Interval(s - 0.01, s + 0.02);
    }
    x[n - 1] = Interval(-1e3, 1e3);  // a final fix, so the backward sweep contracts
  }
};

constexpr std::size_t kSteps = 1'000'000;

template <auto Sweep>
void forward(benchmark::State& state) {
  Chain chain(kSteps);
  for (auto _ : state) {
    state.PauseTiming();
    std::fill(chain.x.begin() + 1, chain.x.end(), Interval::entire());
    state.ResumeTiming();
    benchmark::DoNotOptimize(Sweep(chain.x, chain.v));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * (kSteps - 1)));
}

template <auto ForwardSweep, auto BackwardSweep>
void backward(benchmark::State& state) {
  Chain chain(kSteps);
  ForwardSweep(chain.x, chain.v);
  for (auto _ : state) {
    benchmark::DoNotOptimize(BackwardSweep(chain.x, chain.v));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * (kSteps - 1)));
}

void BM_ChainForward(benchmark::State& s) { forward<gesmi::chain_forward>(s); }
void BM_ChainForwardPortable(benchmark::State& s) { forward<gesmi::chain_forward_portable>(s); }
void BM_ChainBackward(benchmark::State& s) { backward<gesmi::chain_forward, gesmi::chain_backward>(s); }
void BM_ChainBackwardPortable(benchmark::State& s) {
  backward<gesmi::chain_forward_portable, gesmi::chain_backward_portable>(s);
}

// The three chains of a tube: one after the other, together (chains_forward,
// chains_backward), and together over marked steps with every step marked (what the first
// sweep of a solve does), one forward and one backward sweep each.
enum class Sweeps { one_by_one, together, all_marked };
template <Sweeps How>
void three_chains(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Chain a(n), b(n), c(n);
  const std::array<std::span<Interval>, 3> x{a.x, b.x, c.x};
  const std::array<std::span<Interval>, 3> v{a.v, b.v, c.v};
  const std::array<std::span<const Interval>, 3> v_const{a.v, b.v, c.v};
  for (auto _ : state) {
    state.PauseTiming();
    for (Chain* chain : {&a, &b, &c}) std::fill(chain->x.begin() + 1, chain->x.end() - 1, Interval::entire());
    state.ResumeTiming();
    if constexpr (How == Sweeps::all_marked) {
      state.PauseTiming();
      gesmi::StepsToSweep steps(n);
      state.ResumeTiming();
      benchmark::DoNotOptimize(gesmi::chains_forward(x, v_const, steps));
      benchmark::DoNotOptimize(gesmi::chains_backward(x, v, steps));
    } else if constexpr (How == Sweeps::together) {
      benchmark::DoNotOptimize(gesmi::chains_forward(x, v_const));
      benchmark::DoNotOptimize(gesmi::chains_backward(x, v));
    } else {
      for (int i = 0; i < 3; ++i) benchmark::DoNotOptimize(gesmi::chain_forward(x[i], v[i]));
      for (int i = 0; i < 3; ++i) benchmark::DoNotOptimize(gesmi::chain_backward(x[i], v[i]));
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 3 * (n - 1)));
}

void BM_ThreeChainsOneByOne(benchmark::State& s) { three_chains<Sweeps::one_by_one>(s); }
void BM_ThreeChainsTogether(benchmark::State& s) { three_chains<Sweeps::together>(s); }
void BM_ThreeChainsAllMarked(benchmark::State& s) { three_chains<Sweeps::all_marked>(s); }

BENCHMARK(BM_ChainForward)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ThreeChainsOneByOne)->Arg(60000)->Arg(kSteps)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ThreeChainsTogether)->Arg(60000)->Arg(kSteps)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ThreeChainsAllMarked)->Arg(60000)->Arg(kSteps)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChainForwardPortable)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChainBackward)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChainBackwardPortable)->Unit(benchmark::kMillisecond);

}  // namespace
