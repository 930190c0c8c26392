#pragma once
// Motion the simulated robot's guidance does not steer, added to its flown track in the
// world frame (NED): the waves while it waits at the surface before the dive and after
// surfacing, and short vertical jerk bursts while submerged. Both are smooth (bounded
// jerk) and known in closed form, so that the truth and its velocity are exact.
//
// Waves: an orbital motion of height H and period T (heave down, sway east), faded in
// and out over one period at the ends of each surface phase; jerk up to about
// (H/2) (2 pi / T)^3. Bursts: a vertical velocity (J tau^2 / c) (sin(2 pi u)/2 -
// sin(4 pi u)/4), u = (t - t0) / tau over tau = 1 s, scaled so that its second
// derivative peaks at J; its velocity and acceleration are zero at both ends.

#include <vector>

#include "solver/interval/box.h"
#include "solver/sim/simulation_options.h"

namespace gesmi {

class ExtraMotion {
 public:
  ExtraMotion(const SimulationOptions& options);

  /// Whether t is in a surface phase (before the dive or after surfacing).
  bool at_surface(double t) const;
  /// Displacement (m) and velocity (m/s) added at t, world frame.
  void at(double t, Vec3d& displacement, Vec3d& velocity) const;

 private:
  void waves(double t, Vec3d& displacement, Vec3d& velocity) const;
  void bursts(double t, Vec3d& displacement, Vec3d& velocity) const;

  SimulationOptions o_;
  std::vector<double> burst_starts_;
  double burst_amplitude_ = 0.0;  // m/s
};

}  // namespace gesmi
