// Datasets read and written in blocks of rows (no row-major copy of the whole dataset):
// H5File::read_columns_into reads files written by Debian's h5py, independently of
// gesmi's writer, with row counts around the block size, value for value, and names a
// value refused in a later block by its index in the whole dataset; datasets written by
// write_digested_in_blocks read back by h5py value for value, with the digest of the
// whole-array writer.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "io/format_error.h"
#include "io/hdf5/h5_digest.h"
#include "io/hdf5/h5_file.h"
#include "tests/support/run_command.h"

namespace gesmi::io {
namespace {

// A file made by a few lines of h5py ('f' is the file open for writing).
std::string written_by_h5py(const std::string& name, const std::string& python) {
  const std::string folder = test::temp_folder(name);
  const std::string path = folder + "/columns.h5", script = folder + "/write.py";
  std::ofstream(script) << "import h5py, numpy as np, sys\nf = h5py.File(sys.argv[1], 'w')\n" << python << "\nf.close()\n";
  EXPECT_EQ(std::system(("/usr/bin/python3 " + script + " " + path).c_str()), 0) << python;
  return path;
}

// Three column vectors read_columns_into fills.
struct ThreeColumns {
  std::vector<double> a, b, c;
  std::vector<double>* columns[3] = {&a, &b, &c};
  ThreeColumns() = default;
  ThreeColumns(const ThreeColumns&) = delete;
  void read(const H5File& file, const std::string& dataset) {
    file.read_columns_into(dataset, std::span<std::vector<double>* const>(columns, 3));
  }
  // The message of the FormatError reading `dataset` gives (a failure, and empty, if none).
  std::string refusal(const H5File& file, const std::string& dataset) {
    try {
      read(file, dataset);
    } catch (const FormatError& e) {
      return e.what();
    }
    ADD_FAILURE() << dataset << " accepted";
    return {};
  }
};

// Value (r, c) of the datasets below: exact in doubles and in 64-bit integers.
double expected(std::size_t r, std::size_t c) { return 4.0 * static_cast<double>(r) + static_cast<double>(c); }

// Row counts around the blocks: none, one row, one fewer than a block, a block, one more,
// several and a rest.
std::vector<std::size_t> row_counts() {
  const std::size_t b = H5File::kBlockRows;
  return {0, 1, b - 1, b, b + 1, 3 * b + 5};
}

std::string python_list(const std::vector<std::size_t>& values) {
  std::string list;
  for (const std::size_t v : values) list += (list.empty() ? "" : ", ") + std::to_string(v);
  return "[" + list + "]";
}

TEST(H5Blocks, EveryRowIsReadAroundAndAcrossTheBlocks) {
  const std::string python = "for n in " + python_list(row_counts()) + ":\n"
                             "    v = 4.0 * np.arange(n)[:, None] + np.arange(3)[None, :]\n"
                             "    f[f'd{n}'] = v\n"
                             "    f[f'i{n}'] = v.astype(np.int64)\n"
                             "    f[f's{n}'] = v.astype(np.int32)\n";
  const H5File file = H5File::open_read(written_by_h5py("h5-columns", python));
  for (const std::size_t n : row_counts())
    for (const char* kind : {"d", "i", "s"}) {
      const std::string dataset = kind + std::to_string(n);
      SCOPED_TRACE(dataset);
      ThreeColumns read;
      read.a = {7.0};  // earlier contents and sizes are replaced
      read.c.assign(1000, 7.0);
      read.read(file, dataset);
      std::size_t wrong = 0;
      for (std::size_t col = 0; col < 3; ++col) {
        ASSERT_EQ(read.columns[col]->size(), n);
        for (std::size_t r = 0; r < n; ++r) wrong += (*read.columns[col])[r] != expected(r, col) ? 1 : 0;
      }
      EXPECT_EQ(wrong, 0u);
    }
}

TEST(H5Blocks, TwoDatasetsAreReadInStepBlockByBlock) {
  // RowBlocks as a result's lower and upper bounds are read: in step, every row once,
  // each block's first row reported, and the digest of the blocks that of the whole.
  const std::string python = "for n in " + python_list(row_counts()) + ":\n"
                             "    v = 4.0 * np.arange(n)[:, None] + np.arange(3)[None, :]\n"
                             "    f[f'lo{n}'] = v\n"
                             "    f[f'hi{n}'] = -v\n";
  const H5File file = H5File::open_read(written_by_h5py("h5-row-blocks", python));
  for (const std::size_t n : row_counts()) {
    SCOPED_TRACE(n);
    H5File::RowBlocks lower(file, "lo" + std::to_string(n), 3), upper(file, "hi" + std::to_string(n), 3);
    ASSERT_EQ(lower.rows(), n);
    DatasetDigest blockwise("/v", n, 3, DigestKind::xxh128), whole("/v", n, 3, DigestKind::xxh128);
    std::vector<double> all;
    std::size_t rows_seen = 0, wrong = 0;
    for (std::span<const double> lo = lower.next(), hi = upper.next(); !lo.empty(); lo = lower.next(), hi = upper.next()) {
      ASSERT_EQ(lower.first(), rows_seen);
      ASSERT_EQ(upper.first(), rows_seen);
      ASSERT_EQ(hi.size(), lo.size());
      ASSERT_LE(lo.size(), 3 * H5File::kBlockRows);
      blockwise.add(lo);
      for (std::size_t i = 0; i < lo.size(); ++i) {
        const double want = expected(rows_seen + i / 3, i % 3);
        wrong += lo[i] != want || hi[i] != -want ? 1 : 0;
        all.push_back(lo[i]);
      }
      rows_seen += lo.size() / 3;
    }
    EXPECT_EQ(rows_seen, n);
    EXPECT_EQ(wrong, 0u);
    whole.add(std::span<const double>(all));
    EXPECT_EQ(blockwise.hex(), whole.hex());
  }
  // A wrong number of columns: refused on opening, before any block.
  const H5File four_columns = H5File::open_read(written_by_h5py("h5-row-blocks-four", "f['four'] = np.zeros((10, 4))\n"));
  try {
    const H5File::RowBlocks four(four_columns, "four", 3);
    ADD_FAILURE() << "four columns accepted";
  } catch (const FormatError& e) {
    EXPECT_NE(std::string(e.what()).find("four: expected 3 columns, found 4"), std::string::npos) << e.what();
  }
}

TEST(H5Blocks, AnIntegerTooLargeInALaterBlockIsNamedByItsIndex) {
  const std::size_t rows = 3 * H5File::kBlockRows + 5, bad_row = H5File::kBlockRows + 10;
  const std::string path = written_by_h5py("h5-columns-wide", "v = np.zeros((" + std::to_string(rows) +
                                                                  ", 3), dtype=np.int64)\n"
                                                                  "v[" + std::to_string(bad_row) + ", 1] = 2**60\n"
                                                                  "f['wide'] = v\n");
  ThreeColumns read;
  const std::string what = read.refusal(H5File::open_read(path), "wide");
  EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
  // Row bad_row, column 1 of a row-major N x 3 dataset: value 3 bad_row + 1.
  const std::string named = "value " + std::to_string(3 * bad_row + 1) + " is an integer too large";
  EXPECT_NE(what.find(named), std::string::npos) << what;
}

TEST(H5Blocks, AWrongColumnCountIsRefusedBeforeReading) {
  const H5File file = H5File::open_read(written_by_h5py("h5-columns-four", "f['four'] = np.zeros((20000, 4))\n"));
  ThreeColumns read;
  const std::string what = read.refusal(file, "four");
  EXPECT_NE(what.find("expected 3 columns, found 4"), std::string::npos) << what;
  EXPECT_TRUE(read.a.empty());
}

TEST(H5Blocks, WrittenInBlocksAsWholeWithTheSameDigest) {
  const std::string folder = test::temp_folder("h5-blocks-write");
  for (const std::size_t n : row_counts())
    for (const std::size_t columns : {std::size_t{1}, std::size_t{3}}) {
      const std::string tag = std::to_string(n) + "x" + std::to_string(columns);
      SCOPED_TRACE(tag);
      const int rank = columns == 1 ? 1 : 2;
      std::vector<double> whole(n * columns);
      for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < columns; ++c) whole[r * columns + c] = expected(r, c);
      const std::string in_blocks = folder + "/blocks-" + tag + ".h5", at_once = folder + "/whole-" + tag + ".h5";
      std::size_t rows_filled = 0;
      {
        H5File f = H5File::create(in_blocks);
        const std::string digest = write_digested_in_blocks(
            f, "/g/v", n, columns, rank, DigestKind::xxh128, [&](std::size_t first, std::size_t count, std::span<double> out) {
              ASSERT_EQ(out.size(), count * columns);
              ASSERT_EQ(first, rows_filled);  // in order, each row once
              rows_filled += count;
              for (std::size_t r = 0; r < count; ++r)
                for (std::size_t c = 0; c < columns; ++c) out[r * columns + c] = expected(first + r, c);
            });
        H5File g = H5File::create(at_once);
        EXPECT_EQ(digest, write_digested(g, "/g/v", whole, n, DigestKind::xxh128, columns, rank));
        f.close();
        g.close();
      }
      EXPECT_EQ(rows_filled, n);
      // h5py reads the shape and every value (an independent reader).
      const std::string script = folder + "/check.py";
      std::ofstream(script) << "import h5py, numpy as np, sys\n"
                            << "v = h5py.File(sys.argv[1], 'r')['/g/v'][...]\n"
                            << "n, k = " << n << ", " << columns << "\n"
                            << "want = 4.0 * np.arange(n)[:, None] + np.arange(k)[None, :]\n"
                            << "want = want[:, 0] if k == 1 else want\n"
                            << "sys.exit(0 if v.shape == want.shape and (v == want).all() else 1)\n";
      EXPECT_EQ(std::system(("/usr/bin/python3 " + script + " " + in_blocks).c_str()), 0);
    }
}

}  // namespace
}  // namespace gesmi::io
