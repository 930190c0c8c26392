#pragma once
// What a mark must satisfy to belong to a mission, stated once for every way a mark
// comes in: the mission file reader, `gesmi import marks`, `gesmi marks add` and the
// Python module's add_mark.

#include <optional>
#include <string>

#include "solver/mission/mission.h"

namespace gesmi::io {

struct MarkRules {
  double first_time = 0.0, last_time = 0.0;  // s, the navigation's span
  double max_range = 0.0;                    // m: the sonar's range plus the range bound
  int mine_count = 0;
};
MarkRules mark_rules(const Mission& mission);

enum class MarkField { time, mine, range, side };  // the marks CSV's column order
/// "time", "mine", "range", "side".
const char* mark_field_name(MarkField field);

struct MarkProblem {
  MarkField field;
  std::string reason;  // e.g. "601 s is outside the mission [0, 600] s"
};

/// Why the mark (mine -1: not associated; side +1 starboard, -1 port) cannot belong
/// to a mission with these rules, or nullopt.
std::optional<MarkProblem> check_mark(const MarkRules& rules, double time, long long mine, double range, int side);

}  // namespace gesmi::io
