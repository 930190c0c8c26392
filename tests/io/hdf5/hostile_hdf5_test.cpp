// Hostile HDF5 files, edited by Debian's h5py (independent of gesmi's writer): every
// one is refused with one FormatError naming the file, the object and the reason,
// before any value reaches a buffer of the wrong size (the sanitizer build runs
// these too), and a file a user may legitimately produce with h5py is still read.

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "io/exports/result_exports.h"
#include "io/files/mission_file.h"
#include "io/files/result_file.h"
#include "io/format_error.h"
#include "tests/support/h5py_edits.h"
#include "tests/support/paths.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

namespace fs = std::filesystem;

// A short simulated mission and its result, made once by the gesmi binary.
struct Samples {
  std::string mission, result;
};
const Samples& samples() {
  static const Samples s = [] {
    const std::string folder = test::temp_folder("hostile-samples");
    Samples out{folder + "/m.h5", folder + "/r.h5"};
    EXPECT_EQ(test::run_gesmi({"simulate", "--seed", "3", "--duration", "600", "-o", out.mission}).exit_code, 0);
    EXPECT_EQ(test::run_gesmi({"solve", out.mission, "-o", out.result}).exit_code, 0);
    return out;
  }();
  return s;
}

std::string edited(const std::string& source, const std::string& python_edit) {
  return test::h5py_edited_copy(source, python_edit);
}

struct Case {
  const char* edit;
  const char* must_name;  // part of the one-line message
};

template <class Read>
void expect_refused_file(const std::string& path, const Case& c, Read read) {
  SCOPED_TRACE(c.edit);
  try {
    read(path);
    ADD_FAILURE() << "accepted";
  } catch (const FormatError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;  // names the file first
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(c.must_name), std::string::npos) << "wanted '" << c.must_name << "' in: " << what;
  }
}

// Each case's edit on a copy of `source` (all in one h5py process), each copy refused.
template <class Read>
void expect_refused(const std::string& source, std::span<const Case> cases, Read read) {
  std::vector<std::string> edits;
  for (const Case& c : cases) edits.push_back(c.edit);
  const std::vector<std::string> paths = test::h5py_edited_copies(source, edits);
  for (std::size_t i = 0; i < cases.size(); ++i) expect_refused_file(paths[i], cases[i], read);
}

TEST(HostileHdf5, MissionAttributesMustBeOneValueOfTheRightKind) {
  const Case cases[] = {
      {"f.attrs['origin_latitude'] = np.array([48.0, 49.0])", "/: attribute origin_latitude holds 2 values, expected one"},
      {"f.attrs['origin_latitude'] = np.arange(1000.0)", "attribute origin_latitude holds 1000 values"},
      {"f.attrs['mine_count'] = np.array([1, 2, 3], dtype=np.int64)", "attribute mine_count holds 3 values"},
      {"f.attrs['format'] = np.array([b'gesmi-mission', b'x'])", "attribute format holds 2 values"},
      {"f['/model'].attrs['sonar_side'] = np.array([b'starboard', b'port'])", "/model: attribute sonar_side holds 2 values"},
      {"f['/model'].attrs['heading'] = np.zeros(64)", "/model: attribute heading holds 64 values"},
      {"f.attrs['mine_count'] = 'three'", "attribute mine_count is a string, expected an integer"},
      {"f.attrs['mine_count'] = 2.5", "attribute mine_count is a floating-point number, expected an integer"},
      {"f.attrs['origin_latitude'] = 'north'", "attribute origin_latitude is a string, expected a number"},
      {"f.attrs['format'] = 7", "attribute format is an integer, expected a string"},
      {"f.attrs.create('origin_latitude', h5py.Empty('f8'))", "attribute origin_latitude holds 0 values"},
      {"f.attrs['format_version'] = 7", "format_version 7 was written by a newer gesmi"},
      {"f.attrs['format_version'] = 0", "format_version 0 is not one this gesmi reads"},
      {"del f.attrs['format_version']", "missing attribute format_version"},
      {"f['/model'].attrs['heading'] = np.longdouble(0.01)", "/model: attribute heading is wider than 64 bits"},
  };
  expect_refused(samples().mission, cases, [](const std::string& p) { return read_mission(p); });
}

