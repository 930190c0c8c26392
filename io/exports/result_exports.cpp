#include "io/exports/result_exports.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "io/exports/export_csv.h"
#include "io/output/atomic_output.h"
#include "io/exports/geodetic_grid.h"
#include "io/format_error.h"
#include "io/text/csv_number.h"
#include "io/io_version.h"
#include "io/report/report_json.h"
#include "io/time/utc_time.h"
#include "solver/tube/box_union_outline.h"

namespace gesmi::io {
namespace {

using nlohmann::json;

// The geodetic columns of a result whose origin does not allow them (geodetic_problem).
constexpr GeodeticBox kNoGeodeticBox{NAN, NAN, NAN, NAN};

std::optional<LocalFrame> geodetic_frame(const SolveResult& r) {
  if (!geodetic_problem(r.origin).empty()) return std::nullopt;
  return LocalFrame(*r.origin);
}

// Geodetic bounds of a local box: outward when bounded and within the export radius,
// the whole globe when unbounded or farther, NaN when empty (an inconsistent result).
GeodeticBox geodetic_bounds(GeodeticGrid& grid, const Interval& north, const Interval& east) {
  if (north.is_empty() || east.is_empty()) return {NAN, NAN, NAN, NAN};
  if (!north.is_bounded() || !east.is_bounded() || !within_export_radius(north, east)) return {-90.0, 90.0, -180.0, 180.0};
  return grid.box(north, east);
}

// The geodetic columns of a result's CSV rows: NaN throughout when its origin does not
// allow them.
class GeodeticColumns {
 public:
  explicit GeodeticColumns(const SolveResult& r) : frame_(geodetic_frame(r)) {
    if (frame_) grid_.emplace(*frame_);
  }
  GeodeticColumns(const GeodeticColumns&) = delete;  // the grid refers to the frame
  GeodeticColumns& operator=(const GeodeticColumns&) = delete;
  GeodeticBox operator()(const Interval& north, const Interval& east) {
    return grid_ ? geodetic_bounds(*grid_, north, east) : kNoGeodeticBox;
  }

 private:
  std::optional<LocalFrame> frame_;
  std::optional<GeodeticGrid> grid_;
};

void append_bounds(std::string& row, const Interval& x) {
  row += ',';
  append_number(row, x.is_empty() ? NAN : x.lo());
  row += ',';
  append_number(row, x.is_empty() ? NAN : x.hi());
}

void append_geodetic(std::string& row, const GeodeticBox& g) {
  for (const double v : {g.latitude_lo, g.latitude_hi, g.longitude_lo, g.longitude_hi}) {
    row += ',';
    append_number(row, v);
  }
}

// A closed ring in [longitude, latitude]: every local edge cut into pieces of at most
// kGeodeticPiece metres (the pad the local outline was widened by covers the chords).
json geodetic_ring(const LocalFrame& frame, const OutlineRing& ring) {
  json out = json::array();
  for (std::size_t i = 0; i + 1 < ring.size(); ++i) {
    const OutlinePoint& a = ring[i];
    const OutlinePoint& b = ring[i + 1];
    const int pieces = static_cast<int>(std::max(1.0, std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / kGeodeticPiece)));
    for (int p = 0; p < pieces; ++p) {
      const double f = static_cast<double>(p) / pieces;
      const GeoOrigin g = geodetic_point(frame, a[1] + f * (b[1] - a[1]), a[0] + f * (b[0] - a[0]));  // x east, y north
      out.push_back({g.longitude, g.latitude});
    }
  }
  out.push_back(out.front());
  return out;
}

json geodetic_polygon(const LocalFrame& frame, const OutlinePolygon& polygon) {
  json rings = json::array({geodetic_ring(frame, polygon.exterior)});
  for (const OutlineRing& hole : polygon.holes) rings.push_back(geodetic_ring(frame, hole));
  return rings;
}

// The counter-clockwise ring of a geodetic box.
json box_ring(const GeodeticBox& g) {
  return json::array({json::array({json::array({g.longitude_lo, g.latitude_lo}), json::array({g.longitude_hi, g.latitude_lo}),
                                   json::array({g.longitude_hi, g.latitude_hi}), json::array({g.longitude_lo, g.latitude_hi}),
                                   json::array({g.longitude_lo, g.latitude_lo})})});
}

json feature(json properties, json geometry) {
  return {{"type", "Feature"}, {"properties", std::move(properties)}, {"geometry", std::move(geometry)}};
}

}  // namespace

