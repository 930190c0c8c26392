#include "io/exports/result_exports.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "io/output/atomic_output.h"
#include "io/geodesy.h"
#include "io/time/utc_time.h"

namespace gesmi::io {
namespace {

std::string number(double x, int digits) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

// A closed ring of the box's four corners in [longitude, latitude].
std::string ring(const LocalFrame& frame, const Interval& north, const Interval& east) {
  const double corners[5][2] = {{north.lo(), east.lo()}, {north.lo(), east.hi()}, {north.hi(), east.hi()},
                                {north.hi(), east.lo()}, {north.lo(), east.lo()}};
  std::string out = "[[";
  for (int i = 0; i < 5; ++i) {
    const GeoOrigin g = frame.to_geodetic(corners[i][0], corners[i][1]);
    out += (i ? ", [" : "[") + number(g.longitude, 9) + ", " + number(g.latitude, 9) + "]";
  }
  return out + "]]";
}

}  // namespace

void write_mines_csv(const TubeDomains& d, const std::string& path) {
  std::string text = "mine,north_lo,north_hi,east_lo,east_hi,down_lo,down_hi\n";
  for (std::size_t i = 0; i < d.mines.size(); ++i) {
    text += std::to_string(i);
    for (int c = 0; c < 3; ++c) {
      const Interval& x = d.mines[i][c];
      text += "," + (x.is_empty() ? std::string("nan") : number(x.lo(), 3)) + "," +
              (x.is_empty() ? std::string("nan") : number(x.hi(), 3));
    }
    text += "\n";
  }
  write_text_file(path, text);
}

void write_geojson(const TubeDomains& d, const GeoOrigin& origin, std::optional<std::int64_t> epoch, const std::string& path,
                   std::size_t polygons) {
  const LocalFrame frame(origin);
  std::string text = "{\"type\": \"FeatureCollection\", \"features\": [\n";
  bool first = true;
  const auto feature = [&](const std::string& properties, const std::string& geometry) {
    text += (first ? "" : ",\n") + std::string("{\"type\": \"Feature\", \"properties\": ") + properties +
            ", \"geometry\": " + geometry + "}";
    first = false;
  };
  for (std::size_t i = 0; i < d.mines.size(); ++i) {
    const Vec3I& m = d.mines[i];
    if (!m[0].is_bounded() || !m[1].is_bounded()) continue;
    feature("{\"kind\": \"mine\", \"mine\": " + std::to_string(i) + "}",
            "{\"type\": \"Polygon\", \"coordinates\": " + ring(frame, m[0], m[1]) + "}");
  }
  const std::size_t n = d.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + polygons - 1) / std::max<std::size_t>(polygons, 1));
  std::string envelope;
  for (std::size_t k = 0; k < n; k += stride) {
    Interval north = d.px[k], east = d.py[k];
    for (std::size_t j = k; j < std::min(n, k + stride + 1); ++j) {
      north = hull(north, d.px[j]);
      east = hull(east, d.py[j]);
    }
    if (!north.is_bounded() || !east.is_bounded()) continue;
    envelope += (envelope.empty() ? "" : ", ") + ring(frame, north, east);
  }
  if (!envelope.empty())
    feature(epoch ? "{\"kind\": \"envelope\", \"epoch_utc\": \"" + format_iso8601(*epoch) + "\"}" : "{\"kind\": \"envelope\"}", "{\"type\": \"MultiPolygon\", \"coordinates\": [" + envelope + "]}");
  text += "\n]}\n";
  write_text_file(path, text);
}

}  // namespace gesmi::io
