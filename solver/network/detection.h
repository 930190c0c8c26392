#pragma once
// One detection of the sonar mark table (seed 001, section IV-D): the sonar plane at
// the mark time (sonar_plane.h) with the measured slant range, and the mine it
// belongs to (or the mines it may belong to, for a mark without a number).

#include <cstdint>

#include "solver/network/sonar_plane.h"
#include "solver/network/time_location.h"

namespace gesmi {

struct Detection {
  std::size_t mark = 0;      // row in the mark table
  double time = 0.0;         // s
  int mine = 0;              // mine index, -1 when the mark table does not say
  /// Mines this detection may belong to before any propagation (bit i: mine i).
  /// One bit for an associated detection; for an unassociated one, the mines that
  /// survive symmetry breaking among unlabelled mines (docs/model.md).
  std::uint64_t allowed = 0;
  double measured_range = 0.0;
  TimeLocation at;
  SonarPlane plane;  // at the mark time
  Interval range;    // slant range domain: the measured range ± its bound

  /// Contracts the position q at the mark time and the mine box m; false when the
  /// constraint has no solution in them (q and m are then left empty).
  bool contract(Vec3I& q, Vec3I& m) const {
    Interval r = range;
    return plane.contract(q, m, r);
  }
};

}  // namespace gesmi
