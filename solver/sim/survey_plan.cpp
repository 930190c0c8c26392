#include "solver/sim/survey_plan.h"

#include <algorithm>

namespace gesmi {
namespace {

// The reference mines (Codac's Redermor example), x read as north and y as east.
constexpr double kMines[6][2] = {{594.05, 374.73}, {599.61, 484.55}, {601.46, 557.36},
                                 {94.01, -2.87},   {119.94, 84.75},  {127.35, 156.33}};

}  // namespace

double sea_floor_depth(double north, double east) { return 19.5 + 0.0015 * (north - 350.0) + 0.0015 * (east - 250.0); }

std::vector<Vec3d> reference_mines(int count, double (*floor_depth)(double, double)) {
  std::vector<Vec3d> mines;
  for (int i = 0; i < count; ++i) {
    double north, east;
    if (i < 6) {
      north = kMines[i][0];
      east = kMines[i][1];
    } else {  // extra mines spread over the surveyed area
      north = 60.0 + 97.0 * ((i * 37) % 7);
      east = -10.0 + 61.0 * ((i * 53) % 10);
    }
    mines.emplace_back(north, east, floor_depth(north, east));
  }
  return mines;
}

std::vector<Waypoint> reference_survey() {
  // As in the reference mark table, every mine is seen early, in the middle and
  // late in the mission, and the north mines last, just before surfacing at the end
  // fix next to them, so that detections near both GPS fixes anchor the mines:
  //  - early and late passes: an eastbound leg 40 m north of the south cluster and
  //    a westbound leg 40 m south of the north cluster (the mines to starboard); the
  //    late one stops at the end fix's east coordinate and surfaces;
  //  - middle: a pair of north-south legs around each mine (northbound 40 m west of
  //    it, southbound 40 m east).
  // Turns go around "bulb" waypoints so that the heading rate stays within bounds.
  constexpr double kOffset = 40.0, kBulb = 60.0, kHalfLeg = 100.0, kWest = -60.0, kEast = 620.0;
  const double south_cluster = 113.8, north_cluster = 598.4;
  std::vector<Waypoint> w;
  const auto cross_clusters = [&](double depth, double west_end) {
    w.push_back({south_cluster + kOffset, kWest, depth});
    w.push_back({south_cluster + kOffset, kEast, depth});  // eastbound: mines to the south
    w.push_back({north_cluster - kOffset, kEast + kBulb, depth});
    w.push_back({north_cluster - kOffset, west_end, depth});  // westbound: mines to the north
  };
  const auto pair_around = [&](int i, double depth) {
    const double n = kMines[i][0], e = kMines[i][1];
    w.push_back({n - kHalfLeg - kBulb, e - kOffset - 20.0, depth});
    w.push_back({n - kHalfLeg, e - kOffset, depth});
    w.push_back({n + kHalfLeg, e - kOffset, depth});  // northbound: the mine to the east
    w.push_back({n + kHalfLeg + kBulb, e, depth});
    w.push_back({n + kHalfLeg, e + kOffset, depth});
    w.push_back({n - kHalfLeg, e + kOffset, depth});  // southbound: the mine to the west
  };
  cross_clusters(6.0, kWest);
  for (const int i : {0, 1, 2}) pair_around(i, 10.0);
  for (const int i : {5, 4, 3}) pair_around(i, 8.0);
  cross_clusters(6.0, kReferenceEndEast);
  w.push_back({kReferenceEndNorth, kReferenceEndEast, 2.0});  // surface at the end fix
  return w;
}

}  // namespace gesmi
