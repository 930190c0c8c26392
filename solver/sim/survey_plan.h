#pragma once
// The survey the simulated robot flies: waypoints of a lawnmower over the reference
// mine field (legs paired around each mine so that the starboard sonar sees every
// mine about twice, as in the reference mark table), ending at the reference end
// fix, and the reference mine layout in the local frame.

#include <vector>

#include "solver/interval/box.h"

namespace gesmi {

struct Waypoint {
  double north, east;  // m, local frame
  double depth;        // m, target depth on the way to this waypoint
};

/// Local frame position of the reference end fix relative to the start fix
/// (computed from the two published fixes by io/geodesy; docs/formats.md).
inline constexpr double kReferenceEndNorth = 690.43;
inline constexpr double kReferenceEndEast = 265.07;

/// One pass over the mine field, from the start (0, 0) to the end fix.
std::vector<Waypoint> reference_survey();
/// The six reference mines (north, east) from the Codac Redermor example, read
/// with x = north, y = east; depth from the sea floor model.
std::vector<Vec3d> reference_mines(int count, double (*floor_depth)(double north, double east));
/// The sea floor depth (m) under a point: 19.5 m with a 0.2 % slope.
double sea_floor_depth(double north, double east);

}  // namespace gesmi
