#pragma once
// The solver's result file (docs/formats.md): a MissionSolution (tube, increments,
// mine boxes, reconstructed waterfall, mark table, candidates and outliers, status,
// sweeps, timings) with the digests of its inputs and the gesmi version. Written
// atomically; read back for warm reruns and for `gesmi waterfall` / `candidates`.
//
// Every dataset carries its digest (XXH3-128; SHA-256 in formats 2 to 5) and the root
// carries one over the attributes and the dataset digests: read_result() refuses a
// result that differs from what gesmi wrote, so a warm start never trusts edited
// domains (docs/guarantees.md).

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/digest/digest.h"
#include "solver/mission/mission.h"
#include "solver/solve/mission_solution.h"

namespace gesmi::io {

/// The layout results are written in (docs/formats.md, "Result file").
inline constexpr std::int64_t kResultFormat = 7;

/// The digests of a result of that format: SHA-256 in formats 2 to 5, XXH3-128 from 6.
constexpr DigestKind result_digest_kind(std::int64_t format_version) {
  return format_version >= 6 ? DigestKind::xxh128 : DigestKind::sha256;
}
/// The digests results are written with, and the mission fingerprints they store.
inline constexpr DigestKind kResultDigest = result_digest_kind(kResultFormat);

/// A result file: the solution and what proves which inputs it was computed from.
struct SolveResult {
  MissionSolution solution;
  // Digests of the inputs (io/files/mission_digest.h), of the kind of format_version.
  std::string navigation_digest, bounds_digest, marks_digest;
  std::string version;  // gesmi that wrote it
  std::optional<std::int64_t> epoch;  // the mission's UTC epoch of t = 0, when it has one
  /// The mission's local frame origin (WGS84); absent in results before format 5.
  std::optional<GeoOrigin> origin;
  /// Layout of the file read: 1 for results written before digests existed (readable,
  /// but unfit for a warm start), 2 to 5 with SHA-256 digests, 6 with XXH3-128 ones;
  /// a result is always written in kResultFormat.
  std::int64_t format_version = kResultFormat;
};

/// Rows of a tube handed over block by block: `result` holds what was read before the
/// tube (attributes, times), x, y and z the rows first to first + x.size() - 1.
using TubeRows = std::function<void(const SolveResult& result, std::size_t first, std::span<const Interval> x,
                                    std::span<const Interval> y, std::span<const Interval> z)>;

/// The parts of a result a reader needs besides its attributes, times, mine boxes and
/// mark table. Parts left out stay empty, but are still checked against their digests
/// (in blocks, none kept), as every dataset read is.
struct ResultParts {
  bool tube = true;        // the tube (warm starts, exports)
  bool increments = true;  // with the tube (warm starts)
  bool waterfall = true;
  /// When set, the tube's rows go there block by block, in order, instead of into the
  /// result, and `tube` and `increments` are ignored (no tube nor increments kept): a
  /// tube of 10^7 steps is 480 MB. An error found later (a digest, a row, an empty
  /// interval in a consistent result) is thrown after the blocks it covers were handed
  /// over, so the receiver writes to a temporary output and discards it.
  TubeRows tube_rows = nullptr;
  /// Off only for a read of a file that a streamed read (`tube_rows`) then reads whole and
  /// checks: the export of the tube CSV reads the status first.
  bool check_unread = true;

  bool reads_tube() const { return tube_rows || tube; }
  bool keeps_increments() const { return increments && tube && !tube_rows; }
};

/// Records in `result` what it was computed from: the digests of the mission's
/// navigation (`navigation_digest`, of today's kind, computed when empty), bounds and
/// marks, the gesmi version, the mission's epoch and its origin; sets its
/// format_version to kResultFormat.
void record_inputs(SolveResult& result, const Mission& mission, std::string navigation_digest = {});

/// Writes the result in today's format; FormatError when its input digests are not of
/// today's kind (a result read from an earlier format, not recorded again).
void write_result(const SolveResult& result, const std::string& path);
/// Reads a result; FormatError naming the file and dataset when it is not a valid
/// gesmi result or differs from what gesmi wrote.
SolveResult read_result(const std::string& path, ResultParts parts = {});

}  // namespace gesmi::io
