#pragma once
// A mission as a GESMI text log (io/imports/import_gesmi_txt.h, docs/formats.md), e.g. to
// make the sample in missions/ from a simulated mission. Each half-width is the
// mission's per-sample one, or else the model's bound at that sample (rounded up,
// as the solver computes it); x and y are the GPS fixes in the local frame (north,
// east) with their box half-widths on the rows at the fix times, and "nan nan"
// elsewhere. Marks, mines and truth are not part of the format.

#include <ostream>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io {

/// Writes the log; the mission's GPS fixes must be in the local frame (as
/// read_mission leaves them) and each at a sample time, else FormatError naming
/// `source`, the mission's file.
void write_gesmi_txt(const Mission& mission, const std::string& source, std::ostream& out);

/// The same into a file, atomically (temporary name, then rename).
void export_gesmi_txt(const Mission& mission, const std::string& source, const std::string& path);

}  // namespace gesmi::io
