#pragma once
// Exports of a result for other tools (docs/formats.md, "Exports of a result"):
//   - the mine boxes as CSV, in local metres and latitude/longitude;
//   - the tube as CSV, one row per sample (time, UTC when the epoch is known, local
//     bounds, latitude/longitude bounds);
//   - GeoJSON (RFC 7946) for GIS: the envelope as one valid (Multi)Polygon, the union
//     of the tube's boxes simplified only outward; the mine boxes as polygons; the GPS
//     fixes as points when the mission is given.
// Local bounds are written exactly (shortest round-trip text); geodetic bounds are
// outward (io/exports/geodetic_grid.h), so they contain the local ones. Every row and
// feature carries the result's status: an inconsistent result's boxes are no answer.

#include <optional>
#include <span>
#include <string>

#include "io/files/result_file.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

/// Why a result's origin allows no latitude/longitude export, with the remedy: none
/// recorded (a result of an older gesmi), or beyond kGeodeticExportLatitude; empty when
/// it allows them. The CSV exports then leave their latitude/longitude columns NaN;
/// the GeoJSON export refuses (FormatError).
std::string geodetic_problem(const std::optional<GeoOrigin>& origin);

/// "consistent" or "inconsistent".
const char* status_name(const MissionSolution& solution);

/// Marks that belong to mine i: rows whose only remaining candidate is i and that no
/// hypothesis removes.
int marks_of_mine(const MissionSolution& solution, int mine);

void write_mines_csv(const SolveResult& result, const std::string& path);
/// The tube of the result file `result_path`, read block by block (a tube of 10^7 steps
/// is 480 MB of bounds) and checked as read_result() checks it; nothing is written when
/// the file is refused, or when it no longer holds `read_before` (the same file read
/// without its tube, whose status the caller accepted: replaced meanwhile).
void write_tube_csv(const std::string& result_path, const SolveResult& read_before, const std::string& path);
/// `fixes`: the mission whose GPS fixes become points (nullptr: none).
void write_geojson(const SolveResult& result, const Mission* fixes, const std::string& path);

}  // namespace gesmi::io
