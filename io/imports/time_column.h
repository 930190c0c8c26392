#pragma once
// The time column of a mapped CSV (column_map.h): seconds as they are, or absolute
// times (ISO 8601, Unix epoch) turned into seconds after the mission's epoch, the
// whole UTC second at or before the first time read when no epoch is given.

#include <cstdint>
#include <optional>

#include "io/imports/column_map.h"
#include "io/imports/csv_reader.h"

namespace gesmi::io {

class TimeColumn {
 public:
  /// `epoch`: the mission's, when known. `may_set_epoch`: the first absolute time sets
  /// it when not known (a navigation log); otherwise absolute times need it (marks).
  TimeColumn(const ColumnMap& map, std::optional<std::int64_t> epoch, bool may_set_epoch);

  /// The current row's time at `column`, in seconds after the epoch.
  double read(const CsvReader& csv, std::size_t column);

  std::optional<std::int64_t> epoch() const { return epoch_; }

 private:
  TimeFormat format_;
  std::optional<int> timezone_;
  std::optional<std::int64_t> epoch_;
  bool may_set_epoch_;
};

}  // namespace gesmi::io
