// Reading datasets: every read checks the element class, the shape and the stored
// size before a value is read or a buffer allocated.

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/format_error.h"
#include "io/hdf5/h5_file.h"

namespace gesmi::io {
namespace {

// Integers beyond 2^53 have no exact double.
constexpr double kLargestExactInteger = 9007199254740992.0;
// deflate, the strongest filter HDF5 ships, compresses at most about 1032:1.
constexpr double kLargestCompression = 1100.0;

// Whether rows x columns is the whole dataset.
bool whole_dataset(hid_t dataset, std::size_t rows, std::size_t columns) {
  const H5Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
  hsize_t dims[2] = {0, 0};
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(space.get(), dims, nullptr) != rank) return false;
  return dims[0] == rows && (rank == 1 || dims[1] == columns);
}

// Why values of this stored type cannot be read as doubles, or empty.
std::string double_type_problem(hid_t type) {
  switch (H5Tget_class(type)) {
    case H5T_FLOAT:
      return H5Tget_size(type) <= 8 ? "" : "stores floating-point numbers wider than 64 bits, expected doubles";
    case H5T_INTEGER:
      return "";
    case H5T_ENUM:
      return "stores an enumeration (booleans?), expected numbers";
    case H5T_STRING:
      return "stores strings, expected numbers";
    default:
      return "stores compound or opaque values, expected numbers";
  }
}

std::string integer_type_problem(hid_t type) {
  switch (H5Tget_class(type)) {
    case H5T_INTEGER:
      return "";
    case H5T_FLOAT:
      return "stores floating-point numbers, expected integers";
    case H5T_ENUM:
      return "stores an enumeration (booleans?), expected integers";
    case H5T_STRING:
      return "stores strings, expected integers";
    default:
      return "stores compound or opaque values, expected integers";
  }
}

// Why the file cannot back `values` values of `type_size` bytes, or empty: a
// small file can declare a huge dataset that was never written.
std::string storage_problem(hid_t dataset, std::size_t values, std::size_t type_size) {
  if (values == 0) return "";
  const H5Handle plist(H5Dget_create_plist(dataset), H5Pclose);
  if (!plist.valid()) return "cannot read its storage properties (damaged file?)";
  if (H5Pget_layout(plist.get()) == H5D_VIRTUAL) return "is a virtual dataset; gesmi reads only data stored in the file";
  if (H5Pget_external_count(plist.get()) > 0) return "keeps its data in an external file; gesmi reads only data stored in the file";
  const double declared = static_cast<double>(values) * static_cast<double>(type_size);
  const double stored = static_cast<double>(H5Dget_storage_size(dataset));
  const int filters = H5Pget_nfilters(plist.get());
  const bool backed = filters > 0 ? declared <= kLargestCompression * stored : declared <= stored;
  if (backed) return "";
  return "declares " + std::to_string(values) + " values but the file stores " +
         std::to_string(static_cast<long long>(stored)) + " bytes for them (never written, or truncated)";
}

}  // namespace

H5Shape H5File::checked_shape(std::int64_t d, const std::string& dataset, bool integers, int rank) const {
  const H5Shape s = shape_of(d, dataset);
  if (rank != 0 && s.rank != rank)
    fail(dataset, "expected " + std::to_string(rank) + " dimension" + (rank == 1 ? "" : "s") + ", found " + std::to_string(s.rank));
  const H5Handle type(H5Dget_type(d), H5Tclose);
  if (!type.valid()) fail(dataset, "cannot read its type (damaged file?)");
  const std::string why_type = integers ? integer_type_problem(type.get()) : double_type_problem(type.get());
  if (!why_type.empty()) fail(dataset, why_type);
  const std::string why_storage = storage_problem(d, s.rows * s.columns, H5Tget_size(type.get()));
  if (!why_storage.empty()) fail(dataset, why_storage);
  return s;
}

void H5File::read_rows(std::int64_t d, const std::string& dataset, RowBlock block, std::span<double> out) const {
  const H5Handle type(H5Dget_type(d), H5Tclose);
  if (!type.valid()) fail(dataset, "cannot read its type (damaged file?)");
  // The whole dataset (H5S_ALL), or the block's rows of the file's row-major values into
  // a flat buffer.
  H5Handle file_space, memory_space;
  hid_t memory = H5S_ALL, file = H5S_ALL;
  if (block.first > 0 || !whole_dataset(d, block.rows, block.columns)) {
    file_space = H5Handle(H5Dget_space(d), H5Sclose);
    const hsize_t start[2] = {block.first, 0}, count[2] = {block.rows, block.columns};
    const hsize_t values = block.rows * block.columns;
    memory_space = H5Handle(H5Screate_simple(1, &values, nullptr), H5Sclose);
    if (!file_space.valid() || !memory_space.valid() ||
        H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0)
      fail(dataset, "cannot select rows " + std::to_string(block.first) + " to " +
                        std::to_string(block.first + block.rows - 1) + " (damaged file?)");
    memory = memory_space.get();
    file = file_space.get();
  }
  const bool wide_integers = H5Tget_class(type.get()) == H5T_INTEGER && H5Tget_size(type.get()) > 4;
  if (!wide_integers) {
    if (H5Dread(d, H5T_NATIVE_DOUBLE, memory, file, H5P_DEFAULT, out.data()) < 0)
      fail(dataset, "cannot read the values (truncated or damaged file)");
    return;
  }
  // 64-bit integers: read exactly, then refuse values a double cannot hold.
  const bool is_signed = H5Tget_sign(type.get()) != H5T_SGN_NONE;
  std::vector<std::int64_t> signed_values(is_signed ? out.size() : 0);
  std::vector<std::uint64_t> unsigned_values(is_signed ? 0 : out.size());
  const herr_t status = is_signed ? H5Dread(d, H5T_NATIVE_INT64, memory, file, H5P_DEFAULT, signed_values.data())
                                  : H5Dread(d, H5T_NATIVE_UINT64, memory, file, H5P_DEFAULT, unsigned_values.data());
  if (status < 0) fail(dataset, "cannot read the values (truncated or damaged file)");
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double v = is_signed ? static_cast<double>(signed_values[i]) : static_cast<double>(unsigned_values[i]);
    if (std::fabs(v) > kLargestExactInteger)
      fail(dataset, "value " + std::to_string(block.first * block.columns + i) +
                        " is an integer too large to be read exactly");
    out[i] = v;
  }
}

