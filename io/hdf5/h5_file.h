#pragma once
// A thin RAII wrapper over the HDF5 C API (the C++ API is reported discontinued
// from HDF5 2.0): files, typed 1-D and 2-D datasets of double and int32, and scalar
// attributes. Every failure is a FormatError naming the file, the object and the
// reason; HDF5's own error printing is switched off.

#include <cstdint>
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

 private:
  std::int64_t id_ = -1;
  Closer closer_ = nullptr;
};

/// Shape of a dataset: 1 or 2 dimensions (rows, columns).
struct H5Shape {
  std::size_t rows = 0, columns = 1;
  int rank = 1;
};

class H5File {
 public:
  /// Opens an existing file read-only; FormatError if it is missing or not HDF5.
  static H5File open_read(const std::string& path);
  /// Creates (truncates) a file for writing.
  static H5File create(const std::string& path);

  const std::string& path() const { return path_; }

  bool has(const std::string& object) const;
  /// Shape of a dataset; FormatError if missing or not 1-D/2-D.
  H5Shape shape(const std::string& dataset) const;

  /// Reads a whole dataset (1-D, or 2-D row-major) converting to double / int32.
  std::vector<double> read_doubles(const std::string& dataset) const;
  std::vector<std::int32_t> read_ints(const std::string& dataset) const;
  /// Reads into a caller-sized buffer (no extra copy); sizes must match.
  void read_doubles_into(const std::string& dataset, std::span<double> out) const;
  /// Reads one column of a 2-D dataset straight into out (rows values): a mission's
  /// N x 3 arrays load into three flat vectors without a transposing copy.
  void read_column_into(const std::string& dataset, std::size_t column, std::span<double> out) const;

  /// Creates a group (and its parents) if missing.
  void create_group(const std::string& group) { ensure_parent_groups(group + "/"); }
  /// Writes a dataset (creating parent groups): rows x columns, row-major.
  void write(const std::string& dataset, std::span<const double> values, std::size_t rows, std::size_t columns = 1,
             int rank = 1);
  void write(const std::string& dataset, std::span<const std::int32_t> values, std::size_t rows,
             std::size_t columns = 1, int rank = 1);

  /// Writes a 3-D dataset (e.g. N x 3 x 3 covariances), row-major.
  void write_3d(const std::string& dataset, std::span<const double> values, std::size_t d0, std::size_t d1,
                std::size_t d2);

  // Attributes on an object ("/" for the file).
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
  H5Handle open_dataset(const std::string& dataset) const;
  H5Handle file_;
  std::string path_;
};

}  // namespace gesmi::io
