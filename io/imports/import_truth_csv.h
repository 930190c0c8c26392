#pragma once
// Ground truth of a simulated mission as CSV (docs/formats.md), so that an exported
// simulated mission imports back with its truth:
//   truth.csv        time,north,east,down   (a row at every navigation sample's time; rows
//                                           between the samples are skipped)
//   truth_mines.csv  mine,north,east,down   (mines 0..K-1 in order)
// Local NED metres about the mission origin.

#include <istream>
#include <string>
#include <vector>

namespace gesmi::io {

struct TruthTrack {
  std::vector<double> north, east, down;
};

/// Reads truth.csv at the times `nav_time` (increasing): every one must have its row.
TruthTrack read_truth_csv(std::istream& in, const std::string& name, const std::vector<double>& nav_time);

/// Reads truth_mines.csv; returns K x 3 row-major positions.
std::vector<double> read_truth_mines_csv(std::istream& in, const std::string& name);

}  // namespace gesmi::io
