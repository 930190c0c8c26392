// The HDF5 mission file: round trip, a read by Debian's h5py, and every bad input
// named in one line.

#include "io/files/mission_file.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io/format_error.h"
#include "io/hdf5/h5_file.h"
#include "tests/support/h5py_edits.h"
#include "tests/support/run_command.h"
#include "tests/support/tiny_mission.h"

namespace gesmi::io {
namespace {

Mission sample_mission() {
  Mission m = test::make_tiny_mission(5, test::TinyErrors::uniform).mission;
  m.origin = {48.212920614, -4.458227931};
  m.gps_time = {m.time.front(), m.time.back()};
  m.gps_latitude = {48.212920614, 48.2130};
  m.gps_longitude = {-4.458227931, -4.4580};
  return m;
}

std::string expect_error(const std::string& path) {
  try {
    read_mission(path);
  } catch (const FormatError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind(path, 0), 0u) << what;  // starts with the file name
    return what;
  }
  ADD_FAILURE() << "no error for " << path;
  return {};
}

TEST(MissionFile, RoundTripKeepsEveryField) {
  const Mission m = sample_mission();
  const std::string path = test::temp_folder("mission") + "/m.h5";
  write_mission(m, path);
  const Mission r = read_mission(path);
  EXPECT_EQ(r.time, m.time);
  EXPECT_EQ(r.heading, m.heading);
  EXPECT_EQ(r.vy, m.vy);
  EXPECT_EQ(r.depth, m.depth);
  EXPECT_EQ(r.mark_range, m.mark_range);
  EXPECT_EQ(r.mark_mine, m.mark_mine);
  EXPECT_EQ(r.truth_y, m.truth_y);
  EXPECT_EQ(r.truth_mines, m.truth_mines);
  EXPECT_EQ(r.gps_latitude, m.gps_latitude);
  EXPECT_EQ(r.mine_count, m.mine_count);
  EXPECT_EQ(r.model.heading, m.model.heading);
  EXPECT_EQ(r.model.sonar_side, m.model.sonar_side);
  ASSERT_EQ(r.gps_north.size(), 2u);
  EXPECT_NEAR(r.gps_north[0], 0.0, 1e-6);  // the first fix is the origin
  EXPECT_GE(r.gps_north_halfwidth[0], m.model.gps_metres);
}

TEST(MissionFile, ReadsTheSameNavigationWithoutTheTruth) {
  Mission m = sample_mission();
  m.half_widths.heading.assign(m.size(), 0.01);
  const std::string path = test::temp_folder("mission-no-truth") + "/m.h5";
  write_mission(m, path);
  const Mission r = read_mission(path, TruthReading::skip);
  EXPECT_TRUE(r.truth_x.empty() && r.truth_mines.empty() && r.truth_marks_mine.empty());
  EXPECT_FALSE(m.truth_x.empty());
  for (const auto field : {&Mission::time, &Mission::roll, &Mission::pitch, &Mission::heading, &Mission::vx, &Mission::vy,
                           &Mission::vz, &Mission::altitude, &Mission::depth, &Mission::gps_longitude, &Mission::gps_latitude})
    EXPECT_EQ(r.*field, m.*field);
  EXPECT_EQ(r.half_widths.heading, m.half_widths.heading);
}

TEST(MissionFile, IsReadableByH5py) {
  const std::string path = test::temp_folder("mission") + "/m.h5";
  write_mission(sample_mission(), path);
  const std::string script = "import h5py,sys\nf=h5py.File(sys.argv[1],'r')\nprint(f['/nav/attitude'].shape[0], f['/nav/attitude'].shape[1], f.attrs['mine_count'], f['/marks/time'].shape[0])\n";
  const std::string script_path = test::temp_folder("py") + "/read.py";
  std::ofstream(script_path) << script;
  const std::string out_path = script_path + ".out";
  ASSERT_EQ(std::system(("/usr/bin/python3 " + script_path + " " + path + " > " + out_path).c_str()), 0);
  std::ifstream in(out_path);
  std::size_t rows = 0, columns = 0, mines = 0, marks = 0;
  in >> rows >> columns >> mines >> marks;
  EXPECT_EQ(rows, 3001u);
  EXPECT_EQ(columns, 3u);
  EXPECT_EQ(mines, 1u);
  EXPECT_EQ(marks, 2u);
}

// A valid mission file edited by h5py (independent of gesmi's writer).
std::string edited(const std::string& python_edit) {
  const std::string path = test::temp_folder("edit") + "/m.h5";
  write_mission(sample_mission(), path);
  return test::h5py_edited_copy(path, python_edit);
}

// gesmi kalman reads the truth after its smoothing (MissionReader::read_truth), from the
// file it keeps open: the same truth as one read, that file's truth even when the path
// is replaced meanwhile, and a damaged truth refused at the first read.
TEST(MissionFile, ReadsTheTruthAfterTheMissionFromTheSameFile) {
  Mission m = sample_mission();
  m.truth_marks_mine.assign(m.mark_count(), 0);
  const std::string folder = test::temp_folder("mission-truth-after");
  const std::string path = folder + "/m.h5";
  write_mission(m, path);
  const Mission whole = read_mission(path);
  {
    const MissionReader reader(path);
    Mission r = reader.read(TruthReading::skip);
    EXPECT_TRUE(r.truth_x.empty() && r.truth_mines.empty());
    // Another mission (its truth shifted by 1 m) renamed over the path meanwhile.
    Mission other = sample_mission();
    for (double& x : other.truth_x) x += 1.0;
    write_mission(other, folder + "/other.h5");
    std::filesystem::rename(folder + "/other.h5", path);
    reader.read_truth(r);
    for (const auto field : {&Mission::truth_x, &Mission::truth_y, &Mission::truth_z, &Mission::truth_mines,
                             &Mission::truth_missed_marks})
      EXPECT_EQ(r.*field, whole.*field);
    EXPECT_EQ(r.truth_marks_mine, whole.truth_marks_mine);
    EXPECT_FALSE(r.truth_x.empty());
    EXPECT_THROW(reader.read_truth(r), std::logic_error);  // read already
  }
  // A truth of another length: refused by the first read already.
  const std::string short_truth = edited("n = f['/truth/position'].shape[0]\n"
                                         "p = f['/truth/position'][:n - 1]\n"
                                         "del f['/truth/position']\n"
                                         "f['/truth/position'] = p\n");
  try {
    read_mission(short_truth, TruthReading::skip);
    ADD_FAILURE() << "a truth of another length was accepted";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("/truth/position: expected 3001 x 3"), std::string::npos) << e.what();
  }
  // A truth whose shapes fit but whose values do not: refused by the first read too,
  // whether it keeps the truth or not (gesmi solve keeps none).
  const std::string path_written = test::temp_folder("edit") + "/m.h5";
  write_mission(sample_mission(), path_written);
  const std::pair<const char*, const char*> cases[] = {
      {"import numpy as np\nif '/truth/marks_mine' in f: del f['/truth/marks_mine']\n"
       "f['/truth/marks_mine'] = np.full(f['/marks/time'].shape[0], 7, dtype='int32')\n",
       "/truth/marks_mine: row 0: not one of the mission's mines"},
      {"p = f['/truth/position'][:]\np[5, 1] = np.nan\nf['/truth/position'][:] = p\n", "/truth/position: row 5: position is NaN"},
      {"import numpy as np\nif '/truth/marks_outlier' in f: del f['/truth/marks_outlier']\n"
       "f['/truth/marks_outlier'] = np.full(f['/marks/time'].shape[0], 2, dtype='int32')\n",
       "/truth/marks_outlier: row 0: expected 0 or 1"},
      {"import numpy as np\nif '/truth/missed_marks' in f: del f['/truth/missed_marks']\n"
       "f['/truth/missed_marks'] = np.array([[1.0, 0.0, np.inf]])\n",
       "/truth/missed_marks"},
  };
  std::vector<std::string> edits;
  for (const auto& c : cases) edits.push_back(c.first);
  const std::vector<std::string> paths = test::h5py_edited_copies(path_written, edits);
  for (std::size_t i = 0; i < edits.size(); ++i)
    for (const TruthReading truth : {TruthReading::read, TruthReading::skip}) {
      SCOPED_TRACE(cases[i].first);
      try {
        read_mission(paths[i], truth);
        ADD_FAILURE() << "a damaged truth was accepted";
      } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find(cases[i].second), std::string::npos) << e.what();
      }
    }
}

