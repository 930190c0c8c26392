#include "io/import_marks_csv.h"

#include "io/csv_number.h"
#include "io/csv_reader.h"
#include "io/message_text.h"

namespace gesmi::io {

MarkRules mark_rules(const Mission& m) {
  return {m.time.front(), m.time.back(), m.model.sonar_max_range + m.model.mark_range, m.mine_count};
}

MarkTable read_marks_csv(std::istream& in, const std::string& name, const MarkRules& rules) {
  CsvReader csv(in, name);
  csv.read_header({"time", "mine", "range", "side"});
  MarkTable marks;
  while (csv.next()) {
    const double t = csv.number(0);
    if (t < rules.first_time || t > rules.last_time)
      csv.fail(0, format_number(t) + " s is outside the mission [" + format_number(rules.first_time) + ", " +
                      format_number(rules.last_time) + "] s");
    const std::string_view mine_text = csv.text(1);
    std::int32_t mine = -1;
    if (!mine_text.empty() && mine_text != "?") {
      const std::optional<long long> i = parse_integer(mine_text);
      if (!i) csv.fail(1, "expected a mine number, '?' or nothing, found " + quoted_input(mine_text));
      if (*i < -1 || *i >= rules.mine_count) {
        const std::string known = rules.mine_count == 0 ? "the mission has no mines"
                                                        : "the mission's mines are 0.." + std::to_string(rules.mine_count - 1);
        csv.fail(1, "unknown mine " + std::string(mine_text) + ": " + known +
                        " ('?' when not associated; --mines K sets the number of mines)");
      }
      mine = static_cast<std::int32_t>(*i);
    }
    const double range = csv.number(2);
    if (range < 0.0) csv.fail(2, format_number(range) + " m is negative");
    if (range > rules.max_range)
      csv.fail(2, format_number(range) + " m is beyond the sonar's maximum range plus the range bound (" +
                      format_number(rules.max_range) + " m)");
    const std::string_view side_text = csv.text(3);
    std::int32_t side = 0;
    if (side_text == "starboard" || side_text == "+1" || side_text == "1") side = 1;
    else if (side_text == "port" || side_text == "-1") side = -1;
    else csv.fail(3, "expected starboard, port, +1 or -1, found " + quoted_input(side_text));
    marks.time.push_back(t);
    marks.mine.push_back(mine);
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
