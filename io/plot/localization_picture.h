#pragma once
// The picture of a localization result: the map (walls with their reflecting side,
// landmarks), the paving projected on (x, y) and on (x, theta), the hull of each
// hypothesis and the true pose; the bottom row zooms on the hypotheses.

#include <string>

#include "solver/setinv/localization/localization_problem.h"

namespace gesmi::io {

void write_localization_picture(const std::string& png_path, const LocalizationProblem& problem,
                                const LocalizationResult& result);

}  // namespace gesmi::io
