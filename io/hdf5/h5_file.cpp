#include "io/hdf5/h5_file.h"

#include <hdf5.h>

#include <cstdio>
#include <type_traits>

#include "io/format_error.h"

namespace gesmi::io {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "HDF5 handles are expected to be 64-bit");

// HDF5 prints its error stack on every failure unless told not to; gesmi reports
// failures itself, in one line.
void silence_hdf5() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

}  // namespace

H5Handle& H5Handle::operator=(H5Handle&& other) noexcept {
  if (this != &other) {
    reset();
    id_ = other.id_;
    closer_ = other.closer_;
    other.id_ = -1;
  }
  return *this;
}

void H5Handle::reset() {
  if (id_ >= 0 && closer_) closer_(id_);
  id_ = -1;
}

void H5File::fail(const std::string& object, const std::string& reason) const {
  throw FormatError(path_ + (object.empty() ? "" : ": " + object) + ": " + reason);
}

H5File H5File::open_read(const std::string& path) {
  silence_hdf5();
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw FormatError(path + ": cannot open the file (does it exist?)");
    std::fclose(f);
    throw FormatError(path + ": not an HDF5 file, or truncated");
  }
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) throw FormatError(path + ": cannot open as HDF5 (truncated or damaged file)");
  return H5File(H5Handle(id, H5Fclose), path);
}

H5File H5File::create(const std::string& path) {
  silence_hdf5();
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw FormatError(path + ": cannot create the file");
  return H5File(H5Handle(id, H5Fclose), path);
}

void H5File::close() {
  if (!file_.valid()) return;
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("", "cannot flush the file");
  file_.reset();
}

bool H5File::has(const std::string& object) const {
  // Check each level: H5Lexists fails when an intermediate group is missing.
  std::size_t pos = 0;
  while (true) {
    pos = object.find('/', pos + 1);
    const std::string prefix = object.substr(0, pos);
    if (prefix.empty() || prefix == "/") {
      if (pos == std::string::npos) return true;
      continue;
    }
    if (H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) return true;
  }
}

H5Handle H5File::open_dataset(const std::string& dataset) const {
  if (!has(dataset)) fail(dataset, "missing dataset");
  const hid_t id = H5Dopen2(file_.get(), dataset.c_str(), H5P_DEFAULT);
  if (id < 0) fail(dataset, "is not a dataset");
  return H5Handle(id, H5Dclose);
}

H5Shape H5File::shape(const std::string& dataset) const {
  const H5Handle d = open_dataset(dataset);
  const H5Handle space(H5Dget_space(d.get()), H5Sclose);
  if (!space.valid()) fail(dataset, "cannot read its shape");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > 2) fail(dataset, "expected 1 or 2 dimensions, found " + std::to_string(rank));
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  return H5Shape{static_cast<std::size_t>(dims[0]), rank == 2 ? static_cast<std::size_t>(dims[1]) : 1, rank};
}

void H5File::read_doubles_into(const std::string& dataset, std::span<double> out) const {
  const H5Shape s = shape(dataset);
  if (s.rows * s.columns != out.size())
    fail(dataset, "expected " + std::to_string(out.size()) + " values, found " + std::to_string(s.rows * s.columns));
  const H5Handle d = open_dataset(dataset);
  const H5Handle type(H5Dget_type(d.get()), H5Tclose);
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_FLOAT && cls != H5T_INTEGER) fail(dataset, "expected numbers");
  if (out.empty()) return;
  if (H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail(dataset, "cannot read the values (truncated or damaged file)");
}

void H5File::read_column_into(const std::string& dataset, std::size_t column, std::span<double> out) const {
  const H5Shape s = shape(dataset);
  if (s.rank != 2 || column >= s.columns) fail(dataset, "expected a 2-D dataset with column " + std::to_string(column));
  if (s.rows != out.size()) fail(dataset, "expected " + std::to_string(out.size()) + " rows, found " + std::to_string(s.rows));
  if (out.empty()) return;
  const H5Handle d = open_dataset(dataset);
  const H5Handle file_space(H5Dget_space(d.get()), H5Sclose);
  const hsize_t start[2] = {0, column}, count[2] = {s.rows, 1};
  const hsize_t memory_dims[1] = {s.rows};
  const H5Handle memory_space(H5Screate_simple(1, memory_dims, nullptr), H5Sclose);
  if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0 ||
      H5Dread(d.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT, out.data()) < 0)
    fail(dataset, "cannot read column " + std::to_string(column) + " (truncated or damaged file)");
}

std::vector<double> H5File::read_doubles(const std::string& dataset) const {
  const H5Shape s = shape(dataset);
  std::vector<double> values(s.rows * s.columns);
  read_doubles_into(dataset, values);
  return values;
}

