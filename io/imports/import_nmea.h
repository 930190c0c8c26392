#pragma once
// GPS fixes from NMEA 0183 sentences (docs/formats.md, "NMEA"). A small strict
// parser (Debian packages no C++ NMEA library): every line is a sentence
// "$ttSSS,f1,...*hh" (blank lines skipped). GGA gives the fixes (time of day,
// latitude, longitude, fix quality: 1-5 are measured fixes; 0 (none), 6 (dead
// reckoning), 7 (manual) and 8 (simulation) are skipped and counted); RMC the date;
// other sentences are counted and ignored. The checksum is verified: a sentence with
// a bad or missing one is skipped and counted. A sentence whose checksum holds but
// whose fields do not parse is an error naming the line and the field.
//
// A GGA's time of day takes the date of the nearest RMC (the last one before it, else
// the first after), moved by a day when they straddle midnight (more than 12 h apart);
// without any RMC, `date` (--date) dates the first GGA and midnight is crossed when
// the time of day falls back by more than 12 h.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "io/time/utc_time.h"

namespace gesmi::io {

struct NmeaFixes {
  std::vector<UtcTime> time;
  std::vector<double> latitude, longitude;  // degrees
  std::vector<std::size_t> line;
  std::size_t bad_checksum = 0;  // sentences skipped
  std::size_t no_fix = 0;        // GGA with quality 0 (no fix) or 6-8 (estimated, manual, simulated)
  std::size_t other = 0;         // sentences neither GGA nor RMC
  std::size_t rmc = 0;
};

/// `date_days`: days since 1970 of the first GGA when the file has no RMC.
NmeaFixes read_nmea(std::istream& in, const std::string& name, std::optional<std::int64_t> date_days);

/// True when the first non-blank line of the file starts with '$' (an NMEA log).
bool looks_like_nmea(std::istream& in);

}  // namespace gesmi::io