// gesmi kalman counts the true positions as they are read, block by block, without
// keeping them: the blocks come in order and hold the whole truth; a bad value in a
// later block is named by its row.
TEST(MissionFile, StreamsTheTruePositionsBlockByBlock) {
  const std::string folder = test::temp_folder("mission-truth-blocks");
  const std::string path = folder + "/m.h5";
  ASSERT_EQ(test::run_gesmi({"simulate", "--seed", "3", "--duration", "1800", "-o", path}).exit_code, 0);
  const Mission whole = read_mission(path);
  ASSERT_GT(whole.size(), 2 * H5File::kBlockRows);
  std::vector<double> north, east, down;
  std::size_t blocks = 0;
  const auto collect = [&](std::size_t first, std::span<const double> rows) {
    ASSERT_EQ(first, north.size());
    ASSERT_EQ(rows.size() % 3, 0u);
    for (std::size_t i = 0; i < rows.size(); i += 3) {
      north.push_back(rows[i]);
      east.push_back(rows[i + 1]);
      down.push_back(rows[i + 2]);
    }
    ++blocks;
  };
  const MissionReader reader(path);
  Mission r = reader.read(TruthReading::skip);
  reader.read_truth(r, collect);
  EXPECT_EQ(north, whole.truth_x);
  EXPECT_EQ(east, whole.truth_y);
  EXPECT_EQ(down, whole.truth_z);
  EXPECT_EQ(blocks, (whole.size() + H5File::kBlockRows - 1) / H5File::kBlockRows);
  EXPECT_TRUE(r.truth_x.empty());  // handed over, not kept
  EXPECT_EQ(r.truth_mines, whole.truth_mines);

  const std::string row = std::to_string(2 * H5File::kBlockRows + 5);
  const std::string nan_path = folder + "/nan.h5", script = folder + "/edit.py";
  std::filesystem::copy_file(path, nan_path);
  std::ofstream(script) << "import h5py, numpy as np, sys\nf = h5py.File(sys.argv[1], 'r+')\n"
                        << "p = f['/truth/position'][:]\np[" << row << ", 2] = np.nan\nf['/truth/position'][:] = p\nf.close()\n";
  ASSERT_EQ(std::system(("/usr/bin/python3 " + script + " " + nan_path).c_str()), 0);
  // Refused by the first read, which checks the truth it does not keep.
  const MissionReader nan_reader(nan_path);
  try {
    nan_reader.read(TruthReading::skip);
    ADD_FAILURE() << "a NaN true position was accepted";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find(nan_path + ": /truth/position: row " + row + ": position is NaN"), std::string::npos)
        << e.what();
  }
}