std::vector<std::int32_t> H5File::read_ints(const std::string& dataset) const {
  const H5Shape s = shape(dataset);
  const H5Handle d = open_dataset(dataset);
  const H5Handle type(H5Dget_type(d.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_INTEGER) fail(dataset, "expected integers");
  std::vector<std::int32_t> values(s.rows * s.columns);
  if (!values.empty() && H5Dread(d.get(), H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(dataset, "cannot read the values (truncated or damaged file)");
  return values;
}

void H5File::ensure_parent_groups(const std::string& dataset) {
  std::size_t pos = 0;
  while ((pos = dataset.find('/', pos + 1)) != std::string::npos) {
    const std::string group = dataset.substr(0, pos);
    if (H5Lexists(file_.get(), group.c_str(), H5P_DEFAULT) > 0) continue;
    const H5Handle g(H5Gcreate2(file_.get(), group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
    if (!g.valid()) fail(group, "cannot create the group");
  }
}

namespace {

template <class T>
void write_dataset(H5File& file, hid_t file_id, const std::string& dataset, std::span<const T> values, std::size_t rows,
                   std::size_t columns, int rank, hid_t memory_type, hid_t file_type,
                   void (H5File::*ensure)(const std::string&), const std::string& path) {
  (file.*ensure)(dataset);
  if (values.size() != rows * columns) throw FormatError(path + ": " + dataset + ": internal shape mismatch");
  const hsize_t dims[2] = {rows, columns};
  const H5Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  const H5Handle d(H5Dcreate2(file_id, dataset.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
  if (!d.valid()) throw FormatError(path + ": " + dataset + ": cannot create the dataset");
  if (!values.empty() && H5Dwrite(d.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw FormatError(path + ": " + dataset + ": cannot write (disk full?)");
}

}  // namespace

void H5File::write(const std::string& dataset, std::span<const double> values, std::size_t rows, std::size_t columns,
                   int rank) {
  write_dataset(*this, file_.get(), dataset, values, rows, columns, rank, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE,
                &H5File::ensure_parent_groups, path_);
}

void H5File::write(const std::string& dataset, std::span<const std::int32_t> values, std::size_t rows,
                   std::size_t columns, int rank) {
  write_dataset(*this, file_.get(), dataset, values, rows, columns, rank, H5T_NATIVE_INT32, H5T_STD_I32LE,
                &H5File::ensure_parent_groups, path_);
}

void H5File::write_3d(const std::string& dataset, std::span<const double> values, std::size_t d0, std::size_t d1,
                      std::size_t d2) {
  ensure_parent_groups(dataset);
  if (values.size() != d0 * d1 * d2) fail(dataset, "internal shape mismatch");
  const hsize_t dims[3] = {d0, d1, d2};
  const H5Handle space(H5Screate_simple(3, dims, nullptr), H5Sclose);
  const H5Handle d(H5Dcreate2(file_.get(), dataset.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                              H5P_DEFAULT),
                   H5Dclose);
  if (!d.valid()) fail(dataset, "cannot create the dataset");
  if (!values.empty() && H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    fail(dataset, "cannot write (disk full?)");
}

namespace {

H5Handle open_object(hid_t file, const std::string& object) {
  return H5Handle(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
}

}  // namespace

void H5File::set_attribute(const std::string& object, const std::string& name, double value) {
  const H5Handle o = open_object(file_.get(), object);
  const H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const H5Handle a(H5Acreate2(o.get(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail(object, "cannot write attribute " + name);
}

void H5File::set_attribute(const std::string& object, const std::string& name, std::int64_t value) {
  const H5Handle o = open_object(file_.get(), object);
  const H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const H5Handle a(H5Acreate2(o.get(), name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_INT64, &value) < 0) fail(object, "cannot write attribute " + name);
}

void H5File::set_attribute(const std::string& object, const std::string& name, const std::string& value) {
  const H5Handle o = open_object(file_.get(), object);
  const H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), value.empty() ? 1 : value.size());
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  const H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const H5Handle a(H5Acreate2(o.get(), name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const std::string stored = value.empty() ? std::string(1, '\0') : value;
  if (!a.valid() || H5Awrite(a.get(), type.get(), stored.data()) < 0) fail(object, "cannot write attribute " + name);
}

namespace {

H5Handle open_attribute(hid_t file, const std::string& object, const std::string& name) {
  if (H5Aexists_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT) <= 0) return H5Handle();
  return H5Handle(H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
}

}  // namespace

std::optional<double> H5File::double_attribute(const std::string& object, const std::string& name) const {
  if (object != "/" && !has(object)) return std::nullopt;
  const H5Handle a = open_attribute(file_.get(), object, name);
  if (!a.valid()) return std::nullopt;
  double value = 0.0;
  if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail(object, "attribute " + name + " is not a number");
  return value;
}

std::optional<std::int64_t> H5File::int_attribute(const std::string& object, const std::string& name) const {
  if (object != "/" && !has(object)) return std::nullopt;
  const H5Handle a = open_attribute(file_.get(), object, name);
  if (!a.valid()) return std::nullopt;
  const H5Handle type(H5Aget_type(a.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_INTEGER) fail(object, "attribute " + name + " is not an integer");
  std::int64_t value = 0;
  if (H5Aread(a.get(), H5T_NATIVE_INT64, &value) < 0) fail(object, "cannot read attribute " + name);
  return value;
}

std::optional<std::string> H5File::string_attribute(const std::string& object, const std::string& name) const {
  if (object != "/" && !has(object)) return std::nullopt;
  const H5Handle a = open_attribute(file_.get(), object, name);
  if (!a.valid()) return std::nullopt;
  const H5Handle type(H5Aget_type(a.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0)
    fail(object, "attribute " + name + " is not a fixed-length string");
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(a.get(), type.get(), value.data()) < 0) fail(object, "cannot read attribute " + name);
  while (!value.empty() && value.back() == '\0') value.pop_back();
  return value;
}

}  // namespace gesmi::io