void H5File::read_doubles_into(const std::string& dataset, std::span<double> out) const {
  const H5Handle d = open_dataset(dataset);
  const H5Shape s = checked_shape(d.get(), dataset, false);
  if (s.rows * s.columns != out.size())
    fail(dataset, "expected " + std::to_string(out.size()) + " values, found " + std::to_string(s.rows * s.columns));
  if (!out.empty()) read_rows(d.get(), dataset, {0, s.rows, s.columns}, out);
}

H5File::RowBlocks::RowBlocks(const H5File& file, const std::string& dataset, std::size_t columns, int rank)
    : file_(file), dataset_(dataset), handle_(file.open_dataset(dataset)), columns_(columns) {
  const H5Shape s = file.checked_shape(handle_.get(), dataset, false, rank);  // before allocating
  if (s.columns != columns)
    file.fail(dataset, "expected " + std::to_string(columns) + " columns, found " + std::to_string(s.columns));
  rows_ = s.rows;
}

std::span<const double> H5File::RowBlocks::next() {
  first_ = end_;
  if (first_ >= rows_) return {};
  // At the first block, after the caller's own arrays: allocated before them, the buffer
  // moved them up the heap, and `marks add` touched one more 2 MiB page (18 -> 20 MB).
  if (buffer_.empty()) buffer_.resize(std::min(rows_, kBlockRows) * columns_);
  end_ = std::min(rows_, first_ + kBlockRows);
  const std::span<double> values(buffer_.data(), (end_ - first_) * columns_);
  file_.read_rows(handle_.get(), dataset_, {first_, end_ - first_, columns_}, values);
  return values;
}

void H5File::read_columns_into(const std::string& dataset, std::span<std::vector<double>* const> columns) const {
  // Contiguous reads of blocks of rows through one small buffer: a strided read per
  // column costs more than the copy, and a row-major copy of the whole dataset would be
  // one more array to fault in and zero (240 MB a dataset at 10^7 steps).
  const std::size_t width = columns.size();
  RowBlocks blocks(*this, dataset, width, 2);
  for (std::vector<double>* out : columns) out->resize(blocks.rows());
  for (std::span<const double> block = blocks.next(); !block.empty(); block = blocks.next())
    for (std::size_t c = 0; c < width; ++c) {
      double* out = columns[c]->data() + blocks.first();
      for (std::size_t r = 0; r < block.size() / width; ++r) out[r] = block[r * width + c];
    }
}

std::vector<double> H5File::read_doubles(const std::string& dataset, int rank) const {
  const H5Handle d = open_dataset(dataset);
  const H5Shape s = checked_shape(d.get(), dataset, false, rank);  // before allocating
  std::vector<double> values(s.rows * s.columns);
  if (!values.empty()) read_rows(d.get(), dataset, {0, s.rows, s.columns}, values);
  return values;
}

std::vector<std::int32_t> H5File::read_ints(const std::string& dataset, int rank) const {
  const H5Handle d = open_dataset(dataset);
  const H5Shape s = checked_shape(d.get(), dataset, true, rank);  // before allocating
  const std::size_t count = s.rows * s.columns;
  const H5Handle type(H5Dget_type(d.get()), H5Tclose);
  if (!type.valid()) fail(dataset, "cannot read its type (damaged file?)");
  if (H5Tget_sign(type.get()) == H5T_SGN_2 && H5Tget_size(type.get()) <= 4) {
    // Signed and at most 32 bits (what gesmi writes): every value fits, and a stored
    // int32 is read as it is, without HDF5's conversion buffer (allocated and cleared
    // at each read of a converted type).
    std::vector<std::int32_t> values(count);
    if (count > 0 && H5Dread(d.get(), H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
      fail(dataset, "cannot read the values (truncated or damaged file)");
    return values;
  }
  // Wider or unsigned: read as 64 bits (HDF5 clips larger unsigned values, which the
  // range check then refuses).
  std::vector<std::int64_t> wide(count);
  if (count > 0 && H5Dread(d.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, wide.data()) < 0)
    fail(dataset, "cannot read the values (truncated or damaged file)");
  std::vector<std::int32_t> values(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (wide[i] < std::numeric_limits<std::int32_t>::min() || wide[i] > std::numeric_limits<std::int32_t>::max())
      fail(dataset, "value " + std::to_string(i) + " (" + std::to_string(wide[i]) + ") does not fit in 32 bits");
    values[i] = static_cast<std::int32_t>(wide[i]);
  }
  return values;
}

}  // namespace gesmi::io
