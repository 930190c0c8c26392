#pragma once
// Deterministic random numbers for the simulator: std::mt19937_64 with our own
// transforms (the std:: distributions differ between standard libraries).

#include <cstdint>
#include <random>

namespace gesmi {

class RandomSource {
 public:
  explicit RandomSource(std::uint64_t seed) : rng_(seed) {}
  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(rng_() >> 11) * 0x1p-53; }
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// -1 or +1.
  double sign() { return (rng_() >> 63) ? 1.0 : -1.0; }
  bool chance(double p) { return uniform() < p; }

 private:
  std::mt19937_64 rng_;
};

}  // namespace gesmi
