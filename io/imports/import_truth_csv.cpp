#include "io/imports/import_truth_csv.h"

#include <limits>

#include "io/text/csv_number.h"
#include "io/imports/csv_reader.h"
#include "io/text/message_text.h"

namespace gesmi::io {

TruthTrack read_truth_csv(std::istream& in, const std::string& name, const std::vector<double>& nav_time) {
  CsvReader csv(in, name);
  csv.read_header({"time", "north", "east", "down"});
  TruthTrack track;
  double previous = -std::numeric_limits<double>::infinity();
  const auto missing = [&](std::size_t k) {
    return "no row at the navigation sample " + std::to_string(k) + " (" + format_number(nav_time[k]) +
           " s): the truth needs a row at every sample's time";
  };
  while (csv.next()) {
    const std::size_t k = track.north.size();
    const double t = csv.number(0);
    if (!(t > previous)) csv.fail(0, format_number(t) + " s does not follow " + format_number(previous) + " s");
    previous = t;
    if (k < nav_time.size() && t > nav_time[k]) csv.fail(0, missing(k));
    if (k >= nav_time.size() || t != nav_time[k]) continue;  // a row between the samples
    track.north.push_back(csv.number(1));
    track.east.push_back(csv.number(2));
    track.down.push_back(csv.number(3));
  }
  if (track.north.size() != nav_time.size()) csv.fail_line(missing(track.north.size()));
  return track;
}

std::vector<double> read_truth_mines_csv(std::istream& in, const std::string& name) {
  CsvReader csv(in, name);
  csv.read_header({"mine", "north", "east", "down"});
  std::vector<double> mines;
  while (csv.next()) {
    const std::size_t i = mines.size() / 3;
    const std::optional<long long> mine = parse_integer(csv.text(0));
    if (!mine || *mine != static_cast<long long>(i))
      csv.fail(0, "expected mine " + std::to_string(i) + " (mines 0..K-1 in order), found " + quoted_input(csv.text(0)));
    for (std::size_t c = 1; c <= 3; ++c) mines.push_back(csv.number(c));
  }
  return mines;
}

}  // namespace gesmi::io