TEST(HostileHdf5, MissionDatasetsAreCheckedBeforeAnythingIsAllocated) {
  const Case cases[] = {
      // Declared sizes the file cannot hold: refused before allocating.
      {"del f['/nav/depth']\nf.create_dataset('/nav/depth', shape=(10**12,), dtype='f8')", "more than gesmi reads from one dataset"},
      {"del f['/nav/depth']\nf.create_dataset('/nav/depth', shape=(10**8,), dtype='f8')", "but the file stores 0 bytes"},
      {"del f['/nav/depth']\nf.create_dataset('/nav/depth', shape=(10**8,), dtype='f8', chunks=True, compression='gzip')",
       "but the file stores"},
      // Classes.
      {"d = f['/nav/depth'][:]\ndel f['/nav/depth']\nf['/nav/depth'] = d > 5", "/nav/depth: stores an enumeration"},
      {"d = f['/nav/depth'][:]\ndel f['/nav/depth']\nf['/nav/depth'] = d.astype(np.longdouble)", "wider than 64 bits"},
      {"n = f['/nav/depth'].shape[0]\ndel f['/nav/depth']\nf['/nav/depth'] = np.array([b'deep'] * n)", "/nav/depth: stores strings"},
      {"n = f['/nav/time'].shape[0]\ndel f['/nav/time']\nf['/nav/time'] = np.arange(n, dtype=np.int64) + 2**60",
       "/nav/time: value 0 is an integer too large to be read exactly"},
      {"s = f['/marks/side'][:]\ndel f['/marks/side']\nf['/marks/side'] = s.astype(float)", "/marks/side: stores floating-point numbers, expected integers"},
      {"m = f['/marks/mine'][:]\ndel f['/marks/mine']\nf['/marks/mine'] = m.astype(np.int64) + 2**40", "/marks/mine: value 0 (1099511627"},
      {"m = f['/marks/mine'][:]\ndel f['/marks/mine']\nf['/marks/mine'] = m > 2", "/marks/mine: stores an enumeration"},
      {"del f['/nav/time']\nf['/nav/time'] = np.zeros((2, 2, 2))", "/nav/time: expected 1 or 2 dimensions, found 3"},
      // Groups, datasets and links.
      {"del f['/marks']\nf['/marks'] = np.zeros(3)", "/marks: expected a group, found a dataset"},
      {"del f['/gps']\nf['/gps'] = np.zeros(3)", "/gps: expected a group, found a dataset"},
      {"del f['/model']\nf['/model'] = np.zeros(3)", "/model: expected a group, found a dataset"},
      {"del f['/nav/depth']\nf.create_group('/nav/depth')", "/nav/depth: expected a dataset, found a group"},
      {"del f['/gps/time']", "/gps/time: missing dataset"},
      {"del f['/marks/range']", "/marks/range: missing dataset"},
      {"del f['/nav/depth']\nf['/nav/depth'] = h5py.SoftLink('/nav/altitude')", "/nav/depth: is a soft or external link"},
      {"del f['/nav/depth']\nf['/nav/depth'] = h5py.ExternalLink('/etc/passwd', '/x')", "/nav/depth: is a soft or external link"},
      // Values.
      {"t = f['/gps/time'][:]\nt[1] = t[0]\nf['/gps/time'][:] = t", "/gps/time: row 1: fix times must increase"},
      {"f['/truth/position'][3, 1] = np.nan", "/truth/position: row 3: position is NaN"},
      {"f['/truth/mines'][0, 0] = np.inf", "/truth/mines: row 0: position is infinite"},
  };
  expect_refused(samples().mission, cases, [](const std::string& p) { return read_mission(p); });
}

