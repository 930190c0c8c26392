#pragma once
// Localization scenarios (YAML): the map, the sensors, the measurements, the prior,
// the solver settings, the outlier policy and optionally the true pose, read into a
// gesmi::LocalizationProblem. Angles are in degrees in the file (keys ending in
// _deg) and in radians in the problem. Every error is a FormatError with one line
// "FILE:LINE: KEY: reason". The format is documented in docs/setinversion.md.

#include <istream>
#include <string>

#include "solver/setinv/localization/localization_problem.h"

namespace gesmi::io {

LocalizationProblem read_localization_scenario(const std::string& path);
/// `source` names the input in error messages.
LocalizationProblem parse_localization_scenario(std::istream& in, const std::string& source);

/// The `measurements:` block of a scenario for the problem's measurements (used
/// to write simulated measurements back into a scenario file).
std::string localization_measurements_yaml(const LocalizationProblem& problem);

}  // namespace gesmi::io
