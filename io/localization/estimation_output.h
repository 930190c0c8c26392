#pragma once
// Everything `gesmi estimate` writes: summary.txt (also printed), summary.json and
// boxes.csv, the boxes of each outlier set. Data are numbered from 1, in the order
// of the scenario file. Each file is written to a temporary name and renamed.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/setinv/estimation_problem.h"

namespace gesmi::io {

std::string estimation_summary(const EstimationProblem& problem, const EstimationResult& result);
/// One hypothesis per outlier set of size q, for each level q.
nlohmann::json estimation_summary_json(const EstimationProblem& problem, const EstimationResult& result);
/// q,outliers,kind,p1_lo,p1_hi,p2_lo,p2_hi: one line per box of each set (kind inner or
/// boundary), then the level's unresolved boxes (outliers "?", kind unresolved).
std::string estimation_boxes_csv(const EstimationResult& result);

std::vector<std::string> estimation_output_files(const std::string& folder);
std::vector<std::string> write_estimation_outputs(const std::string& folder, const EstimationProblem& problem,
                                                  const EstimationResult& result);

}  // namespace gesmi::io
