#pragma once
// The solver's result file (docs/formats.md): tube, increments, mine boxes,
// reconstructed waterfall, mark candidates and outliers, and attributes (status,
// sweeps, timings, input digests, version). Written atomically; read back for warm
// reruns and for `gesmi waterfall` / `gesmi candidates`.
//
// Every dataset carries its SHA-256 and the root carries one over the attributes
// and the dataset digests: read_result() refuses a result that differs from what
// gesmi wrote, so a warm start never trusts edited domains (docs/guarantees.md).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "solver/network/tube_domains.h"
#include "solver/network/waterfall.h"

namespace gesmi::io {

struct SolveResult {
  std::vector<double> time;
  TubeDomains domains;                    // tube, increments, mines
  Waterfall waterfall;
  std::vector<double> mark_time, mark_range;  // the mark table the result was computed with
  std::vector<std::int32_t> mark_mine;
  std::vector<std::uint64_t> candidates;  // per mark row: candidate mines (bit i: mine i)
  std::vector<std::int32_t> outlier;      // per mark row: 1 when every outlier hypothesis removes it
  std::vector<std::int32_t> gps_outlier;  // per GPS fix
  int mine_count = 0;
  bool consistent = true;
  std::string message;                    // the inconsistency, or empty
  std::int64_t sweeps = 0;
  bool converged = false;
  std::int64_t minimal_outliers = 0;
  std::map<std::string, double> timings_ms;
  std::string navigation_digest, bounds_digest, marks_digest;  // SHA-256 of the inputs (io/mission_digest.h)
  std::int64_t mark_count = 0;            // rows of the mark table the result was computed with
  std::string version;
  /// Layout of the file read: 1 for results written before digests existed (readable,
  /// but unfit for a warm start), 2 today.
  std::int64_t format_version = 2;
};

void write_result(const SolveResult& result, const std::string& path);
/// Reads a result; FormatError naming the file and dataset when it is not a valid
/// gesmi result or differs from what gesmi wrote (the waterfall is read only when
/// with_waterfall).
SolveResult read_result(const std::string& path, bool with_waterfall = true);

}  // namespace gesmi::io
