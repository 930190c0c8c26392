#include "io/imports/import_gesmi_txt.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "io/text/csv_number.h"
#include "io/format_error.h"
#include "io/geodesy.h"
#include "io/text/message_text.h"
#include "solver/interval/rounding.h"

namespace gesmi::io {
namespace {

constexpr const char* kNames[GesmiColumn::count] = {"roll", "pitch", "heading", "vx", "vy",
                                                    "vz",   "depth", "altitude", "x", "y"};
constexpr const char* kRowShape =
    "21 numbers: t, then value and half-width of roll, pitch, heading, vx, vy, vz, depth, altitude, x, y";

// Blanks of the format: ASCII space, tab and the CR of CRLF files (no locale lookup).
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

void split_whitespace(const std::string& line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  const std::string_view s(line);
  std::size_t i = 0;
  while (true) {
    while (i < s.size() && blank(s[i])) ++i;
    if (i == s.size()) return;
    const std::size_t start = i;
    while (i < s.size() && !blank(s[i])) ++i;
    tokens.push_back(s.substr(start, i - start));
  }
}

[[noreturn]] void fail_at(const std::string& name, std::size_t line, const std::string& what) {
  throw FormatError(name + ":" + std::to_string(line) + ": " + what);
}

std::string field_name(std::size_t token) {
  if (token == 0) return "t";
  const std::string name = kNames[(token - 1) / 2];
  return token % 2 == 1 ? name : name + " half-width";
}

}  // namespace

const char* gesmi_column_name(std::size_t column) { return kNames[column]; }

double column_half_width(const SensorModel& model, std::size_t column, double value) {
  // The navigation channel of each column, by name.
  static const std::array<std::size_t, 8> kChannel = [] {
    std::array<std::size_t, 8> out{};
    for (std::size_t c = 0; c < out.size(); ++c)
      out[c] = static_cast<std::size_t>(&nav_channel(kNames[c]) - nav_channels().data());
    return out;
  }();
  return model_half_width(model, kChannel[column], value);
}

GesmiTextLog read_gesmi_txt(std::istream& in, const std::string& name) {
  GesmiTextLog log;
  std::string text;
  std::vector<std::string_view> tokens;
  std::size_t line = 0;
  double numbers[21];
  const auto fail = [&](const std::string& what) { fail_at(name, line, what); };
  while (std::getline(in, text)) {
    ++line;
    split_whitespace(text, tokens);
    if (tokens.empty()) continue;
    bool numeric = tokens.size() == 21;
    std::size_t bad_token = 0;
    for (std::size_t i = 0; numeric && i < 21; ++i) {
      const std::optional<double> x = parse_number(tokens[i]);
      if (!x) {
        numeric = false;
        bad_token = i;
      } else {
        numbers[i] = *x;
      }
    }
    if (!numeric) {
      if (log.time.empty()) continue;  // a header line
      if (tokens.size() != 21) fail("expected " + std::string(kRowShape) + "; found " + std::to_string(tokens.size()) + " fields");
      fail(field_name(bad_token) + ": expected a number, found " + quoted_input(tokens[bad_token]));
    }
    if (const std::string_view why = non_finite_reason(numbers[0]); !why.empty()) fail("t: " + std::string(why));
    if (!log.time.empty() && !(numbers[0] > log.time.back()))
      fail("t: " + format_number(numbers[0]) + " s does not increase (" + format_number(log.time.back()) + " s on line " +
           std::to_string(log.line.back()) + ")");
    for (std::size_t c = 0; c < GesmiColumn::count; ++c) {
      double value = numbers[1 + 2 * c], half_width = numbers[2 + 2 * c];
      if (half_width < 0.0) fail(field_name(2 + 2 * c) + ": " + format_number(half_width) + " is negative (nan or inf when not given)");
      if (!std::isfinite(half_width)) half_width = NAN;
      // x and y may be unknown (NaN) on rows that are not position fixes.
      const bool may_be_unknown = (c == GesmiColumn::x || c == GesmiColumn::y) && std::isnan(half_width);
      if (const std::string_view why = non_finite_reason(value); !why.empty() && !may_be_unknown)
        fail(field_name(1 + 2 * c) + ": " + std::string(why));
      log.value[c].push_back(value);
      log.half_width[c].push_back(half_width);
    }
    if (std::isnan(log.half_width[GesmiColumn::x].back()) != std::isnan(log.half_width[GesmiColumn::y].back()))
      fail("x half-width: x and y half-widths are given together or not at all");
    log.time.push_back(numbers[0]);
    log.line.push_back(line);
  }
  if (in.bad()) fail("read error");
  line = std::max<std::size_t>(line, 1);
  if (log.time.empty()) fail("no data row (rows of " + std::string(kRowShape) + ")");
  if (log.time.size() < 2) fail("a mission needs at least 2 data rows, found 1");
  return log;
}

Mission mission_from_gesmi_txt(GesmiTextLog log, const std::string& name, const GeoOrigin& origin,
                               const SensorModel& model, GesmiXy xy) {
  Mission m;
  m.origin = origin;
  m.model = model;
  const std::size_t n = log.time.size();
  m.time = std::move(log.time);
  for (std::size_t c = 0; c < GesmiColumn::x; ++c) {
    const NavChannel& channel = nav_channel(kNames[c]);
    std::vector<double>& given = log.half_width[c];
    bool any = false;
    for (const double h : given) any = any || !std::isnan(h);
    if (any) {
      // Samples without a half-width keep the model's bound.
      for (std::size_t k = 0; k < n; ++k)
        if (std::isnan(given[k])) given[k] = column_half_width(model, c, log.value[c][k]);
      m.half_widths.*channel.half_widths = std::move(given);
    }
    m.*channel.readings = std::move(log.value[c]);
  }

  const std::vector<double>& x = log.value[GesmiColumn::x];
  const std::vector<double>& y = log.value[GesmiColumn::y];
  const std::vector<double>& dx = log.half_width[GesmiColumn::x];
  const std::vector<double>& dy = log.half_width[GesmiColumn::y];
  const LocalFrame frame(origin);
  const auto add_fix = [&](std::size_t k) {
    const GeoOrigin g = frame.to_geodetic(x[k], y[k]);
    m.gps_time.push_back(m.time[k]);
    m.gps_latitude.push_back(g.latitude);
    m.gps_longitude.push_back(g.longitude);
    m.gps_given_north_halfwidth.push_back(dx[k]);
    m.gps_given_east_halfwidth.push_back(dy[k]);
  };
  // A row is a fix when its x and y half-widths say something: finite, and narrower
  // than the local frame's zone (logs write "unknown" as a huge bound, e.g. 1e9).
  const auto is_fix = [&](std::size_t k) {
    return std::isfinite(dx[k]) && std::isfinite(dy[k]) && dx[k] < kLocalFrameZone && dy[k] < kLocalFrameZone;
  };
  if (xy == GesmiXy::fixes) {
    for (std::size_t k = 0; k < n; ++k)
      if (is_fix(k)) add_fix(k);
  } else {
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(x[k]) || !std::isfinite(y[k]))
        fail_at(name, log.line[k], std::string(std::isfinite(x[k]) ? "y" : "x") + ": needed as ground truth, found " +
                                       format_number(std::isfinite(x[k]) ? y[k] : x[k]));
    if (is_fix(0)) add_fix(0);
    m.truth_x = x;
    m.truth_y = y;
    m.truth_z = m.depth;
  }
  // Fixes farther than the local frame's zone would lose the conversion bound.
  for (std::size_t i = 0; i < m.gps_time.size(); ++i) {
    const std::size_t k = static_cast<std::size_t>(
        std::lower_bound(m.time.begin(), m.time.end(), m.gps_time[i]) - m.time.begin());
    if (std::hypot(x[k], y[k]) > kLocalFrameZone)
      fail_at(name, log.line[k], "x, y: " + fix_beyond_zone(std::hypot(x[k], y[k])));
  }
  return m;
}

}  // namespace gesmi::io