TEST(MissionFile, NamesTheProblemOfEveryBadFile) {
  const std::string folder = test::temp_folder("bad");
  // Missing file, empty file, truncated file.
  EXPECT_NE(expect_error(folder + "/missing.h5").find("cannot open"), std::string::npos);
  std::ofstream(folder + "/empty.h5").close();
  EXPECT_NE(expect_error(folder + "/empty.h5").find("not an HDF5 file"), std::string::npos);
  const std::string good = folder + "/good.h5";
  write_mission(sample_mission(), good);
  const auto size = std::filesystem::file_size(good);
  std::filesystem::copy_file(good, folder + "/truncated.h5");
  std::filesystem::resize_file(folder + "/truncated.h5", size / 2);
  expect_error(folder + "/truncated.h5");

  // A written mission with a broken field: validated before writing, so build the
  // invalid missions in memory and check validate_mission's messages.
  const auto invalid = [&](void (*mutate)(Mission&), const char* must_contain) {
    Mission m = sample_mission();
    mutate(m);
    try {
      validate_mission(m, "m.h5");
      ADD_FAILURE() << "accepted: " << must_contain;
    } catch (const FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(must_contain), std::string::npos) << e.what();
    }
  };
  invalid([](Mission& m) { m.time[10] = m.time[9]; }, "/nav/time: row 10: time does not increase");
  invalid([](Mission& m) { m.heading[3] = std::nan(""); }, "/nav/attitude heading: row 3: value is NaN");
  invalid([](Mission& m) { m.vx.pop_back(); }, "/nav/velocity x: expected 3001 rows");
  invalid([](Mission& m) { m.mark_time[0] = 1e6; }, "/marks/time: row 0");
  invalid([](Mission& m) { m.mark_side[1] = 0; }, "/marks/side: row 1");
  invalid([](Mission& m) { m.mark_mine[1] = 4; }, "/marks/mine: row 1");
  invalid([](Mission& m) { m.mark_range[0] = -2.0; }, "/marks/range: row 0");
  invalid([](Mission& m) { m.mark_range[0] = 500.0; }, "beyond the sonar");
  invalid([](Mission& m) { m.gps_latitude[1] = 95.0; }, "/gps/lonlat: row 1");
  invalid([](Mission& m) { m.depth[7] = std::numeric_limits<double>::infinity(); }, "/nav/depth: row 7: value is infinite");
  invalid([](Mission& m) { m.model.heading = -1.0; }, "/model: heading");
}

