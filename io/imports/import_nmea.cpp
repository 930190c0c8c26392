#include "io/imports/import_nmea.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include "io/format_error.h"
#include "io/text/csv_number.h"
#include "io/text/message_text.h"

namespace gesmi::io {
namespace {

constexpr double kHalfDay = 43200.0;

struct Sentence {
  std::string_view type;  // "GGA", "RMC", ... (the talker's two letters dropped)
  std::vector<std::string_view> fields;  // fields[0] is the address "GPGGA"
};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// The sentence between '$' and '*' when its checksum holds; nullopt otherwise.
std::optional<std::string_view> checked_body(std::string_view line) {
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos || star + 3 != line.size()) return std::nullopt;
  const int high = hex_digit(line[star + 1]), low = hex_digit(line[star + 2]);
  if (high < 0 || low < 0) return std::nullopt;
  unsigned char sum = 0;
  for (std::size_t i = 1; i < star; ++i) sum ^= static_cast<unsigned char>(line[i]);
  if (sum != high * 16 + low) return std::nullopt;
  return line.substr(1, star - 1);
}

Sentence split_sentence(std::string_view body) {
  Sentence s;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = body.find(',', start);
    s.fields.push_back(body.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  const std::string_view address = s.fields[0];
  s.type = address.size() >= 3 ? address.substr(address.size() - 3) : address;
  return s;
}

class SentenceError {
 public:
  SentenceError(const std::string& name, std::size_t line, const Sentence& s) : name_(name), line_(line), s_(s) {}
  [[noreturn]] void fail(std::size_t field, const std::string& reason) const {
    throw FormatError(name_ + ":" + std::to_string(line_) + ": " + std::string(s_.fields[0]) + " field " +
                      std::to_string(field) + ": " + reason);
  }
  std::string_view field(std::size_t i) const {
    if (i >= s_.fields.size())
      fail(i, "missing (the sentence has " + std::to_string(s_.fields.size() - 1) + " fields)");
    return s_.fields[i];
  }

 private:
  const std::string& name_;
  std::size_t line_;
  const Sentence& s_;
};

bool all_digits(std::string_view text) {
  return !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
}

// "hhmmss[.sss]" -> seconds of the day.
double time_of_day(const SentenceError& e, std::size_t i) {
  const std::string_view text = e.field(i);
  const std::size_t dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  if (whole.size() != 6 || !all_digits(whole) || (dot != std::string_view::npos && !all_digits(text.substr(dot + 1))))
    e.fail(i, "expected a time hhmmss.ss, found " + quoted_input(text));
  const int h = (whole[0] - '0') * 10 + (whole[1] - '0'), m = (whole[2] - '0') * 10 + (whole[3] - '0'),
            s = (whole[4] - '0') * 10 + (whole[5] - '0');
  if (h > 23 || m > 59 || s > 59) e.fail(i, "the time " + quoted_input(text) + " does not exist");
  double fraction = 0.0;
  if (dot != std::string_view::npos) fraction = *parse_number("0" + std::string(text.substr(dot)));
  return h * 3600.0 + m * 60.0 + s + fraction;
}

// "ddmm.mmmm" / "dddmm.mmmm" and its hemisphere letter -> signed degrees.
double angle(const SentenceError& e, std::size_t i, int degree_digits, char positive, char negative, double limit) {
  const std::string_view text = e.field(i);
  const std::size_t dot = text.find('.');
  const std::string_view whole = text.substr(0, dot);
  if (whole.size() != static_cast<std::size_t>(degree_digits + 2) || !all_digits(whole) ||
      (dot != std::string_view::npos && !all_digits(text.substr(dot + 1))))
    e.fail(i, "expected " + std::string(static_cast<std::size_t>(degree_digits), 'd') + "mm.mmmm, found " + quoted_input(text));
  const double degrees = *parse_number(whole.substr(0, static_cast<std::size_t>(degree_digits)));
  const double minutes = *parse_number(text.substr(static_cast<std::size_t>(degree_digits)));
  if (minutes >= 60.0) e.fail(i, "minutes " + format_number(minutes) + " are not below 60");
  const double value = degrees + minutes / 60.0;
  if (value > limit) e.fail(i, format_number(value) + " degrees is beyond " + format_number(limit));
  const std::string_view hemisphere = e.field(i + 1);
  if (hemisphere.size() != 1 || (hemisphere[0] != positive && hemisphere[0] != negative))
    e.fail(i + 1, std::string("expected ") + positive + " or " + negative + ", found " + quoted_input(hemisphere));
  return hemisphere[0] == negative ? -value : value;
}

struct Gga {
  double time_of_day, latitude, longitude;
  std::size_t line, order;
};
struct Rmc {
  std::int64_t days;
  double time_of_day;
  std::size_t order;
};

}  // namespace

bool looks_like_nmea(std::istream& in) {
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte order mark
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    return line[first] == '$';
  }
  return false;
}

