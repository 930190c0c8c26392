#pragma once
// The result of `gesmi localize` as JSON: the hypotheses with their outlier sets,
// S_q split by outlier set, and the safety of each datum. Written twice: as the
// `localization` field of the --json report (data as indices from 0, ranges first,
// for programs) and as OUT/summary.json (data by their number in the scenario
// file, from 1, for people). Fields: docs/setinversion.md, section 4.

#include <nlohmann/json.hpp>

#include "solver/setinv/localization/localization_problem.h"

namespace gesmi::io {

enum class DatumNumbering {
  index,  // 0-based, ranges first then bearings (the problem's order)
  file,   // the measurement's position in the scenario file, from 1
};

nlohmann::json localization_json(const LocalizationProblem& problem, const LocalizationResult& result,
                                 DatumNumbering numbering);

/// OUT/summary.json: the scenario's name, the data, localization_json with file
/// numbers, and the timings (whole run, and each GOMNE step).
nlohmann::json localization_summary_json(const LocalizationProblem& problem, const LocalizationResult& result);

}  // namespace gesmi::io