std::string geodetic_problem(const std::optional<GeoOrigin>& origin) {
  if (!origin)
    return "the result records no origin (written by an older gesmi): solve the mission again to export it in "
           "latitude/longitude";
  if (!(std::abs(origin->latitude) <= kGeodeticExportLatitude))
    return "the origin's latitude " + format_number(origin->latitude) + " is beyond +-" +
           format_number(kGeodeticExportLatitude) + " degrees, where latitude/longitude exports are not supported";
  return {};
}

const char* status_name(const MissionSolution& s) { return s.report.consistent ? "consistent" : "inconsistent"; }

int marks_of_mine(const MissionSolution& s, int mine) {
  int count = 0;
  for (std::size_t j = 0; j < s.candidates.size(); ++j)
    if (s.candidates[j] == std::uint64_t{1} << mine && !(j < s.mark_outlier.size() && s.mark_outlier[j])) ++count;
  return count;
}

void write_mines_csv(const SolveResult& r, const std::string& path) {
  GeodeticColumns geodetic(r);
  const MissionSolution& s = r.solution;
  std::string text =
      "mine,marks,north_lo,north_hi,east_lo,east_hi,down_lo,down_hi,latitude_lo,latitude_hi,longitude_lo,longitude_hi,"
      "status\n";
  for (std::size_t i = 0; i < s.domains.mines.size(); ++i) {
    const Vec3I& m = s.domains.mines[i];
    text += std::to_string(i) + "," + std::to_string(marks_of_mine(s, static_cast<int>(i)));
    for (int c = 0; c < 3; ++c) append_bounds(text, m[c]);
    append_geodetic(text, geodetic(m[0], m[1]));
    text += std::string(",") + status_name(s) + "\n";
  }
  write_text_file(path, text);
}

void write_tube_csv(const std::string& result_path, const SolveResult& read_before, const std::string& path) {
  write_text_file(path, [&](std::ostream& out) {
    std::optional<GeodeticColumns> geodetic;  // with the header, from the first block
    std::string row;
    const auto rows = [&](const SolveResult& r, std::size_t first, std::span<const Interval> north,
                          std::span<const Interval> east, std::span<const Interval> down) {
      const MissionSolution& s = r.solution;
      if (!geodetic) {
        if (s.report.consistent != read_before.solution.report.consistent || s.time != read_before.solution.time ||
            r.navigation_digest != read_before.navigation_digest || r.marks_digest != read_before.marks_digest)
          throw FormatError(result_path + ": changed while it was exported (replaced meanwhile?): export it again");
        geodetic.emplace(r);
        out << "time" << (r.epoch ? ",utc" : "")
            << ",north_lo,north_hi,east_lo,east_hi,down_lo,down_hi,latitude_lo,latitude_hi,longitude_lo,longitude_hi,"
               "status\n";
      }
      for (std::size_t i = 0; i < north.size(); ++i) {
        const double time = s.time[first + i];
        row.clear();
        append_number(row, time);
        if (r.epoch) row += "," + format_iso8601_micro(*r.epoch, time);
        append_bounds(row, north[i]);
        append_bounds(row, east[i]);
        append_bounds(row, down[i]);
        append_geodetic(row, (*geodetic)(north[i], east[i]));
        row += std::string(",") + status_name(s) + "\n";
        out.write(row.data(), static_cast<std::streamsize>(row.size()));
      }
    };
    read_result(result_path, {.tube = false, .increments = false, .waterfall = false, .tube_rows = rows});
  });
}

