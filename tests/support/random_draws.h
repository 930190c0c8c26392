#pragma once
// Random draws shared by the soundness tests (fixed seeds, std::mt19937_64).

#include <random>

namespace gesmi::test {

/// A value drawn "at" a bound lies this far inside it (1e-9 relative): inside, whatever
/// the rounding of the code under test.
inline constexpr long double kStrictlyInside = 1.0L - 1e-9L;

/// A uniform draw of [lo, hi] in long double, from the generator's top 53 bits.
inline long double uniform(std::mt19937_64& rng, long double lo, long double hi) {
  return lo + (hi - lo) * static_cast<long double>(rng() >> 11) * 0x1p-53L;
}

}  // namespace gesmi::test
