// Cost of each interval operation (outward rounded) next to the same operation
// on plain double: ns per operation, as "Interval/op" and "Double/op". Inputs
// cycle through 1024 pre-drawn values so that nothing is constant-folded. Reverse
// operators are paired with the double function they invert (bwd_sin with asin).

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "solver/interval/interval.h"
#include "solver/interval/interval_reverse.h"

namespace {

using gesmi::Interval;

constexpr std::size_t kInputs = 1024;  // a power of two: the index wraps with a mask

// Random intervals in [lo, hi] of width up to `width`, and their midpoints.
struct Inputs {
  std::vector<Interval> x;
  std::vector<double> d;
  Inputs(double lo, double hi, double width, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi), w(0.0, width);
    for (std::size_t i = 0; i < kInputs; ++i) {
      const double a = u(rng);
      x.push_back(Interval(a, std::min(hi, a + w(rng))));
      d.push_back(x.back().mid());
    }
  }
};

const Inputs& general() {
  static const Inputs in(-10.0, 10.0, 1.0, 1);
  return in;
}
const Inputs& other() {
  static const Inputs in(-10.0, 10.0, 1.0, 2);
  return in;
}
const Inputs& positive() {
  static const Inputs in(0.1, 100.0, 1.0, 3);
  return in;
}
const Inputs& unit() {
  static const Inputs in(-0.9, 0.9, 0.1, 4);
  return in;
}

