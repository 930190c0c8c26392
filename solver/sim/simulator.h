#pragma once
// The reference-like mission simulator: a robot flies the survey plan with a
// heading-rate- and acceleration-limited guidance law; the truth is integrated from
// its attitude and body velocity, which vary continuously within the sensor model's
// rate bounds, with a midpoint rule on sub-steps (so every step's displacement lies
// in the solver's enclosure); readings are the truth plus errors strictly inside
// the declared bounds (uniform, or worst-case biases held at 99 % of the bound);
// marks are produced where a mine crosses the starboard sonar plane within range.
// Deterministic for a seed.
//
// GPS fixes are produced in the local frame (gps_north/east with half-widths); io/
// turns them into longitude and latitude.

#include "solver/mission/mission.h"
#include "solver/sim/simulation_options.h"

namespace gesmi {

Mission simulate_mission(const SimulationOptions& options, const SensorModel& model = {});

}  // namespace gesmi
