#pragma once
// The files `gesmi solve -o RESULT.h5` writes: the result and, beside it when asked,
// the mine boxes as CSV (RESULT.mines.csv), GeoJSON (RESULT.geojson) and the envelope
// picture (RESULT.envelope.png).

#include <string>
#include <vector>

#include "io/files/result_file.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

/// RESULT.mines.csv, RESULT.geojson, RESULT.envelope.png for a result path.
std::vector<std::string> solve_output_siblings(const std::string& result_path);

/// The siblings to write beside the result.
struct SolveSiblings {
  bool mines_csv = false, geojson = false, envelope_png = false;
};

/// The result and the siblings asked for, in the order write_solve_outputs() writes
/// them.
std::vector<std::string> asked_solve_outputs(const std::string& result_path, const SolveSiblings& asked);

/// Writes the result and the asked siblings (each atomically; inside an OutputSet, as
/// one set); `mission_name` titles the picture. Returns the paths written, the result
/// first.
std::vector<std::string> write_solve_outputs(const SolveResult& result, const Mission& mission,
                                             const std::string& result_path, const std::string& mission_name,
                                             const SolveSiblings& siblings);

}  // namespace gesmi::io
