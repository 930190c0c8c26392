#include "io/imports/import_nav_csv.h"

#include "io/imports/csv_reader.h"

namespace gesmi::io {

const std::array<NavHalfWidthColumn, 8>& nav_half_width_columns() {
  // "<channel>_halfwidth", one per navigation channel (mission.h), in its order.
  static const std::array<std::string, 8> names = [] {
    std::array<std::string, 8> out;
    for (std::size_t i = 0; i < 8; ++i) out[i] = std::string(nav_channels()[i].name) + "_halfwidth";
    return out;
  }();
  static const std::array<NavHalfWidthColumn, 8> columns = [] {
    std::array<NavHalfWidthColumn, 8> out;
    for (std::size_t i = 0; i < 8; ++i) out[i] = {names[i], nav_channels()[i].half_widths};
    return out;
  }();
  return columns;
}

NavLog read_nav_csv(std::istream& in, const std::string& name) {
  const auto& hw = nav_half_width_columns();
  CsvReader csv(in, name);
  csv.read_header({"time", "roll", "pitch", "heading", "vx", "vy", "vz", "altitude", "depth"},
                  {hw[0].name, hw[1].name, hw[2].name, hw[3].name, hw[4].name, hw[5].name, hw[6].name, hw[7].name});
  NavLog log;
  std::vector<double>* values[9] = {&log.time, &log.roll, &log.pitch, &log.heading, &log.vx,
                                    &log.vy,   &log.vz,   &log.altitude, &log.depth};
  // Optional half-width columns: (column in the file, array to fill).
  std::vector<std::pair<std::size_t, std::vector<double>*>> bounds;
  for (const NavHalfWidthColumn& h : hw)
    if (const int c = csv.column(h.name); c >= 0) bounds.emplace_back(static_cast<std::size_t>(c), &(log.half_widths.*h.member));

  std::size_t previous_line = 0;
  while (csv.next()) {
    for (std::size_t c = 0; c < 9; ++c) values[c]->push_back(csv.number(c));
    if (log.time.size() > 1) expect_increasing_time(csv, 0, log.time.back(), log.time[log.time.size() - 2], previous_line);
    previous_line = csv.line();
    log.line.push_back(csv.line());
    for (const auto& [column, array] : bounds) {
      const double h = csv.number(column);
      if (h < 0.0) csv.fail(column, "a half-width must be >= 0");
      array->push_back(h);
    }
  }
  if (log.time.size() < 2)
    csv.fail_line("a navigation log needs at least 2 rows, found " + std::to_string(log.time.size()));
  return log;
}

}  // namespace gesmi::io
