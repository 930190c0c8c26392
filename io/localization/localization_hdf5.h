#pragma once
// The pavings and hypotheses of a localization result as HDF5 (paving.h5):
//   /inner/boxes, /boundary/boxes   N x 6 doubles: x_lo x_hi y_lo y_hi theta_lo theta_hi (rad)
//   /inner/component, /boundary/component   N int32: hypothesis number (1-based)
//   /components/hull                C x 6 doubles (theta: shortest arc, may leave the prior's window)
//   /components/inner_boxes, boundary_boxes, holds_truth, outliers_determined   C int32
//   /components/outliers            C x n int32: 1 where datum i (ranges, then bearings) is an outlier
//   attributes on /: scenario, q (outliers the pavings allow), found, seconds
// Written to a temporary name and renamed.

#include <string>

#include "solver/setinv/localization/localization_problem.h"

namespace gesmi::io {

void write_localization_hdf5(const std::string& path, const LocalizationProblem& problem, const LocalizationResult& result);

}  // namespace gesmi::io
