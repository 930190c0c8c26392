#pragma once
// Random configurations that satisfy the mark equation of docs/model.md exactly
// (in long double, independently of the solver): a robot pose, a mine position,
// an altitude and a slant range with
//   e = p - m, e_b = R^T e:  |e_b.x| <= along-track tolerance, side * e_b.y <= 0,
//   e_b.z <= 0, ||e|| = range, e.z = -(altitude + s) with |s| <= depth band.
// Adversarial: the along-track offset, the depth offset s and the range error
// are drawn at their bounds (pulled inside by 1e-9 relative, far more than the
// long-double evaluation error), the mine straight below the robot (e_b.y near 0)
// or at its level (e_b.z near 0), ranges from 1 mm to the sonar's reach, any
// heading including +-pi, roll and pitch up to 0.3 rad.

#include <random>

#include "solver/mission/sensor_model.h"

namespace gesmi::test {

struct SonarConfiguration {
  double roll = 0, pitch = 0, heading = 0;  // rad, the true attitude
  double p[3] = {0, 0, 0};                  // robot (doubles: exact in any box)
  double m[3] = {0, 0, 0};                  // mine
  int side = 1;                             // +1 starboard, -1 port
  long double altitude = 0;                 // m, true altitude
  long double range = 0;                    // m, true slant range ||p - m||
  double measured_range = 0;                // within range +- model.mark_range
};

/// A configuration whose robot is at `robot` (when given) or anywhere within
/// +-2 km (depth 0..100 m), with range at most max_range.
SonarConfiguration random_sonar_configuration(std::mt19937_64& rng, const SensorModel& model, double max_range,
                                              const double* robot = nullptr);

/// Long-double check of the mark equation for p, m and the attitude (and the
/// altitude within the depth band), used to certify generated configurations.
bool satisfies_mark_geometry(const SonarConfiguration& c, const SensorModel& model);

/// Draws from [lo, hi] with the ends (pulled inside by 1e-9 relative) a third of
/// the time each.
long double adversarial(std::mt19937_64& rng, long double lo, long double hi);

}  // namespace gesmi::test