TEST(HostileHdf5, FilesAUserMayWriteWithH5pyAreStillRead) {
  // Variable-length strings (h5py's default), compressed and chunked datasets,
  // integers where doubles are expected when doubles hold them exactly.
  const std::string path = edited(samples().mission,
                                  "f.attrs['format'] = 'gesmi-mission'\n"
                                  "f['/model'].attrs['sonar_side'] = 'starboard'\n"
                                  "d = f['/nav/depth'][:]\ndel f['/nav/depth']\n"
                                  "f.create_dataset('/nav/depth', data=d, chunks=True, compression='gzip')\n"
                                  "r = f['/marks/range'][:]\ndel f['/marks/range']\nf['/marks/range'] = np.round(r).astype(np.int64)\n"
                                  "m = f['/marks/mine'][:]\ndel f['/marks/mine']\nf['/marks/mine'] = m.astype(np.int64)\n");
  const Mission original = read_mission(samples().mission);
  const Mission m = read_mission(path);
  EXPECT_EQ(m.depth, original.depth);
  EXPECT_EQ(m.mark_mine, original.mark_mine);
  ASSERT_EQ(m.mark_range.size(), original.mark_range.size());
  for (std::size_t j = 0; j < m.mark_range.size(); ++j) EXPECT_EQ(m.mark_range[j], std::round(original.mark_range[j]));
}

TEST(HostileHdf5, EditedResultsAreRefusedNamingWhatDiffers) {
  const Case cases[] = {
      {"lo = f['/tube/lower'][:]\nf['/tube/lower'][:] = np.roll(lo, 1, axis=0)", "/tube/lower: contents differ from the XXH3-128 digest"},
      {"u = f['/tube/upper'][:]\nu[100:200] += 50\nf['/tube/upper'][:] = u", "/tube/upper: contents differ"},
      {"m = f['/mines/lower'][:]\nm[0, 0] = -123456.0\nf['/mines/lower'][:] = m", "/mines/lower: contents differ"},
      {"lo = f['/tube/lower'][:]\nlo[5] = np.nan\nf['/tube/lower'][:] = lo", "/tube/lower: contents differ"},
      {"c = f['/marks/candidates'][:]\nc[:] = 1\nf['/marks/candidates'][:] = c", "/marks/candidates: contents differ"},
      {"del f['/increments/lower'].attrs['xxh128']", "/increments/lower: has no xxh128 attribute"},
      {"f.attrs.modify('mark_count', f.attrs['mark_count'] - 1)", "/marks/candidates: expected"},
      {"f.attrs['sweeps'] = np.int64(999)", "/: attributes or dataset digests differ"},
      {"f.attrs['inconsistency'] = 'all fine'", "/: attributes or dataset digests differ"},
      {"f.attrs['bounds_xxh128'] = np.array([b'a', b'b'])", "attribute bounds_xxh128 holds 2 values"},
      {"s = f['/waterfall/step'][:]\ns[[0, 1]] = s[[1, 0]] + 1\nf['/waterfall/step'][:] = s", "/waterfall/step: contents differ"},
      {"m = f['/waterfall/mine'][:]\ndel f['/waterfall/mine']\nf['/waterfall/mine'] = m[:-1]",
       "/waterfall/mine: " },
      // Values edited and their dataset digest recomputed the way gesmi computes it, by
      // an independent XXH3-128 (Python's xxhash): the dataset's check passes (so gesmi's
      // digest is that one), and the root digest, which covers every dataset digest,
      // still tells.
      {"import xxhash, struct\nname = b'/tube/lower'\nlo = f['/tube/lower'][:] - 1.0\nf['/tube/lower'][:] = lo\n"
       "h = xxhash.xxh3_128_hexdigest(struct.pack('<Q', len(name)) + name + struct.pack('<QQQ', lo.shape[0], 3, lo.size) + "
       "lo.astype('<f8').tobytes())\nf['/tube/lower'].attrs['xxh128'] = h",
       "/: attributes or dataset digests differ from the XXH3-128 digest"},
  };
  expect_refused(samples().result, cases, [](const std::string& p) { return read_result(p); });
}

