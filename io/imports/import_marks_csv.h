#pragma once
// The operator's mark table as CSV (docs/formats.md):
//   time,mine,range,side
// time in s inside the mission; mine a number 0..K-1, or empty, '?' or -1 when not
// associated; range the measured slant range in m, from 0 to the sonar's maximum
// range plus the range bound (what the mission file accepts); side 'starboard',
// 'port', '+1', '1' or '-1'. Rows in any order.

#include <cstdint>
#include <optional>
#include <istream>
#include <string>
#include <vector>

#include "io/imports/column_map.h"
#include "io/files/mark_rules.h"
#include "solver/mission/mission.h"

namespace gesmi::io {

struct MarkTable {
  std::vector<double> time, range;
  std::vector<std::int32_t> mine, side;
};

/// Reads and validates a marks CSV; FormatError "name:LINE: field: reason". May hold
/// no mark.
MarkTable read_marks_csv(std::istream& in, const std::string& name, const MarkRules& rules);

/// A marks file read through a column map (column_map.h: time, mine, range, side);
/// absolute times are taken relative to the mission's `epoch` (needed for them).
MarkTable read_mapped_marks_csv(std::istream& in, const std::string& name, const MarkRules& rules, const ColumnMap& map,
                                std::optional<std::int64_t> epoch);

/// Replaces the mission's mark table. The per-mark truth of a simulated mission
/// (/truth/marks_outlier, /truth/marks_mine) describes the old rows and is dropped.
void replace_marks(Mission& mission, MarkTable marks);

}  // namespace gesmi::io
