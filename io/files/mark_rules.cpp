#include "io/files/mark_rules.h"

#include <cmath>

#include "io/text/csv_number.h"

namespace gesmi::io {

MarkRules mark_rules(const Mission& m) {
  return {m.time.front(), m.time.back(), m.model.sonar_max_range + m.model.mark_range, m.mine_count};
}

const char* mark_field_name(MarkField field) {
  switch (field) {
    case MarkField::time: return "time";
    case MarkField::mine: return "mine";
    case MarkField::range: return "range";
    case MarkField::side: return "side";
  }
  return "mark";
}

std::optional<MarkProblem> check_mark(const MarkRules& rules, double time, long long mine, double range, int side) {
  if (!std::isfinite(time) || time < rules.first_time || time > rules.last_time)
    return MarkProblem{MarkField::time, format_number(time) + " s is outside the mission [" + format_number(rules.first_time) +
                                            ", " + format_number(rules.last_time) + "] s"};
  if (mine < -1 || mine >= rules.mine_count) {
    const std::string known = rules.mine_count == 0 ? "the mission has no mines"
                                                    : "the mission's mines are 0.." + std::to_string(rules.mine_count - 1);
    return MarkProblem{MarkField::mine, "unknown mine " + std::to_string(mine) + ": " + known +
                                            " ('?' when not associated; --mines K sets the number of mines)"};
  }
  if (!std::isfinite(range)) return MarkProblem{MarkField::range, "must be a finite number of metres"};
  if (range < 0.0) return MarkProblem{MarkField::range, format_number(range) + " m is negative"};
  if (range > rules.max_range)
    return MarkProblem{MarkField::range, format_number(range) + " m is beyond the sonar's maximum range plus the range bound (" +
                                             format_number(rules.max_range) + " m)"};
  if (side != 1 && side != -1)
    return MarkProblem{MarkField::side, "must be +1 (starboard) or -1 (port), found " + std::to_string(side)};
  return std::nullopt;
}

}  // namespace gesmi::io
