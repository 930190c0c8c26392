#include "io/imports/import_marks_csv.h"

#include "io/imports/csv_number.h"
#include "io/imports/csv_reader.h"
#include "io/text/message_text.h"

namespace gesmi::io {

MarkTable read_marks_csv(std::istream& in, const std::string& name, const MarkRules& rules) {
  CsvReader csv(in, name);
  csv.read_header({"time", "mine", "range", "side"});
  MarkTable marks;
  while (csv.next()) {
    const double t = csv.number(0);
    const std::string_view mine_text = csv.text(1);
    long long mine = -1;
    if (!mine_text.empty() && mine_text != "?") {
      const std::optional<long long> i = parse_integer(mine_text);
      if (!i) csv.fail(1, "expected a mine number, '?' or nothing, found " + quoted_input(mine_text));
      mine = *i;
    }
    const double range = csv.number(2);
    const std::string_view side_text = csv.text(3);
    std::int32_t side = 0;
    if (side_text == "starboard" || side_text == "+1" || side_text == "1") side = 1;
    else if (side_text == "port" || side_text == "-1") side = -1;
    else csv.fail(3, "expected starboard, port, +1 or -1, found " + quoted_input(side_text));
    if (const auto problem = check_mark(rules, t, mine, range, side))
      csv.fail(static_cast<std::size_t>(problem->field), problem->reason);  // MarkField's order is the columns'
    marks.time.push_back(t);
    marks.mine.push_back(static_cast<std::int32_t>(mine));
    marks.range.push_back(range);
    marks.side.push_back(side);
  }
  return marks;
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
