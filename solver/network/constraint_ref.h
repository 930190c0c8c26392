#pragma once
// A typed reference to an input constraint of a mission: a row of the mark table
// or a row of the GPS table. Used wherever a report names a constraint (an
// inconsistency, an outlier hypothesis), instead of an index into the network.

#include <compare>
#include <cstddef>

namespace gesmi {

struct ConstraintRef {
  enum class Kind { mark, gps_fix };
  Kind kind = Kind::mark;
  std::size_t row = 0;  // in the mission's mark table or GPS table

  static ConstraintRef mark(std::size_t row) { return {Kind::mark, row}; }
  static ConstraintRef gps_fix(std::size_t row) { return {Kind::gps_fix, row}; }
  auto operator<=>(const ConstraintRef&) const = default;
};

}  // namespace gesmi
