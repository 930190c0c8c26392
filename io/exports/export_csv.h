#pragma once
// `gesmi export`: a mission as the CSV files `gesmi import nav` reads back
// (docs/formats.md), in one folder:
//   nav.csv, gps.csv, marks.csv, model.yaml, truth.csv and truth_mines.csv (when
//   the mission has them), and import-command.txt (the import that rebuilds it).
// Numbers are written in their shortest exact form, so the round trip is exact.
// Not exported: the simulator's per-mark and per-fix diagnostics (/truth/marks_*,
// /truth/gps_outlier, /truth/missed_marks), which only the HDF5 file holds.

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "solver/mission/mission.h"

namespace gesmi::io {

void write_nav_csv(const Mission& mission, std::ostream& out);
void write_gps_csv(const Mission& mission, std::ostream& out);
void write_marks_csv(const Mission& mission, std::ostream& out);
void write_truth_csv(const Mission& mission, std::ostream& out);
void write_truth_mines_csv(const Mission& mission, std::ostream& out);

/// The arguments of the `gesmi import nav` command that rebuilds the exported
/// mission from the folder's files (names relative to the folder), ending with
/// "-o" and `output`.
std::vector<std::string> import_arguments(const Mission& mission, const std::string& output);

/// Writes a text file through `writer` under a temporary name, renamed into place
/// when complete.
void write_text_file(const std::string& path, const std::function<void(std::ostream&)>& writer);

/// Checks before any work that `folder` can be created: its parent exists and is
/// writable, and the folder does not exist or is empty.
void check_export_folder(const std::string& folder);

/// Writes every file into a temporary folder beside `folder`, then renames it into
/// place; on failure nothing is left under `folder`.
void export_mission_csv(const Mission& mission, const std::string& folder);

}  // namespace gesmi::io
