#include "io/imports/import_marks_csv.h"

#include <array>

#include "io/text/csv_number.h"
#include "io/imports/csv_reader.h"
#include "io/imports/time_column.h"
#include "io/text/message_text.h"

namespace gesmi::io {

namespace {

// The rows of a marks file whose time, mine, range and side are at `columns` (the
// MarkField order); `time` reads the time column, `range_factor` takes ranges to metres.
MarkTable read_mark_rows(CsvReader& csv, const std::array<std::size_t, 4>& columns, TimeColumn* time,
                         double range_factor, const MarkRules& rules) {
  MarkTable marks;
  while (csv.next()) {
    const double t = time ? time->read(csv, columns[0]) : csv.number(columns[0]);
    const std::string_view mine_text = csv.text(columns[1]);
    long long mine = -1;
    if (!mine_text.empty() && mine_text != "?") {
      const std::optional<long long> i = parse_integer(mine_text);
      if (!i) csv.fail(columns[1], "expected a mine number, '?' or nothing, found " + quoted_input(mine_text));
      mine = *i;
    }
    const double range = csv.number(columns[2]) * range_factor;
    const std::string_view side_text = csv.text(columns[3]);
    std::int32_t side = 0;
    if (side_text == "starboard" || side_text == "+1" || side_text == "1") side = 1;
    else if (side_text == "port" || side_text == "-1") side = -1;
    else csv.fail(columns[3], "expected starboard, port, +1 or -1, found " + quoted_input(side_text));
    if (const auto problem = check_mark(rules, t, mine, range, side))
      csv.fail(columns[static_cast<std::size_t>(problem->field)], problem->reason);
    marks.time.push_back(t);
    marks.mine.push_back(static_cast<std::int32_t>(mine));
    marks.range.push_back(range);
    marks.side.push_back(side);
  }
  return marks;
}

}  // namespace

MarkTable read_marks_csv(std::istream& in, const std::string& name, const MarkRules& rules) {
  CsvReader csv(in, name);
  csv.read_header({"time", "mine", "range", "side"});
  return read_mark_rows(csv, {0, 1, 2, 3}, nullptr, 1.0, rules);
}

MarkTable read_mapped_marks_csv(std::istream& in, const std::string& name, const MarkRules& rules, const ColumnMap& map,
                                std::optional<std::int64_t> epoch) {
  CsvReader csv(in, name);
  csv.read_any_header(map.delimiter);
  const std::vector<int> c = mapped_columns(csv, map, marks_map_schema());
  TimeColumn time(map, epoch, false);
  return read_mark_rows(csv, {static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1]), static_cast<std::size_t>(c[2]),
                              static_cast<std::size_t>(c[3])},
                        &time, map.field("range")->unit.factor, rules);
}

void replace_marks(Mission& m, MarkTable marks) {
  m.mark_time = std::move(marks.time);
  m.mark_mine = std::move(marks.mine);
  m.mark_range = std::move(marks.range);
  m.mark_side = std::move(marks.side);
  m.truth_marks_outlier.clear();
  m.truth_marks_mine.clear();
}

}  // namespace gesmi::io