TEST(MissionFile, ReportsMissingDatasetsWrongShapesAndBadAttributes) {
  const std::pair<std::string, std::string> cases[] = {
      {"del f['/nav/depth']", "/nav/depth: missing dataset"},
      {"del f['/nav/attitude']\nf['/nav/attitude'] = np.zeros((3001, 2))", "/nav/attitude: expected 3001 x 3, found 3001 x 2"},
      {"del f['/nav/altitude']\nf['/nav/altitude'] = np.zeros(10)", "/nav/altitude"},
      {"f['/nav/time'][5] = np.nan", "/nav/time: row 5: time is NaN"},
      {"del f['/model'].attrs['heading']", "/model: missing attribute heading"},
      {"f['/model'].attrs['sonar_side'] = np.bytes_(b'left')", "sonar_side"},
      {"f.attrs['format'] = np.bytes_(b'other')", "not a gesmi mission file"},
      // A per-sample bound with no values is not "no bound given": it is refused.
      {"f['/nav/half_widths/depth'] = np.zeros(0)", "/nav/half_widths/depth: expected 3001 rows, found 0"},
      {"f['/nav/half_widths/roll'] = np.full(10, 1e-3)", "/nav/half_widths/roll: expected 3001 rows, found 10"},
      {"f['/nav/half_widths/speed'] = np.zeros(3001)",
       "/nav/half_widths/speed: not a navigation channel (roll, pitch, heading, vx, vy, vz, altitude or depth)"},
      {"[f.create_dataset('/nav/half_widths/x%03d' % i, data=np.zeros(1)) for i in range(100)]",
       "/nav/half_widths: holds 100 members, more than the 64 gesmi reads"},
      {"f.pop('/truth/marks_outlier', None)\nf['/truth/marks_outlier'] = np.zeros(0, dtype=np.int32)",
       "/truth/marks_outlier: expected 2 rows, found 0"},
  };
  const std::string path = test::temp_folder("edits") + "/m.h5";
  write_mission(sample_mission(), path);
  std::vector<std::string> edits;
  for (const auto& c : cases) edits.push_back(c.first);
  const std::vector<std::string> copies = test::h5py_edited_copies(path, edits);
  for (std::size_t i = 0; i < copies.size(); ++i)
    EXPECT_NE(expect_error(copies[i]).find(cases[i].second), std::string::npos) << cases[i].first;
}

}  // namespace
}  // namespace gesmi::io