// A result of more than two blocks of rows (H5File::kBlockRows), made once, or why it
// could not be made (each test that uses it then fails on its own, saying so).
struct MadeResult {
  std::string path, failure;
};
const MadeResult& three_block_result() {
  static const MadeResult result = [] {
    const std::string folder = test::temp_folder("hostile-blocks");
    const std::string mission = folder + "/m.h5", out = folder + "/r.h5";
    for (const std::vector<std::string>& command :
         {std::vector<std::string>{"simulate", "--seed", "3", "--duration", "1800", "-o", mission},
          std::vector<std::string>{"solve", mission, "-o", out}}) {
      const int code = test::run_gesmi(command).exit_code;
      if (code != 0) return MadeResult{"", "gesmi " + command[0] + " exited with " + std::to_string(code)};
    }
    return MadeResult{out, ""};
  }();
  return result;
}

// h5py lines recomputing a N x 3 dataset's digest the way gesmi computes it (Python's
// xxhash).
std::string redigest(const char* dataset) {
  return std::string("import xxhash, struct\nname = b'") + dataset + "'\nv = f['" + dataset + "'][:]\n"
         "f['" + dataset + "'].attrs['xxh128'] = xxhash.xxh3_128_hexdigest(struct.pack('<Q', len(name)) + name + "
         "struct.pack('<QQQ', v.shape[0], 3, v.size) + v.astype('<f8').tobytes())\n";
}

TEST(HostileHdf5, ABadRowInALaterBlockIsNamedOnceTheDigestsAreChecked) {
  // The tube and increments are read in blocks of H5File::kBlockRows rows, lower and
  // upper in step: a bad row in the third block is named by its row in the whole
  // dataset, and only once the digests are checked (the bad row may be the edit).
  ASSERT_EQ(three_block_result().failure, "");
  const std::string& result = three_block_result().path;
  ASSERT_GT(read_result(result).solution.time.size(), 2 * H5File::kBlockRows + 124);
  const std::string row = std::to_string(2 * H5File::kBlockRows + 123);
  const std::string cross = "lo = f['/tube/lower'][:]\nlo[" + row + ", 1] = 1e9\nf['/tube/lower'][:] = lo\n";
  const std::string cross_increment = "hi = f['/increments/upper'][:]\nhi[" + row + ", 2] = -1e9\nf['/increments/upper'][:] = hi\n";
  const std::string cross_redigested = cross + redigest("/tube/lower"),
                    cross_increment_redigested = cross_increment + redigest("/increments/upper");
  const std::string named_tube = "/tube: row " + row + ": not an interval (lower 1e+09",
                    named_increment = "/increments: row " + row + ": not an interval";
  const Case cases[] = {
      {cross.c_str(), "/tube/lower: contents differ from the XXH3-128 digest"},
      {cross_redigested.c_str(), named_tube.c_str()},
      {cross_increment.c_str(), "/increments/upper: contents differ"},
      {cross_increment_redigested.c_str(), named_increment.c_str()},
  };
  expect_refused(result, cases, [](const std::string& p) { return read_result(p); });
}

TEST(ResultTubeRows, AreTheWholeTubeInOrderBlockByBlock) {
  ASSERT_EQ(three_block_result().failure, "");
  const std::string& result = three_block_result().path;
  const TubeDomains whole = read_result(result, {.waterfall = false}).solution.domains;
  std::size_t next = 0, blocks = 0;
  const auto rows = [&](const SolveResult& so_far, std::size_t first, std::span<const Interval> x,
                        std::span<const Interval> y, std::span<const Interval> z) {
    ASSERT_EQ(first, next);
    ASSERT_EQ(so_far.solution.time.size(), whole.size());  // the times come before the tube
    ASSERT_LE(x.size(), H5File::kBlockRows);
    ASSERT_EQ(y.size(), x.size());
    ASSERT_EQ(z.size(), x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      ASSERT_TRUE(x[i] == whole.px[first + i] && y[i] == whole.py[first + i] && z[i] == whole.pz[first + i]) << first + i;
    }
    next += x.size();
    ++blocks;
  };
  const SolveResult streamed = read_result(result, {.waterfall = false, .tube_rows = rows});
  EXPECT_EQ(next, whole.size());
  EXPECT_EQ(blocks, (whole.size() + H5File::kBlockRows - 1) / H5File::kBlockRows);
  EXPECT_TRUE(streamed.solution.domains.px.empty());  // handed over, not kept
  EXPECT_TRUE(streamed.solution.domains.dx.empty());
}

