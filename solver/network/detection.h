#pragma once
// The mark equation of seed 001 (section IV-D) for one detection of the sonar mark
// table, with e = p(t) - m the vector from the mine to the robot and
// e_b = R^T e its coordinates in the robot frame (along, across, down):
//   |e_b.x| <= along-track tolerance   (the mine is in the sonar plane)
//   e_b.y <= 0 starboard, >= 0 port     (the declared side; seed 001 eq. 8)
//   e_b.z <= 0                          (the mine is below the robot)
//   ||e|| in r ± mark error             (slant range)
//   e.z = -(a + s), |s| <= band         (m_z = a + p_z + s, eq. 10)
// contracted forward-backward in both frames (docs/model.md).

#include <cstdint>
#include <string>

#include "solver/interval/box.h"
#include "solver/model/euler.h"
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
  int side = 1;              // +1 starboard, -1 port
  TimeLocation at;
  Attitude<Interval> attitude;  // at the mark time
  Interval range;               // slant range domain
  Interval altitude;            // at the mark time
  double along_tolerance = 0.0;
  double depth_band = 0.0;

  /// Contracts the position q at the mark time and the mine box m; false when the
  /// constraint has no solution in them (q and m are then left empty).
  bool contract(Vec3I& q, Vec3I& m) const {
    Interval r = range;
    return contract(q, m, r);
  }
  /// Same, also narrowing the slant range r (in: its domain, out: contracted).
  bool contract(Vec3I& q, Vec3I& m, Interval& r) const;
  /// The robot-frame box of e allowed by the sonar geometry before any data.
  Vec3I body_prior() const;
};

/// Distance between the points of two boxes, as an interval.
Interval box_distance(const Vec3I& a, const Vec3I& b);

}  // namespace gesmi
