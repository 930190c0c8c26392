#pragma once
// The side-scan sonar's geometry at one instant (seed 001, section IV-D), with
// e = p - m the vector from the mine to the robot and e_b = R^T e its coordinates in
// the robot frame (along, across, down):
//   |e_b.x| <= along-track tolerance   (the mine is in the sonar plane)
//   e_b.y <= 0 starboard, >= 0 port     (the side; seed 001 eq. 8)
//   e_b.z <= 0                          (the mine is below the robot)
//   ||e|| = r                           (the slant range)
//   e.z = -(a + s), |s| <= band         (m_z = a + p_z + s, eq. 10)
// contracted forward-backward in both frames (docs/model.md). The robot and the mine
// are placed in the local frame, where q - m differs from e by at most `frame_slack`
// on each axis (sonar_frame_slack(): the frame's scale and the depth's times the
// largest range, and the surface's drop over it; docs/model.md "The local frame's
// scale"). A mark (detection.h)
// is this plane plus a measured range and a mine; the waterfall (waterfall.h) asks
// the plane alone at which ranges a mine can appear.

#include "solver/interval/box.h"
#include "solver/mission/sensor_model.h"
#include "solver/model/euler.h"

namespace gesmi {

struct SonarPlane {
  Attitude<Interval> attitude;  // of the robot at that instant
  Interval altitude;            // above the floor at that instant
  double along_tolerance = 0.0;
  double depth_band = 0.0;
  double frame_slack = 0.0;  // m, on each axis between the frame's q - m and e
  SonarSide side = SonarSide::starboard;  // port or starboard (not both)

  /// Contracts the robot's position q, the mine box m and the slant range r; false
  /// when they cannot satisfy the geometry (all three are then left empty).
  bool contract(Vec3I& q, Vec3I& m, Interval& r) const;
  /// The robot-frame box of e allowed before any data, on this plane's side or another.
  Vec3I body_prior() const { return body_prior(side); }
  Vec3I body_prior(SonarSide on) const;
  /// e = q - m rotated once into the robot frame, for cheap tests before contract():
  /// empty when e.z misses the vertical band or the along-track component misses the
  /// plane's tolerance.
  Vec3I rough_body_offset(const Vec3I& q, const Vec3I& m) const;
  /// A necessary condition on one side: the rough body offset meets that side's prior.
  /// False means contract() on that side would empty the boxes (it starts from q and m,
  /// only narrows them, and interval operations are inclusion monotone).
  bool may_hold(const Vec3I& rough_body_offset, SonarSide side) const;
  /// The box of e.z = p_z - m_z: -(altitude ± depth band).
  Interval vertical() const;
  /// The offsets e that boxes q and m allow: q - m widened by the frame slack.
  Vec3I offset(const Vec3I& q, const Vec3I& m) const;
  /// The slant ranges |e| that boxes q and m allow, the frame slack included.
  Interval possible_ranges(const Vec3I& q, const Vec3I& m) const;
};

/// Distance between the points of two boxes, as an interval.
Interval box_distance(const Vec3I& a, const Vec3I& b);

/// True only when every point of `a` is farther than `reach` from every point of `b`,
/// decided in plain doubles (a cheap test before box_distance; false when unsure; an
/// empty box, which has no point, is beyond anything).
bool boxes_beyond(const Vec3I& a, const Vec3I& b, double reach);

}  // namespace gesmi
