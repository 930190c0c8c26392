#pragma once
// Exports of a result for other tools: the mine boxes as CSV, and GeoJSON for GIS
// (mine boxes and the envelope as polygons in WGS84 longitude/latitude).

#include <cstdint>
#include <optional>
#include <string>

#include "solver/mission/mission.h"
#include "solver/network/tube_domains.h"

namespace gesmi::io {

void write_mines_csv(const TubeDomains& domains, const std::string& path);
/// The envelope is written as one polygon per stretch of `stride` samples (the
/// hull of their boxes), so a 60,000-step tube stays a few hundred polygons. Its
/// properties carry the mission's UTC epoch (t = 0) when it has one.
void write_geojson(const TubeDomains& domains, const GeoOrigin& origin, std::optional<std::int64_t> epoch,
                   const std::string& path, std::size_t polygons = 600);

}  // namespace gesmi::io
