#include "io/exports/export_gesmi_txt.h"

#include <algorithm>
#include <fstream>
#include <string>

#include "io/output/atomic_output.h"
#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/imports/import_gesmi_txt.h"

namespace gesmi::io {

void write_gesmi_txt(const Mission& m, const std::string& source, std::ostream& out) {
  const std::size_t n = m.size();
  if (m.gps_north.size() != m.gps_time.size())
    throw FormatError(source + ": GESMI text export: the GPS fixes are not in the local frame (read the mission with read_mission)");
  // The fix of each sample, if any.
  std::vector<std::ptrdiff_t> fix_at(n, -1);
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    const auto at = std::lower_bound(m.time.begin(), m.time.end(), m.gps_time[i]);
    if (at == m.time.end() || *at != m.gps_time[i])
      throw FormatError(source + ": /gps/time: fix " + std::to_string(i) + " at " + format_number(m.gps_time[i]) +
                        " s is not at a sample time (a GESMI text log holds positions on sample rows only)");
    const auto k = static_cast<std::size_t>(at - m.time.begin());
    if (fix_at[k] >= 0)
      throw FormatError(source + ": /gps/time: two fixes at " + format_number(m.gps_time[i]) +
                        " s (a GESMI text log holds one position per sample row)");
    fix_at[k] = static_cast<std::ptrdiff_t>(i);
  }
  // The log's channel order (import_gesmi_txt.h): the readings and bounds of each.
  const std::vector<double>* values[GesmiColumn::x];
  const std::vector<double>* given[GesmiColumn::x];
  for (std::size_t c = 0; c < GesmiColumn::x; ++c) {
    const NavChannel& channel = nav_channel(gesmi_column_name(c));
    values[c] = &(m.*channel.readings);
    given[c] = &(m.half_widths.*channel.half_widths);
  }
  out << "# GESMI text log written by gesmi export --format gesmi-txt (docs/formats.md)\n"
      << "# SI units, angles in radians; x north and y east in metres about the origin "
      << format_number(m.origin.latitude) << "," << format_number(m.origin.longitude) << " (lat,lon)\n"
      << "# t roll droll pitch dpitch heading dheading vx dvx vy dvy vz dvz depth ddepth altitude daltitude x dx y dy\n";
  std::string line;
  for (std::size_t k = 0; k < n; ++k) {
    // One reused line buffer, numbers appended in place (no allocation per number).
    line.clear();
    append_number(line, m.time[k]);
    const auto field = [&](double x) {
      line += ' ';
      append_number(line, x);
    };
    for (std::size_t c = 0; c < GesmiColumn::x; ++c) {
      const double value = (*values[c])[k];
      field(value);
      field(given[c]->empty() ? column_half_width(m.model, c, value) : (*given[c])[k]);
    }
    if (fix_at[k] >= 0) {
      const auto i = static_cast<std::size_t>(fix_at[k]);
      const bool own = !m.gps_given_north_halfwidth.empty();
      field(m.gps_north[i]);
      field(own ? m.gps_given_north_halfwidth[i] : m.gps_north_halfwidth[i]);
      field(m.gps_east[i]);
      field(own ? m.gps_given_east_halfwidth[i] : m.gps_east_halfwidth[i]);
    } else {
      line += " nan nan nan nan";
    }
    line += '\n';
    out << line;
  }
}

void export_gesmi_txt(const Mission& mission, const std::string& source, const std::string& path) {
  AtomicOutput out(path);
  {
    std::ofstream file(out.temp_path(), std::ios::binary);
    write_gesmi_txt(mission, source, file);
    file.flush();
    if (!file) throw FormatError(path + ": cannot write (disk full?)");
  }
  out.commit();
}

}  // namespace gesmi::io
