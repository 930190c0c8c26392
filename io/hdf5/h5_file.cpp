#include "io/hdf5/h5_file.h"

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <type_traits>

#include "io/format_error.h"
#include "io/input_file.h"

namespace gesmi::io {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "HDF5 handles are expected to be 64-bit");

// HDF5 prints its error stack on every failure unless told not to; gesmi reports
// failures itself, in one line. And HDF5's exit handler flushes every file still
// open: after a failed write (a full disk) that file cannot be flushed and HDF5
// 1.10 crashes in H5F__close_cb at exit, so gesmi closes its files itself and turns
// the handler off (before any other HDF5 call, as H5dont_atexit requires).
void silence_hdf5() {
  static const bool done = [] {
    H5dont_atexit();
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
  require_regular_file(path);
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

H5File H5File::create(const std::string& path, const std::string& shown_as) {
  silence_hdf5();
  const std::string name = shown_as.empty() ? path : shown_as;
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) throw FormatError(name + ": cannot create the file");
  return H5File(H5Handle(id, H5Fclose), name);
}

void H5File::close() {
  if (!file_.valid()) return;
  const bool flushed = H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) >= 0;
  const bool closed = H5Fclose(file_.release()) >= 0;
  if (!flushed || !closed) fail("", "cannot write the file (disk full?)");
}

H5Kind H5File::kind(const std::string& object) const {
  if (object.empty() || object == "/") return H5Kind::group;
  if (std::find(groups_.begin(), groups_.end(), object) != groups_.end()) return H5Kind::group;  // (an attribute's object)
  const H5Handle o = open_plain_object(object);
  if (!o.valid()) return H5Kind::missing;
  return H5Iget_type(o.get()) == H5I_GROUP ? H5Kind::group : H5Kind::dataset;
}

H5Handle H5File::open_plain_object(const std::string& object) const {
  // Walk the path one level at a time: H5Lexists fails when an intermediate level
  // is missing or is not a group, and only hard links name plain objects (a soft
  // or external link could point anywhere, another file included). A level found to
  // be a group is not walked again: a mission's reader opens about 30 objects under
  // a few groups, and each walk opened every level's object header.
  std::size_t end = 0;
  while (end != std::string::npos) {
    end = object.find('/', end + 1);
    const bool last = end == std::string::npos || end + 1 == object.size();
    const std::string level = object.substr(0, end);
    if (!last && std::find(groups_.begin(), groups_.end(), level) != groups_.end()) continue;
    const htri_t exists = H5Lexists(file_.get(), level.c_str(), H5P_DEFAULT);
    if (exists < 0) fail(level, "cannot be read (damaged file?)");
    if (exists == 0) return H5Handle();
    H5L_info_t link{};
    if (H5Lget_info(file_.get(), level.c_str(), &link, H5P_DEFAULT) < 0) fail(level, "cannot be read (damaged file?)");
    if (link.type != H5L_TYPE_HARD) fail(level, "is a soft or external link; gesmi reads only plain groups and datasets");
    H5Handle o(H5Oopen(file_.get(), level.c_str(), H5P_DEFAULT), H5Oclose);
    if (!o.valid()) fail(level, "cannot be opened (damaged file?)");
    const H5I_type_t type = H5Iget_type(o.get());
    if (type == H5I_GROUP && std::find(groups_.begin(), groups_.end(), level) == groups_.end()) groups_.push_back(level);
    if (!last) {
      if (type != H5I_GROUP) fail(level, "expected a group, found a dataset");
      continue;
    }
    if (type != H5I_GROUP && type != H5I_DATASET) fail(level, "expected a group or a dataset, found a named datatype");
    return o;
  }
  return H5Handle();
}

bool H5File::has_group(const std::string& group) const {
  const H5Kind k = kind(group);
  if (k == H5Kind::dataset) fail(group, "expected a group, found a dataset");
  return k == H5Kind::group;
}

H5Handle H5File::open_dataset(const std::string& dataset) const {
  // The object opened by the walk is the dataset's handle (H5Oopen returns a dataset
  // identifier for a dataset): not opened a second time.
  if (dataset.empty() || dataset == "/") fail(dataset, "expected a dataset, found a group");
  H5Handle d = open_plain_object(dataset);
  if (!d.valid()) fail(dataset, "missing dataset");
  if (H5Iget_type(d.get()) != H5I_DATASET) fail(dataset, "expected a dataset, found a group");
  return d;
}

std::vector<std::string> H5File::members(const std::string& group, std::size_t limit) const {
  const H5Handle g = open_plain_object(group);
  if (!g.valid()) fail(group, "missing group");
  if (H5Iget_type(g.get()) != H5I_GROUP) fail(group, "expected a group, found a dataset");
  H5G_info_t info{};
  if (H5Gget_info(g.get(), &info) < 0) fail(group, "cannot be read (damaged file?)");
  if (info.nlinks > limit)
    fail(group, "holds " + std::to_string(info.nlinks) + " members, more than the " + std::to_string(limit) + " gesmi reads");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t size = H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (size < 0 || static_cast<std::size_t>(size) > kMaxStringAttribute) fail(group, "a member's name cannot be read");
    std::string name(static_cast<std::size_t>(size) + 1, '\0');
    if (H5Lget_name_by_idx(g.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(), H5P_DEFAULT) < 0)
      fail(group, "a member's name cannot be read");
    name.resize(static_cast<std::size_t>(size));
    names.push_back(std::move(name));
  }
  return names;
}

