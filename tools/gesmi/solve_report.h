#pragma once
// What `gesmi solve` prints about a solution: the candidate mines of marks without
// a number, the outlier hypotheses and the one-line summary (--json: command_report.h).

#include <string>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::cli {

/// Notes for the operator on stderr: a warm rerun solved cold, steps whose readings
/// contradict the model's bounds, the inputs nothing else checks, the hypotheses at q*.
void print_solve_notes(const MissionSolution& solution);
/// The mines that rest on one mark and the lone GPS fix (unchecked_inputs.h), on stderr.
void print_unchecked_notes(const MissionSolution& solution);
/// The warnings of the readings' check (step_regimes.h), on stderr; nothing when it found none.
void print_regime_notes(const StepRegimeReport& report);
/// The candidates of unnumbered marks and the summary line naming the files written (stdout).
void print_solve_summary(const Mission& mission, const MissionSolution& solution, const std::vector<std::string>& written);

}  // namespace gesmi::cli
