#pragma once
// Parameter-estimation scenarios (YAML) for `gesmi estimate`: the model, the data
// (numbered from 1 in the order of the file, as seed 004 numbers them), the prior
// box, epsilon and the numbers of outliers to characterise. Every error is a
// FormatError with one line "FILE:LINE: KEY: reason". Format: docs/setinversion.md.

#include <string>

#include "solver/setinv/estimation_problem.h"

namespace gesmi::io {

EstimationProblem read_estimation_scenario(const std::string& path);

}  // namespace gesmi::io