TEST(HostileHdf5, TheTubeCsvExportWritesNothingForAnEditedTube) {
  // `gesmi export --format tube-csv` writes its rows as the tube's blocks arrive: a
  // changed digest found after two blocks were written still leaves no file. (A
  // recomputed dataset digest changes the root digest, which the export checks first;
  // the datasets it does not write are checked once, by the read that streams the tube.)
  ASSERT_EQ(three_block_result().failure, "");
  const std::string& result = three_block_result().path;
  const std::string row = std::to_string(2 * H5File::kBlockRows + 123);
  const std::string cross = "hi = f['/tube/upper'][:]\nhi[" + row + ", 0] = -1e9\nf['/tube/upper'][:] = hi\n";
  const std::string cross_redigested = cross + redigest("/tube/upper");
  const Case cases[] = {
      {cross.c_str(), "/tube/upper: contents differ from the XXH3-128 digest"},
      {cross_redigested.c_str(), "/: attributes or dataset digests differ"},
      {"f.attrs['sweeps'] = np.int64(999)", "/: attributes or dataset digests differ"},
      // (what the export does not write is checked too)
      {"w = f['/waterfall/upper'][:]\nw[0] += 1.0\nf['/waterfall/upper'][:] = w", "/waterfall/upper: contents differ"},
  };
  const std::vector<std::string> paths =
      test::h5py_edited_copies(result, {cases[0].edit, cases[1].edit, cases[2].edit, cases[3].edit});
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    const Case& c = cases[i];
    SCOPED_TRACE(c.edit);
    const std::string& path = paths[i];
    const std::string folder = test::temp_folder("hostile-tube-csv");
    const test::CommandResult run = test::run_gesmi({"export", path, "--format", "tube-csv", "-o", folder + "/t.csv"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find(path + ": " ), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(c.must_name), std::string::npos) << run.err;
    EXPECT_EQ(test::line_count(run.err), 1) << run.err;
    EXPECT_TRUE(test::names_in(folder).empty());
  }
  // A result replaced between the export's two reads (the status check's and the
  // streamed tube's) is refused.
  const std::string replaced = test::temp_folder("tube-csv-replaced");
  try {
    write_tube_csv(result, read_result(samples().result, {.tube = false, .waterfall = false}), replaced + "/t.csv");
    ADD_FAILURE() << "another result's rows were written";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find(result + ": changed while it was exported"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(test::names_in(replaced).empty());
  // Unedited, it writes one row a sample.
  const std::string folder = test::temp_folder("tube-csv");
  ASSERT_EQ(test::run_gesmi({"export", result, "--format", "tube-csv", "-o", folder + "/t.csv"}).exit_code, 0);
  std::ifstream csv(folder + "/t.csv");
  std::string line;
  std::size_t lines = 0;
  while (std::getline(csv, line)) ++lines;
  EXPECT_EQ(lines, read_result(result, {.tube = false, .waterfall = false}).solution.time.size() + 1);
}

TEST(HostileHdf5, PartialReadsCheckEveryDigest) {
  // `gesmi waterfall` and `candidates` read no tube, `export --format mines-csv` neither
  // tube nor waterfall: a result edited in what they leave out is refused all the same.
  const Case cases[] = {
      {"s = f['/waterfall/step'][:]\ns[[0, 1]] = s[[1, 0]] + 1\nf['/waterfall/step'][:] = s", "/waterfall/step: contents differ"},
      {"c = f['/marks/candidates'][:]\nc[:] = 1\nf['/marks/candidates'][:] = c", "/marks/candidates: contents differ"},
      {"f.attrs['sweeps'] = np.int64(999)", "/: attributes or dataset digests differ"},
      {"f['/tube/lower'].attrs['xxh128'] = 'ab'", "differ from the XXH3-128 digest"},  // the tube's or the root's
      {"u = f['/tube/upper'][:]\nu[100:200] += 50\nf['/tube/upper'][:] = u", "/tube/upper: contents differ"},
      {"d = f['/increments/lower'][:]\nd[7, 2] -= 1.0\nf['/increments/lower'][:] = d", "/increments/lower: contents differ"},
      {"w = f['/waterfall/upper'][:]\nw[3] += 1.0\nf['/waterfall/upper'][:] = w", "/waterfall/upper: contents differ"},
  };
  std::vector<std::string> edits;
  for (const Case& c : cases) edits.push_back(c.edit);
  const std::vector<std::string> paths = test::h5py_edited_copies(samples().result, edits);
  for (const ResultParts& parts : {ResultParts{.tube = false}, ResultParts{.tube = false, .increments = false, .waterfall = false},
                                  ResultParts{.tube = true, .waterfall = false}})
    for (std::size_t i = 0; i < std::size(cases); ++i)
      expect_refused_file(paths[i], cases[i], [&](const std::string& p) { return read_result(p, parts); });
  // What was not asked for is still not kept.
  const SolveResult partial = read_result(samples().result, {.tube = false, .waterfall = false});
  EXPECT_TRUE(partial.solution.domains.px.empty());
  EXPECT_TRUE(partial.solution.waterfall.lower.empty());
}

TEST(HostileHdf5, ResultsOfEarlierVersionsAreReadButCheckedValueByValue) {
  // A result as gesmi 0.1 wrote it: no format_version, no digests, a dense waterfall.
  const std::string strip =
      "del f.attrs['format_version']\ndel f.attrs['xxh128']\n"
      "n = f['/time'].shape[0]\nk = int(f.attrs['mine_count'])\nlo = np.full((n, k), np.nan)\nhi = np.full((n, k), np.nan)\n"
      "s = f['/waterfall/step'][:]\nm = f['/waterfall/mine'][:]\n"
      "lo[s, m] = f['/waterfall/lower'][:]\nhi[s, m] = f['/waterfall/upper'][:]\n"
      "for d in ['step', 'mine', 'lower', 'upper']: del f['/waterfall/' + d]\n"
      "f['/waterfall/lower'] = lo\nf['/waterfall/upper'] = hi\n"
      "def drop(name, obj):\n    if isinstance(obj, h5py.Dataset) and 'xxh128' in obj.attrs: del obj.attrs['xxh128']\n"
      "f.visititems(drop)\n";
  const SolveResult old = read_result(edited(samples().result, strip));
  EXPECT_EQ(old.format_version, 1);
  // The dense waterfall of then and the cells of now read back alike, NaN cells included.
  const Waterfall& now = read_result(samples().result).solution.waterfall;
  ASSERT_EQ(old.solution.waterfall.lower.size(), now.lower.size());
  EXPECT_EQ(old.solution.waterfall.step, now.step);
  EXPECT_EQ(old.solution.waterfall.mine, now.mine);
  EXPECT_EQ(std::memcmp(old.solution.waterfall.lower.data(), now.lower.data(), now.lower.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(old.solution.waterfall.upper.data(), now.upper.data(), now.upper.size() * sizeof(double)), 0);
  const Case cases[] = {
      {"m = f['/marks/mine'][:]\nm[0] = 9\nf['/marks/mine'][:] = m", "/marks/mine: row 0: mine 9 is not one of the result's"},
      {"r = f['/marks/range'][:]\nr[1] = -4\nf['/marks/range'][:] = r", "/marks/range: row 1: range must be finite and >= 0"},
      {"lo = f['/tube/lower'][:]\nlo[7, 0] = 1e9\nf['/tube/lower'][:] = lo", "/tube: row 7: not an interval"},
      {"lo = f['/tube/lower'][:]\nhi = f['/tube/upper'][:]\nlo[9] = np.nan\nhi[9] = np.nan\nf['/tube/lower'][:] = lo\nf['/tube/upper'][:] = hi",
       "/tube: a consistent result with an empty domain"},
      {"o = f['/marks/outlier'][:]\no[0] = 5\nf['/marks/outlier'][:] = o", "/marks/outlier: row 0: expected 0 or 1"},
      {"f.attrs['mine_count'] = np.int64(65)", "attribute mine_count must be between 0 and 64"},
  };
  std::vector<std::string> stripped_edits;
  for (const Case& c : cases) stripped_edits.push_back(strip + c.edit);
  std::vector<Case> stripped;
  for (std::size_t i = 0; i < std::size(cases); ++i) stripped.push_back({stripped_edits[i].c_str(), cases[i].must_name});
  expect_refused(samples().result, stripped, [](const std::string& p) { return read_result(p); });
  // The same tube checks when the tube is handed over block by block (gesmi export
  // --format tube-csv), which then writes no file.
  const auto streamed = [](const std::string& p) {
    const TubeRows ignore = [](const SolveResult&, std::size_t, std::span<const Interval>, std::span<const Interval>,
                               std::span<const Interval>) {};
    return read_result(p, {.waterfall = false, .tube_rows = ignore});
  };
  const std::vector<Case> tube_cases = {stripped[2], stripped[3]};
  const std::vector<std::string> tube_edited_paths = test::h5py_edited_copies(samples().result, {tube_cases[0].edit, tube_cases[1].edit});
  for (std::size_t i = 0; i < tube_cases.size(); ++i) {
    const Case& c = tube_cases[i];
    const std::string& path = tube_edited_paths[i];
    expect_refused_file(path, c, streamed);
    const std::string folder = test::temp_folder("tube-csv-old");
    const test::CommandResult run = test::run_gesmi({"export", path, "--format", "tube-csv", "-o", folder + "/t.csv"});
    EXPECT_EQ(run.exit_code, 2) << c.edit;
    EXPECT_NE(run.err.find(c.must_name), std::string::npos) << run.err;
    EXPECT_TRUE(test::names_in(folder).empty());
  }
}

// Results of formats 2 to 5 carry SHA-256 digests: one as gesmi 0.3.0 wrote it before
// format 6, and its mission (tests/data/format5/README.md).
std::string format_5_file(const char* name) { return test::source_dir() + "/tests/data/format5/" + name; }

TEST(HostileHdf5, FormatFiveResultsAreCheckedWithTheirSha256) {
  const SolveResult five = read_result(format_5_file("result-format5.h5"));
  EXPECT_EQ(five.format_version, 5);
  EXPECT_EQ(five.navigation_digest.size(), 64u);  // SHA-256: 64 hex digits, XXH3-128: 32
  EXPECT_EQ(read_result(samples().result).navigation_digest.size(), 32u);
  // Its dataset digests are Python's hashlib SHA-256 of the same bytes: the check of
  // /tube/lower passes once its values and digest are both changed, and the root
  // digest still tells.
  const Case cases[] = {
      {"lo = f['/tube/lower'][:]\nf['/tube/lower'][:] = np.roll(lo, 1, axis=0)", "/tube/lower: contents differ from the SHA-256 digest"},
      {"f.attrs['sweeps'] = np.int64(999)", "/: attributes or dataset digests differ from the SHA-256 digest"},
      {"del f['/increments/lower'].attrs['sha256']", "/increments/lower: has no sha256 attribute"},
      {"import hashlib, struct\nname = b'/tube/lower'\nlo = f['/tube/lower'][:] - 1.0\nf['/tube/lower'][:] = lo\n"
       "h = hashlib.sha256(struct.pack('<Q', len(name)) + name + struct.pack('<QQQ', lo.shape[0], 3, lo.size) + "
       "lo.astype('<f8').tobytes()).hexdigest()\nf['/tube/lower'].attrs['sha256'] = h",
       "/: attributes or dataset digests differ from the SHA-256 digest"},
      // A format-5 file is not checked with XXH3-128 because it says it is of format 6.
      {"f.attrs.modify('format_version', 6)", "/: missing attribute navigation_xxh128"},
  };
  expect_refused(format_5_file("result-format5.h5"), cases, [](const std::string& p) { return read_result(p); });
}

TEST(HostileHdf5, AFormatFiveResultWarmStartsAsItsFormatSixTwin) {
  // The mission's fingerprints are computed as SHA-256 for it: the same rerun as from a
  // result of today's format (no mark added: what is checked is the comparison of the
  // fingerprints). The same to within 1e-9 m, not bitwise: a rerun keeps the earlier
  // result's increments, and the file's were computed before the sensor kernel took
  // libmvec's sines with their wider margin (docs/performance.md), 5e-15 m a step.
  const std::string folder = test::temp_folder("hostile-warm-5");
  const std::string mission = format_5_file("mission.h5"), five = format_5_file("result-format5.h5");
  ASSERT_EQ(test::run_gesmi({"solve", mission, "-o", folder + "/r6.h5"}).exit_code, 0);
  const test::CommandResult from_five = test::run_gesmi({"solve", mission, "--from", five, "-o", folder + "/w5.h5"});
  if (read_result(five).version != read_result(folder + "/r6.h5").version) {
    // Another gesmi version: refused as such (it may enclose differently), not for its digests.
    EXPECT_EQ(from_five.exit_code, 2);
    EXPECT_NE(from_five.err.find("computed by gesmi 0.3.0"), std::string::npos) << from_five.err;
    return;
  }
  ASSERT_EQ(from_five.exit_code, 0) << from_five.err;
  const test::CommandResult from_six = test::run_gesmi({"solve", mission, "--from", folder + "/r6.h5", "-o", folder + "/w6.h5"});
  ASSERT_EQ(from_six.exit_code, 0) << from_six.err;
  const SolveResult w6 = read_result(folder + "/w6.h5"), w5 = read_result(folder + "/w5.h5");
  EXPECT_EQ(w5.solution.report.mode, SolveMode::warm);
  EXPECT_EQ(w6.solution.report.mode, SolveMode::warm);
  EXPECT_EQ(w5.format_version, kResultFormat);  // a rerun is written in today's format
  EXPECT_EQ(w5.navigation_digest, w6.navigation_digest);
  const TubeDomains& a = w5.solution.domains;
  const TubeDomains& b = w6.solution.domains;
  for (const auto& [x, y] : {std::pair{&a.px, &b.px}, std::pair{&a.py, &b.py}, std::pair{&a.pz, &b.pz}}) {
    ASSERT_EQ(x->size(), y->size());
    for (std::size_t k = 0; k < x->size(); ++k) {
      EXPECT_NEAR((*x)[k].lo(), (*y)[k].lo(), 1e-9);
      EXPECT_NEAR((*x)[k].hi(), (*y)[k].hi(), 1e-9);
    }
  }
  // Another mission is still refused: the SHA-256 fingerprints are compared.
  const std::string other = edited(mission, "d = f['/nav/depth'][:]\nd[3] += 0.5\nf['/nav/depth'][:] = d");
  const test::CommandResult refused = test::run_gesmi({"solve", other, "--from", five, "-o", folder + "/w7.h5"});
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("the navigation data"), std::string::npos) << refused.err;
}

TEST(HostileHdf5, WarmStartFromAnEditedResultExitsTwoAndWritesNothing) {
  const std::string shifted = edited(samples().result, "lo = f['/tube/lower'][:]\nf['/tube/lower'][:] = np.roll(lo, 1, axis=0)");
  const std::string folder = test::temp_folder("hostile-warm");
  const test::CommandResult r = test::run_gesmi({"solve", samples().mission, "--from", shifted, "-o", folder + "/r2.h5"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(shifted + ": /tube/lower: contents differ"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(folder));
  // The unedited result still warm-starts.
  const test::CommandResult ok = test::run_gesmi({"solve", samples().mission, "--from", samples().result, "-o", folder + "/r3.h5"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

}  // namespace
}  // namespace gesmi::io
