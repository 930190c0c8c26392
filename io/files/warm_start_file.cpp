#include "io/files/warm_start_file.h"

#include "io/format_error.h"
#include "io/io_version.h"
#include "io/files/mission_digest.h"
#include "io/files/result_file.h"
#include "solver/solve/solve_mission.h"

namespace gesmi::io {

MissionSolution read_warm_start(const std::string& path, const Mission& mission) {
  return read_warm_start(path, mission, navigation_digest(mission, kResultDigest));
}

MissionSolution read_warm_start(const std::string& path, const Mission& mission, std::string navigation) {
  SolveResult previous = read_result(path);  // its waterfall is reused where unchanged
  const auto refuse = [&](const std::string& why) { throw FormatError("--from " + path + ": " + why); };
  if (previous.format_version < 2)
    refuse("written by an earlier gesmi, without the digests a warm start checks; run a cold solve");
  // Another gesmi may enclose differently (a widened box, a fixed margin): its domains
  // are not the ones this gesmi would start from.
  if (previous.version != version())
    refuse("computed by gesmi " + previous.version + ", this is gesmi " + std::string(version()) + "; run a cold solve");
  // A result of format 2 to 5 holds SHA-256 fingerprints: the mission's are computed
  // again of that kind.
  const DigestKind kind = result_digest_kind(previous.format_version);
  if (kind != kResultDigest) navigation = navigation_digest(mission, kind);
  if (previous.navigation_digest != navigation)
    refuse("the navigation data (DVL, attitude, depth, altitude, GPS) differ from the mission it was computed on; run a cold solve");
  if (previous.bounds_digest != bounds_digest(mission.model, kind))
    refuse("the sensor bounds differ from those it was computed with; run a cold solve");
  const std::size_t rows = previous.solution.mark_count();
  if (rows > mission.mark_count() || previous.marks_digest != marks_digest(mission, rows, kind))
    refuse("the mark table changed other than by added rows; run a cold solve");
  if (const std::string why = warm_start_problem(mission, previous.solution); !why.empty()) refuse(why);
  return std::move(previous.solution);
}

}  // namespace gesmi::io