H5Shape H5File::shape(const std::string& dataset) const { return shape_of(open_dataset(dataset).get(), dataset); }

H5Shape H5File::shape_of(std::int64_t d, const std::string& dataset) const {
  const H5Handle space(H5Dget_space(d), H5Sclose);
  if (!space.valid()) fail(dataset, "cannot read its shape");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 1 || rank > 2) fail(dataset, "expected 1 or 2 dimensions, found " + std::to_string(rank));
  hsize_t dims[2] = {0, 1};
  if (H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0) fail(dataset, "cannot read its shape");
  if (dims[0] > kMaxDatasetValues || dims[1] > kMaxDatasetValues || dims[0] * dims[1] > kMaxDatasetValues)
    fail(dataset, "declares " + std::to_string(dims[0]) + (rank == 2 ? " x " + std::to_string(dims[1]) : "") +
                      " values, more than gesmi reads from one dataset (" + std::to_string(kMaxDatasetValues) + ")");
  return H5Shape{static_cast<std::size_t>(dims[0]), rank == 2 ? static_cast<std::size_t>(dims[1]) : 1, rank};
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
void write_dataset(hid_t file_id, const std::string& dataset, std::span<const T> values, const hsize_t* dims, int rank,
                   hid_t memory_type, hid_t file_type, const std::string& path) {
  const H5Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  const H5Handle d(H5Dcreate2(file_id, dataset.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
  if (!d.valid()) throw FormatError(path + ": " + dataset + ": cannot create the dataset (disk full?)");
  if (!values.empty() && H5Dwrite(d.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw FormatError(path + ": " + dataset + ": cannot write (disk full?)");
}

}  // namespace

void H5File::write(const std::string& dataset, std::span<const double> values, std::size_t rows, std::size_t columns,
                   int rank) {
  ensure_parent_groups(dataset);
  if (values.size() != rows * columns) fail(dataset, "internal shape mismatch");
  const hsize_t dims[2] = {rows, columns};
  write_dataset(file_.get(), dataset, values, dims, rank, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, path_);
}

void H5File::write(const std::string& dataset, std::span<const std::int32_t> values, std::size_t rows,
                   std::size_t columns, int rank) {
  ensure_parent_groups(dataset);
  if (values.size() != rows * columns) fail(dataset, "internal shape mismatch");
  const hsize_t dims[2] = {rows, columns};
  write_dataset(file_.get(), dataset, values, dims, rank, H5T_NATIVE_INT32, H5T_STD_I32LE, path_);
}

void H5File::write_in_blocks(const std::string& dataset, std::size_t rows, std::size_t columns, int rank,
                             const RowFiller& fill) {
  if ((rank != 1 && rank != 2) || (rank == 1 && columns != 1)) fail(dataset, "internal shape mismatch");
  ensure_parent_groups(dataset);
  const hsize_t dims[2] = {rows, columns};
  const H5Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  const H5Handle d(H5Dcreate2(file_.get(), dataset.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                              H5P_DEFAULT),
                   H5Dclose);
  if (!d.valid()) fail(dataset, "cannot create the dataset (disk full?)");
  if (rows == 0 || columns == 0) return;
  const std::size_t block_rows = std::min(rows, kBlockRows);
  std::vector<double> block(block_rows * columns);
  for (std::size_t first = 0; first < rows; first += block_rows) {
    const std::size_t count = std::min(block_rows, rows - first);
    const std::span<double> values(block.data(), count * columns);
    fill(first, count, values);
    // The block's rows of the file's dataset, from a flat buffer of as many values.
    const hsize_t start[2] = {first, 0}, extent[2] = {count, columns};
    const hsize_t size = values.size();
    const H5Handle file_space(H5Dget_space(d.get()), H5Sclose), memory_space(H5Screate_simple(1, &size, nullptr), H5Sclose);
    if (!file_space.valid() || !memory_space.valid() ||
        H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, extent, nullptr) < 0 ||
        H5Dwrite(d.get(), H5T_NATIVE_DOUBLE, memory_space.get(), file_space.get(), H5P_DEFAULT, values.data()) < 0)
      fail(dataset, "cannot write (disk full?)");
  }
}

void H5File::write_3d(const std::string& dataset, std::span<const double> values, std::size_t d0, std::size_t d1,
                      std::size_t d2) {
  ensure_parent_groups(dataset);
  if (values.size() != d0 * d1 * d2) fail(dataset, "internal shape mismatch");
  const hsize_t dims[3] = {d0, d1, d2};
  write_dataset(file_.get(), dataset, values, dims, 3, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, path_);
}

}  // namespace gesmi::io