template <class T, class F>
void unary(benchmark::State& state, const std::vector<T>& a, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(a[i]));
    i = (i + 1) & (kInputs - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

template <class T, class F>
void binary(benchmark::State& state, const std::vector<T>& a, const std::vector<T>& b, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(a[i], b[(i * 7) & (kInputs - 1)]));
    i = (i + 1) & (kInputs - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// Reverse operators narrow copies of their arguments, so the inputs stay unchanged.
template <class F>
void reverse(benchmark::State& state, const std::vector<Interval>& y, const std::vector<Interval>& x, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    Interval xi = x[i];
    benchmark::DoNotOptimize(f(y[(i * 7) & (kInputs - 1)], xi));
    benchmark::DoNotOptimize(xi);
    i = (i + 1) & (kInputs - 1);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

// ---- arithmetic ---------------------------------------------------------------
void Interval_add(benchmark::State& s) { binary(s, general().x, other().x, [](auto a, auto b) { return a + b; }); }
void Double_add(benchmark::State& s) { binary(s, general().d, other().d, [](auto a, auto b) { return a + b; }); }
void Interval_sub(benchmark::State& s) { binary(s, general().x, other().x, [](auto a, auto b) { return a - b; }); }
void Double_sub(benchmark::State& s) { binary(s, general().d, other().d, [](auto a, auto b) { return a - b; }); }
void Interval_mul(benchmark::State& s) { binary(s, general().x, other().x, [](auto a, auto b) { return a * b; }); }
void Double_mul(benchmark::State& s) { binary(s, general().d, other().d, [](auto a, auto b) { return a * b; }); }
void Interval_div(benchmark::State& s) { binary(s, general().x, positive().x, [](auto a, auto b) { return a / b; }); }
void Double_div(benchmark::State& s) { binary(s, general().d, positive().d, [](auto a, auto b) { return a / b; }); }
void Interval_sqr(benchmark::State& s) { unary(s, general().x, [](auto a) { return sqr(a); }); }
void Double_sqr(benchmark::State& s) { unary(s, general().d, [](auto a) { return a * a; }); }
void Interval_sqrt(benchmark::State& s) { unary(s, positive().x, [](auto a) { return sqrt(a); }); }
void Double_sqrt(benchmark::State& s) { unary(s, positive().d, [](auto a) { return std::sqrt(a); }); }
void Interval_pow5(benchmark::State& s) { unary(s, general().x, [](auto a) { return pow(a, 5); }); }
void Double_pow5(benchmark::State& s) { unary(s, general().d, [](auto a) { return std::pow(a, 5); }); }
void Interval_abs(benchmark::State& s) { unary(s, general().x, [](auto a) { return abs(a); }); }
void Double_abs(benchmark::State& s) { unary(s, general().d, [](auto a) { return std::fabs(a); }); }
void Interval_min(benchmark::State& s) { binary(s, general().x, other().x, [](auto a, auto b) { return min(a, b); }); }
void Double_min(benchmark::State& s) { binary(s, general().d, other().d, [](auto a, auto b) { return std::min(a, b); }); }
void Interval_intersect(benchmark::State& s) {
  binary(s, general().x, other().x, [](auto a, auto b) { return intersect(a, b); });
}
void Double_intersect(benchmark::State& s) {  // the same two comparisons on bounds
  binary(s, general().d, other().d, [](auto a, auto b) { return std::max(a, b) - std::min(a, b); });
}

// ---- elementary functions ---------------------------------------------------------
void Interval_exp(benchmark::State& s) { unary(s, general().x, [](auto a) { return exp(a); }); }
void Double_exp(benchmark::State& s) { unary(s, general().d, [](auto a) { return std::exp(a); }); }
void Interval_log(benchmark::State& s) { unary(s, positive().x, [](auto a) { return log(a); }); }
void Double_log(benchmark::State& s) { unary(s, positive().d, [](auto a) { return std::log(a); }); }
void Interval_sin(benchmark::State& s) { unary(s, general().x, [](auto a) { return sin(a); }); }
void Double_sin(benchmark::State& s) { unary(s, general().d, [](auto a) { return std::sin(a); }); }
void Interval_cos(benchmark::State& s) { unary(s, general().x, [](auto a) { return cos(a); }); }
void Double_cos(benchmark::State& s) { unary(s, general().d, [](auto a) { return std::cos(a); }); }
void Interval_tan(benchmark::State& s) { unary(s, unit().x, [](auto a) { return tan(a); }); }
void Double_tan(benchmark::State& s) { unary(s, unit().d, [](auto a) { return std::tan(a); }); }
void Interval_atan(benchmark::State& s) { unary(s, general().x, [](auto a) { return atan(a); }); }
void Double_atan(benchmark::State& s) { unary(s, general().d, [](auto a) { return std::atan(a); }); }
void Interval_atan2(benchmark::State& s) {
  binary(s, general().x, positive().x, [](auto a, auto b) { return atan2(a, b); });
}
void Double_atan2(benchmark::State& s) {
  binary(s, general().d, positive().d, [](auto a, auto b) { return std::atan2(a, b); });
}

// ---- reverse operators (double: the inverse function) ------------------------------
void Interval_bwd_add(benchmark::State& s) {
  reverse(s, general().x, other().x, [](const Interval& y, Interval& x) {
    Interval x2 = y;
    return gesmi::bwd_add(y, x, x2);
  });
}
void Double_bwd_add(benchmark::State& s) { binary(s, general().d, other().d, [](auto a, auto b) { return a - b; }); }
void Interval_bwd_mul(benchmark::State& s) {
  reverse(s, general().x, other().x, [](const Interval& y, Interval& x) {
    Interval x2(0.5, 2.0);
    return gesmi::bwd_mul(y, x, x2);
  });
}
void Double_bwd_mul(benchmark::State& s) { binary(s, general().d, positive().d, [](auto a, auto b) { return a / b; }); }
void Interval_bwd_sqr(benchmark::State& s) { reverse(s, positive().x, general().x, gesmi::bwd_sqr); }
void Double_bwd_sqr(benchmark::State& s) { unary(s, positive().d, [](auto a) { return std::sqrt(a); }); }
void Interval_bwd_exp(benchmark::State& s) { reverse(s, positive().x, general().x, gesmi::bwd_exp); }
void Double_bwd_exp(benchmark::State& s) { unary(s, positive().d, [](auto a) { return std::log(a); }); }
void Interval_bwd_sin(benchmark::State& s) { reverse(s, unit().x, general().x, gesmi::bwd_sin); }
void Double_bwd_sin(benchmark::State& s) { unary(s, unit().d, [](auto a) { return std::asin(a); }); }
void Interval_bwd_cos(benchmark::State& s) { reverse(s, unit().x, general().x, gesmi::bwd_cos); }
void Double_bwd_cos(benchmark::State& s) { unary(s, unit().d, [](auto a) { return std::acos(a); }); }
void Interval_bwd_atan2(benchmark::State& s) {
  reverse(s, unit().x, positive().x, [](const Interval& theta, Interval& x) {
    Interval y(-5.0, 5.0);
    return gesmi::bwd_atan2(theta, y, x);
  });
}
void Double_bwd_atan2(benchmark::State& s) {  // x = r cos(theta), y = r sin(theta)
  binary(s, unit().d, positive().d, [](auto t, auto r) { return r * std::cos(t) + r * std::sin(t); });
}

BENCHMARK(Interval_add);
BENCHMARK(Double_add);
BENCHMARK(Interval_sub);
BENCHMARK(Double_sub);
BENCHMARK(Interval_mul);
BENCHMARK(Double_mul);
BENCHMARK(Interval_div);
BENCHMARK(Double_div);
BENCHMARK(Interval_sqr);
BENCHMARK(Double_sqr);
BENCHMARK(Interval_sqrt);
BENCHMARK(Double_sqrt);
BENCHMARK(Interval_pow5);
BENCHMARK(Double_pow5);
BENCHMARK(Interval_abs);
BENCHMARK(Double_abs);
BENCHMARK(Interval_min);
BENCHMARK(Double_min);
BENCHMARK(Interval_intersect);
BENCHMARK(Double_intersect);
BENCHMARK(Interval_exp);
BENCHMARK(Double_exp);
BENCHMARK(Interval_log);
BENCHMARK(Double_log);
BENCHMARK(Interval_sin);
BENCHMARK(Double_sin);
BENCHMARK(Interval_cos);
BENCHMARK(Double_cos);
BENCHMARK(Interval_tan);
BENCHMARK(Double_tan);
BENCHMARK(Interval_atan);
BENCHMARK(Double_atan);
BENCHMARK(Interval_atan2);
BENCHMARK(Double_atan2);
BENCHMARK(Interval_bwd_add);
BENCHMARK(Double_bwd_add);
BENCHMARK(Interval_bwd_mul);
BENCHMARK(Double_bwd_mul);
BENCHMARK(Interval_bwd_sqr);
BENCHMARK(Double_bwd_sqr);
BENCHMARK(Interval_bwd_exp);
BENCHMARK(Double_bwd_exp);
BENCHMARK(Interval_bwd_sin);
BENCHMARK(Double_bwd_sin);
BENCHMARK(Interval_bwd_cos);
BENCHMARK(Double_bwd_cos);
BENCHMARK(Interval_bwd_atan2);
BENCHMARK(Double_bwd_atan2);

}  // namespace
