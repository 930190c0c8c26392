#include "io/imports/import_gps_csv.h"

#include <cmath>

#include "io/text/csv_number.h"
#include "io/imports/csv_reader.h"

namespace gesmi::io {

GpsLog read_gps_csv(std::istream& in, const std::string& name, double first_time, double last_time,
                    std::vector<UnusedFix>* unused, const std::string& why) {
  CsvReader csv(in, name);
  csv.read_header({"time", "longitude", "latitude"}, {"north_halfwidth", "east_halfwidth"});
  const int north = csv.column("north_halfwidth"), east = csv.column("east_halfwidth");
  if ((north < 0) != (east < 0)) csv.fail_line("header: north_halfwidth and east_halfwidth go together");
  GpsLog log;
  while (csv.next()) {
    const double t = csv.number(0), lon = csv.number(1), lat = csv.number(2);
    if (!log.time.empty()) expect_increasing_time(csv, 0, t, log.time.back(), log.line.back());
    if (std::fabs(lon) > 180.0) csv.fail(1, format_number(lon) + " is not in [-180, 180] degrees");
    if (std::fabs(lat) > 90.0) csv.fail(2, format_number(lat) + " is not in [-90, 90] degrees");
    if ((t < first_time || t > last_time) && unused) {
      unused->push_back({name + ":" + std::to_string(csv.line()), t, why});
      continue;
    }
    if (t < first_time || t > last_time)
      csv.fail(0, format_number(t) + " s is outside the mission [" + format_number(first_time) + ", " +
                      format_number(last_time) + "] s");
    log.time.push_back(t);
    log.longitude.push_back(lon);
    log.latitude.push_back(lat);
    log.line.push_back(csv.line());
    if (north >= 0) {
      const auto bound = [&](int column) {
        const double h = csv.number(static_cast<std::size_t>(column));
        if (h < 0.0) csv.fail(static_cast<std::size_t>(column), "a half-width must be >= 0");
        return h;
      };
      log.north_halfwidth.push_back(bound(north));
      log.east_halfwidth.push_back(bound(east));
    }
  }
  return log;
}

}  // namespace gesmi::io