NmeaFixes read_nmea(std::istream& in, const std::string& name, std::optional<std::int64_t> date_days) {
  NmeaFixes out;
  std::vector<Gga> ggas;
  std::vector<Rmc> rmcs;
  std::string text;
  std::size_t line = 0, order = 0;
  while (std::getline(in, text)) {
    ++line;
    std::string_view view = text;
    if (line == 1 && view.rfind("\xEF\xBB\xBF", 0) == 0) view.remove_prefix(3);  // a UTF-8 byte order mark
    while (!view.empty() && (view.back() == '\r' || view.back() == ' ')) view.remove_suffix(1);
    while (!view.empty() && view.front() == ' ') view.remove_prefix(1);
    if (view.empty()) continue;
    if (view.front() != '$')
      throw FormatError(name + ":" + std::to_string(line) + ": not an NMEA sentence (expected a line starting with '$'), found " +
                        quoted_input(view.substr(0, 40)));
    const std::optional<std::string_view> body = checked_body(view);
    if (!body) {
      ++out.bad_checksum;
      continue;
    }
    const Sentence s = split_sentence(*body);
    const SentenceError e(name, line, s);
    ++order;
    if (s.type == "GGA") {
      // 1 GPS, 2 differential, 3 PPS, 4 RTK, 5 float RTK: measured fixes. 0 is none;
      // 6 (dead reckoning), 7 (manual input) and 8 (simulation) are not measurements.
      const std::string_view quality = e.field(6);
      if (quality.size() != 1 || quality[0] < '0' || quality[0] > '8')
        e.fail(6, "expected a fix quality 0-8, found " + quoted_input(quality));
      if (quality == "0" || quality[0] >= '6') {
        ++out.no_fix;
        continue;
      }
      ggas.push_back({time_of_day(e, 1), angle(e, 2, 2, 'N', 'S', 90.0), angle(e, 4, 3, 'E', 'W', 180.0), line, order});
    } else if (s.type == "RMC") {
      const double tod = time_of_day(e, 1);
      const std::string_view date = e.field(9);
      if (date.size() != 6 || !all_digits(date)) e.fail(9, "expected a date ddmmyy, found " + quoted_input(date));
      const int day = (date[0] - '0') * 10 + (date[1] - '0'), month = (date[2] - '0') * 10 + (date[3] - '0'),
                yy = (date[4] - '0') * 10 + (date[5] - '0');
      const auto days = days_since_1970(yy < 80 ? 2000 + yy : 1900 + yy, month, day);
      if (!days) e.fail(9, "the date " + quoted_input(date) + " does not exist");
      rmcs.push_back({*days, tod, order});
      ++out.rmc;
    } else {
      ++out.other;
    }
  }
  if (in.bad()) throw FormatError(name + ": read error");
  if (!ggas.empty() && rmcs.empty() && !date_days)
    throw FormatError(name + ": GGA sentences give only the time of day and the file has no RMC sentence to take the date "
                             "from: give --date YYYY-MM-DD (the UTC date of the first fix)");

  std::size_t next_rmc = 0;  // first RMC after the current GGA
  double previous = 0.0;     // the previous GGA's instant (s since 1970), when dating by --date
  for (std::size_t i = 0; i < ggas.size(); ++i) {
    const Gga& g = ggas[i];
    while (next_rmc < rmcs.size() && rmcs[next_rmc].order < g.order) ++next_rmc;
    double reference;
    if (!rmcs.empty()) {
      const Rmc& r = rmcs[next_rmc > 0 ? next_rmc - 1 : 0];
      reference = static_cast<double>(r.days) * 86400.0 + r.time_of_day;
    } else {
      reference = i == 0 ? static_cast<double>(*date_days) * 86400.0 + g.time_of_day : previous;
    }
    double day = std::floor(reference / 86400.0) * 86400.0;
    if (day + g.time_of_day < reference - kHalfDay) day += 86400.0;
    if (day + g.time_of_day > reference + kHalfDay) day -= 86400.0;
    previous = day + g.time_of_day;
    const double whole = std::floor(g.time_of_day);
    out.time.push_back(UtcTime{static_cast<std::int64_t>(day + whole), g.time_of_day - whole});
    out.latitude.push_back(g.latitude);
    out.longitude.push_back(g.longitude);
    out.line.push_back(g.line);
  }
  return out;
}

}  // namespace gesmi::io
