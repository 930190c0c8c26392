#pragma once
// Everything `gesmi localize` writes: the inner and boundary boxes (CSV, HDF5), the
// components with their hull boxes, outliers and associations (CSV), the summary
// text (also printed), summary.json (localization_json.h) and the picture. Each
// file is written to a temporary name and renamed. Formats: docs/setinversion.md.

#include <string>
#include <vector>

#include "solver/setinv/localization/localization_problem.h"

namespace gesmi::io {

/// Human-readable report: policy, GOMNE steps, paving sizes, hypotheses.
std::string localization_summary(const LocalizationProblem& problem, const LocalizationResult& result);

/// Boxes of one paving, one per line: component,x_lo,x_hi,y_lo,y_hi,theta_lo_rad,theta_hi_rad.
std::string paving_csv(const Paving& paving, const std::vector<int>& component_of_box);
/// One line per hypothesis (component).
std::string components_csv(const LocalizationProblem& problem, const LocalizationResult& result);

/// The files write_localization_outputs() writes into `folder`, in that order.
std::vector<std::string> localization_output_files(const std::string& folder);
/// Writes inner.csv, boundary.csv, components.csv, summary.txt, summary.json, paving.h5, paving.png into
/// `folder` (created if missing); returns the paths written.
std::vector<std::string> write_localization_outputs(const std::string& folder, const LocalizationProblem& problem,
                                                    const LocalizationResult& result);

}  // namespace gesmi::io
