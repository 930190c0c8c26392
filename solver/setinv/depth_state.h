#pragma once
// Per-recursion-level state of a data evaluator: level d holds what is known on the
// box being examined at depth d, and a child starts from its father's level. This is
// seed 003's visibility vector generalised: a datum (or a landmark's visibility)
// settled on a box stays settled on its sub-boxes (inclusion monotonicity), and a
// candidate wall or landmark ruled out for a datum stays ruled out.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gesmi {

/// Fixed-size records of T, one per level, grown on demand (never per box).
template <class T>
class LevelArrays {
 public:
  LevelArrays(std::size_t per_level, T initial) : per_level_(per_level), initial_(initial) {}

  /// Level `depth` initialised from level depth-1 (depth 0: the initial values).
  T* enter(int depth) {
    const auto d = static_cast<std::size_t>(depth);
    if (data_.size() < (d + 1) * per_level_) data_.resize((d + 1) * per_level_, initial_);
    T* level = data_.data() + d * per_level_;
    if (d == 0)
      std::fill(level, level + per_level_, initial_);
    else
      std::copy(level - per_level_, level, level);
    return level;
  }

 private:
  std::size_t per_level_;
  T initial_;
  std::vector<T> data_;
};

/// One bit per (datum, candidate): word layout datum-major.
inline std::size_t words_for(std::size_t bits) { return (bits + 63) / 64; }
inline bool test_bit(const std::uint64_t* words, std::size_t i) { return (words[i / 64] >> (i % 64)) & 1u; }
inline void clear_bit(std::uint64_t* words, std::size_t i) { words[i / 64] &= ~(std::uint64_t{1} << (i % 64)); }

}  // namespace gesmi