void write_geojson(const SolveResult& r, const Mission* mission, const std::string& path) {
  if (const std::string why = geodetic_problem(r.origin); !why.empty()) throw FormatError(path + ": " + why);
  const GeoOrigin origin = *r.origin;
  const LocalFrame frame(origin);
  GeodeticGrid grid(frame);  // the mines' boxes as in the mines CSV
  const MissionSolution& s = r.solution;
  const TubeDomains& d = s.domains;
  const std::string status = status_name(s);
  json features = json::array();

  // The envelope: the boxes within the export radius, widened by what the chords
  // between converted points may lose. The tube's own boxes when none lies farther (no
  // copy of them: 320 MB at 10^7 steps).
  const auto far_box = [&](std::size_t k) {
    const bool bounded = !d.px[k].is_empty() && !d.py[k].is_empty() && d.px[k].is_bounded() && d.py[k].is_bounded();
    return bounded && !within_export_radius(d.px[k], d.py[k]);
  };
  std::size_t far = 0;
  for (std::size_t k = 0; k < d.size(); ++k) far += far_box(k) ? 1 : 0;
  std::vector<Interval> near_east, near_north;
  if (far > 0) {
    near_east.assign(d.size(), Interval::empty());
    near_north.assign(d.size(), Interval::empty());
    for (std::size_t k = 0; k < d.size(); ++k)
      if (!far_box(k)) {
        near_north[k] = d.px[k];
        near_east[k] = d.py[k];
      }
  }
  const BoxOutline outline = outline_of_boxes(far > 0 ? std::span<const Interval>(near_east) : d.py,
                                              far > 0 ? std::span<const Interval>(near_north) : d.px,
                                              geodetic_margin(kGeodeticPiece, farthest_latitude(origin.latitude)));
  if (!outline.polygons.empty()) {
    json polygons = json::array();
    for (const OutlinePolygon& p : outline.polygons) polygons.push_back(geodetic_polygon(frame, p));
    json geometry = polygons.size() == 1 ? json{{"type", "Polygon"}, {"coordinates", polygons[0]}}
                                         : json{{"type", "MultiPolygon"}, {"coordinates", polygons}};
    json properties = {{"kind", "envelope"}, {"status", status}, {"samples", d.size()},
                       {"unbounded_samples", outline.unbounded_boxes - far}, {"far_samples", far},
                       {"grid_cell_m", outline.cell}};
    if (r.epoch) properties["epoch_utc"] = format_iso8601(*r.epoch);
    features.push_back(feature(std::move(properties), std::move(geometry)));
  }
  for (std::size_t i = 0; i < d.mines.size(); ++i) {
    const Vec3I& m = d.mines[i];
    if (m[0].is_empty() || m[1].is_empty() || !m[0].is_bounded() || !m[1].is_bounded() || !within_export_radius(m[0], m[1]))
      continue;
    json properties = {{"kind", "mine"}, {"mine", i}, {"status", status}, {"marks", marks_of_mine(s, static_cast<int>(i))},
                       {"north_width_m", m[0].width()}, {"east_width_m", m[1].width()}};
    if (!m[2].is_empty() && m[2].is_bounded()) {
      properties["down_lo_m"] = m[2].lo();
      properties["down_hi_m"] = m[2].hi();
    }
    features.push_back(feature(std::move(properties), {{"type", "Polygon"}, {"coordinates", box_ring(grid.box(m[0], m[1]))}}));
  }
  if (mission)
    for (std::size_t i = 0; i < mission->gps_time.size(); ++i) {
      json properties = {{"kind", "gps_fix"}, {"status", status}, {"time", mission->gps_time[i]}};
      if (i < s.gps_outlier.size()) properties["outlier"] = s.gps_outlier[i] != 0;
      if (r.epoch) properties["utc"] = format_iso8601_micro(*r.epoch, mission->gps_time[i]);
      // Longitudes within 180 degrees of the origin's, as the polygons' (geodetic_point).
      const double longitude = longitude_near(mission->gps_longitude[i], origin.longitude);
      features.push_back(feature(std::move(properties), {{"type", "Point"},
                                                         {"coordinates", {longitude, mission->gps_latitude[i]}}}));
    }
  json collection = {{"type", "FeatureCollection"}, {"status", status}, {"gesmi_version", std::string(version())},
                     {"features", std::move(features)}};
  if (!s.report.consistent) collection["inconsistency"] = s.report.message;
  write_text_file(path, dump_shortest(collection) + "\n");
}

}  // namespace gesmi::io
