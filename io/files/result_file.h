#pragma once
// The solver's result file (docs/formats.md): a MissionSolution (tube, increments,
// mine boxes, reconstructed waterfall, mark table, candidates and outliers, status,
// sweeps, timings) with the digests of its inputs and the gesmi version. Written
// atomically; read back for warm reruns and for `gesmi waterfall` / `candidates`.
//
// Every dataset carries its SHA-256 and the root carries one over the attributes
// and the dataset digests: read_result() refuses a result that differs from what
// gesmi wrote, so a warm start never trusts edited domains (docs/guarantees.md).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solver/mission/mission.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::io {

/// A result file: the solution and what proves which inputs it was computed from.
struct SolveResult {
  MissionSolution solution;
  std::string navigation_digest, bounds_digest, marks_digest;  // SHA-256 of the inputs (io/files/mission_digest.h)
  std::string version;  // gesmi that wrote it
  std::optional<std::int64_t> epoch;  // the mission's UTC epoch of t = 0, when it has one
  /// The mission's local frame origin (WGS84); absent in results before format 5.
  std::optional<GeoOrigin> origin;
  /// Layout of the file read: 1 for results written before digests existed (readable,
  /// but unfit for a warm start), 2 to 4 with digests, 5 today (what it is written as).
  std::int64_t format_version = 5;
};

/// The parts of a result a reader needs besides its attributes, times, mine boxes and
/// mark table. Parts left out stay empty; the root digest still covers their digests,
/// and every dataset read is checked against its own.
struct ResultParts {
  bool tube = true;  // the tube and the increments (warm starts, exports)
  bool waterfall = true;
};

/// Records in `result` what it was computed from: the digests of the mission's
/// navigation (`navigation_digest`, computed when empty), bounds and marks, the gesmi
/// version, the mission's epoch and its origin.
void record_inputs(SolveResult& result, const Mission& mission, std::string navigation_digest = {});

void write_result(const SolveResult& result, const std::string& path);
/// Reads a result; FormatError naming the file and dataset when it is not a valid
/// gesmi result or differs from what gesmi wrote.
SolveResult read_result(const std::string& path, ResultParts parts = {});

}  // namespace gesmi::io
