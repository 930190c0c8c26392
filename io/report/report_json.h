#pragma once
// JSON values of gesmi's results for the commands' --json reports (docs/reports.md),
// through nlohmann-json: numbers are written so they read back to the same double
// (bounds therefore exactly, never rounded inward); an infinite bound is the string
// "inf" or "-inf" (JSON has no infinity), an empty interval null.

#include <nlohmann/json.hpp>
#include <string>

#include "solver/interval/box.h"
#include "solver/mission/mission.h"
#include "solver/network/constraint_ref.h"
#include "solver/network/mission_solver.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::io {

/// The JSON text of `value` on one line, as nlohmann-json writes it but for its
/// floating-point numbers, written by std::to_chars: the shortest text that reads back
/// to the same double. (nlohmann's Grisu2 always reads back, but was longer than the
/// shortest for 121 of 200,000 doubles in tests/io/report/report_json_test.cpp.)
std::string dump_shortest(const nlohmann::json& value);

/// A number; NaN becomes null and an infinity "inf" / "-inf".
nlohmann::json number_json(double x);
/// [lo, hi], or null when empty.
nlohmann::json interval_json(const Interval& x);
/// [[north], [east], [down]].
nlohmann::json box_json(const Vec3I& box);
/// {"kind": "mark" | "gps_fix", "row": n}.
nlohmann::json constraint_json(const ConstraintRef& c);
/// The empty domain's structured fields and `text`, its one-line explanation.
nlohmann::json inconsistency_json(const Inconsistency& inconsistency, const std::string& text);

/// A mission's size: samples, duration, GPS fixes, marks, mines, the UTC epoch.
nlohmann::json mission_json(const Mission& mission);

/// A solve's report: status, mode, sweeps, the inconsistency, q* and the outlier
/// hypotheses, per mark its association (candidate mines, outlier flag), the mine boxes.
nlohmann::json solve_json(const Mission& mission, const MissionSolution& solution);

}  // namespace gesmi::io
