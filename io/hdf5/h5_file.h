#pragma once
// A thin RAII wrapper over the HDF5 C API (the C++ API is reported discontinued
// from HDF5 2.0): files, typed 1-D and 2-D datasets of double and int32, and scalar
// attributes. Every failure is a FormatError naming the file, the object and the
// reason; HDF5's own error printing is switched off.
//
// Reading never trusts the file: before any value is read, the object's kind
// (group or dataset, through hard links only), class, rank, dimensions and stored
// size are checked, so a hostile or damaged file gives one FormatError and never an
// overflow or an allocation the file cannot back (docs/formats.md, "Limits").

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace gesmi::io {

/// Owns one hid_t and closes it with the matching H5*close.
class H5Handle {
 public:
  using Closer = int (*)(std::int64_t);
  H5Handle() = default;
  H5Handle(std::int64_t id, Closer closer) : id_(id), closer_(closer) {}
  H5Handle(H5Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
  H5Handle& operator=(H5Handle&& other) noexcept;
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  ~H5Handle() { reset(); }
  std::int64_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset();
  /// Gives up ownership without closing.
  std::int64_t release() {
    const std::int64_t id = id_;
    id_ = -1;
    return id;
  }

 private:
  std::int64_t id_ = -1;
  Closer closer_ = nullptr;
};

/// Shape of a dataset: 1 or 2 dimensions (rows, columns).
struct H5Shape {
  std::size_t rows = 0, columns = 1;
  int rank = 1;
};

/// Largest number of values gesmi reads from one dataset (8 GB of doubles); a
/// file declaring more is refused before anything is allocated.
inline constexpr std::size_t kMaxDatasetValues = 1'000'000'000;
/// Largest string attribute gesmi reads (bytes).
inline constexpr std::size_t kMaxStringAttribute = 1 << 20;

enum class H5Kind { missing, group, dataset };

class H5File {
 public:
  /// Opens an existing file read-only; FormatError if it is missing or not HDF5.
  static H5File open_read(const std::string& path);
  /// Creates (truncates) a file for writing at `path`; messages name `shown_as`
  /// (the final name of a file written under a temporary one).
  static H5File create(const std::string& path, const std::string& shown_as = {});

  /// The name used in messages.
  const std::string& path() const { return path_; }

  /// What `object` is; missing when any level of the path is absent. FormatError
  /// when a level of the path is not a group, or is a soft or external link.
  H5Kind kind(const std::string& object) const;
  /// True when `object` exists (a group or a dataset).
  bool has(const std::string& object) const { return kind(object) != H5Kind::missing; }
  /// True when `group` exists as a group; FormatError when it exists as something else.
  bool has_group(const std::string& group) const;
  /// The names of the links in `group` (a plain group), in name order; FormatError when
  /// it holds more than `limit` of them (a hostile file's millions).
  std::vector<std::string> members(const std::string& group, std::size_t limit) const;
  /// Shape of a dataset; FormatError if missing, not a dataset, or not 1-D/2-D.
  H5Shape shape(const std::string& dataset) const;

  /// Reads a whole dataset (1-D, or 2-D row-major) as doubles: floating-point data
  /// of up to 64 bits, or integers whose values doubles hold exactly.
  /// rank: the number of dimensions the format gives the dataset (0: 1 or 2).
  std::vector<double> read_doubles(const std::string& dataset, int rank = 0) const;
  /// Reads a whole dataset of integers that fit in 32 bits.
  std::vector<std::int32_t> read_ints(const std::string& dataset, int rank = 0) const;
  /// Reads into a caller-sized buffer (no extra copy); sizes must match.
  void read_doubles_into(const std::string& dataset, std::span<double> out) const;
  /// Reads a 2-D dataset of rows x columns.size() values, in contiguous blocks of rows,
  /// into one flat vector per column (each sized to the rows): a mission's N x 3 arrays.
  /// On a FormatError from a later block the columns are left sized and partly filled.
  void read_columns_into(const std::string& dataset, std::span<std::vector<double>* const> columns) const;

  /// A dataset of doubles read in blocks of at most kBlockRows rows through one small
  /// buffer, so that several datasets can be read in step (the lower and upper bounds of
  /// a result) without a copy of each whole. Opening checks what read_doubles checks
  /// (rank: the number of dimensions the format gives it, 0: 1 or 2) and the number of
  /// columns.
  class RowBlocks {
   public:
    RowBlocks(const H5File& file, const std::string& dataset, std::size_t columns, int rank = 0);
    RowBlocks(H5File&&, const std::string&, std::size_t, int = 0) = delete;  // (it reads the file as it goes)
    std::size_t rows() const { return rows_; }
    /// The next block's rows, row-major; empty after the last.
    std::span<const double> next();
    /// The index of the first row of the block next() returned last.
    std::size_t first() const { return first_; }

   private:
    const H5File& file_;
    std::string dataset_;
    H5Handle handle_;
    std::size_t rows_ = 0, columns_, first_ = 0, end_ = 0;
    std::vector<double> buffer_;
  };

  /// Creates a group (and its parents) if missing.
  void create_group(const std::string& group) { ensure_parent_groups(group + "/"); }
  /// Writes a dataset (creating parent groups): rows x columns, row-major.
  void write(const std::string& dataset, std::span<const double> values, std::size_t rows, std::size_t columns = 1,
             int rank = 1);
  void write(const std::string& dataset, std::span<const std::int32_t> values, std::size_t rows,
             std::size_t columns = 1, int rank = 1);

  /// Rows of a dataset written in blocks: fill(first, count, out) puts rows [first, first
  /// + count) in out, row-major (count x columns values).
  using RowFiller = std::function<void(std::size_t first, std::size_t count, std::span<double> out)>;
  /// Writes a rows x columns dataset of doubles (1-D when rank is 1) in blocks of at most
  /// kBlockRows rows through one small buffer: no row-major copy of the whole dataset
  /// (240 MB an N x 3 dataset at 10^7 steps).
  void write_in_blocks(const std::string& dataset, std::size_t rows, std::size_t columns, int rank,
                       const RowFiller& fill);
  /// Rows per block of write_in_blocks and read_columns_into: 192 KiB for three columns,
  /// small enough to stay in the processor's cache (blocks of 2,048 rows made a solve of
  /// the reference mission about 10 % slower: HDF5's cost per call).
  static constexpr std::size_t kBlockRows = std::size_t{1} << 13;

  /// Writes a 3-D dataset (e.g. N x 3 x 3 covariances), row-major.
  void write_3d(const std::string& dataset, std::span<const double> values, std::size_t d0, std::size_t d1,
                std::size_t d2);

  // Attributes on an object ("/" for the file). Readers return nullopt when the
  // attribute is absent and throw FormatError when it is not exactly one value of
  // the expected kind (a number, an integer, a string).
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, std::int64_t value);
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  std::optional<double> double_attribute(const std::string& object, const std::string& name) const;
  std::optional<std::int64_t> int_attribute(const std::string& object, const std::string& name) const;
  std::optional<std::string> string_attribute(const std::string& object, const std::string& name) const;

  /// Flushes and closes; errors while closing become FormatError.
  void close();

 private:
  H5File(H5Handle file, std::string path) : file_(std::move(file)), path_(std::move(path)) {}
  [[noreturn]] void fail(const std::string& object, const std::string& reason) const;
  void ensure_parent_groups(const std::string& dataset);
  /// The object at a path of hard-linked groups, opened (a group or a dataset), or an
  /// invalid handle when a level is missing; FormatError as kind() describes.
  H5Handle open_plain_object(const std::string& object) const;
  H5Handle open_dataset(const std::string& dataset) const;
  H5Shape shape_of(std::int64_t dataset, const std::string& name) const;
  H5Handle open_attribute(const std::string& object, const std::string& name) const;
  /// The shape, once class and stored size are known to be readable (integers or numbers).
  H5Shape checked_shape(std::int64_t dataset, const std::string& name, bool integers, int rank = 0) const;
  /// Rows [first, first + rows) of a dataset of `columns` columns.
  struct RowBlock {
    std::size_t first, rows, columns;
  };
  /// A block of rows of an open dataset, its type checked, as doubles into out (rows x
  /// columns values, row-major).
  void read_rows(std::int64_t dataset, const std::string& name, RowBlock block, std::span<double> out) const;
  H5Handle file_;
  std::string path_;
  mutable std::vector<std::string> groups_;  // levels already found to be hard-linked groups
};

}  // namespace gesmi::io
