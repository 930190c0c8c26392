#pragma once
// What `gesmi kalman` says about its fit: the consistency checks, the flagged inputs
// and the biases, as printed lines and as the --json report's fields.

#include <nlohmann/json.hpp>

#include "solver/kalman/kalman_smoother.h"

namespace gesmi::cli {

/// The chi-square line, one line per flagged input and, with biases, their estimates
/// (stdout, after the summary line).
void print_kalman_checks(const KalmanResult& result);
/// "mark 3" or "GPS fix 0": rows numbered as in the mission's tables.
std::string input_name(const ConstraintRef& input);
/// The report's consistency, flagged and biases fields.
void add_kalman_checks(nlohmann::json& kalman, const KalmanResult& result);

}  // namespace gesmi::cli
