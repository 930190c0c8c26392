#include "io/imports/time_column.h"

#include "io/text/message_text.h"
#include "io/time/utc_time.h"

namespace gesmi::io {

TimeColumn::TimeColumn(const ColumnMap& map, std::optional<std::int64_t> epoch, bool may_set_epoch)
    : format_(map.time_format), timezone_(map.timezone_seconds), epoch_(epoch), may_set_epoch_(may_set_epoch) {}

double TimeColumn::read(const CsvReader& csv, std::size_t column) {
  if (format_ == TimeFormat::seconds) return csv.number(column);
  const std::string_view text = csv.text(column);
  if (text.empty()) csv.fail(column, "missing value");
  const ParsedTime parsed = format_ == TimeFormat::iso8601 ? parse_iso8601(text, timezone_) : parse_epoch_seconds(text);
  if (!parsed.time) csv.fail(column, parsed.error + ", found " + quoted_input(text));
  if (!epoch_) {
    if (!may_set_epoch_)
      csv.fail(column, "an absolute time needs the mission's epoch, which it has not: import its navigation with absolute times, or with its epoch given");
    epoch_ = parsed.time->seconds;
  }
  return parsed.time->since(*epoch_);
}

}  // namespace gesmi::io
