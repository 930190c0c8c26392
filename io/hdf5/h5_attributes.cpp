// Attributes: written as scalars; read only when they are exactly one value of the
// expected kind, checked before anything is read into a one-value buffer.

#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "io/format_error.h"
#include "io/hdf5/h5_file.h"

namespace gesmi::io {
namespace {

H5Handle open_object(hid_t file, const std::string& object) {
  return H5Handle(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
}

const char* class_name(H5T_class_t c) {
  switch (c) {
    case H5T_INTEGER: return "an integer";
    case H5T_FLOAT: return "a floating-point number";
    case H5T_STRING: return "a string";
    case H5T_ENUM: return "an enumeration";
    default: return "a compound or opaque value";
  }
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

H5Handle H5File::open_attribute(const std::string& object, const std::string& name) const {
  if (kind(object) == H5Kind::missing) return H5Handle();
  const htri_t exists = H5Aexists_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT);
  if (exists < 0) fail(object, "cannot read attribute " + name + " (damaged file?)");
  if (exists == 0) return H5Handle();
  H5Handle a(H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid()) fail(object, "cannot open attribute " + name + " (damaged file?)");
  // Exactly one value: an attribute written as an array must not reach a
  // one-value buffer.
  const H5Handle space(H5Aget_space(a.get()), H5Sclose);
  const hssize_t points = space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
  if (points != 1)
    fail(object, "attribute " + name + " holds " + (points < 0 ? std::string("no readable") : std::to_string(points)) +
                     " values, expected one");
  return a;
}

std::optional<double> H5File::double_attribute(const std::string& object, const std::string& name) const {
  const H5Handle a = open_attribute(object, name);
  if (!a.valid()) return std::nullopt;
  const H5Handle type(H5Aget_type(a.get()), H5Tclose);
  const H5T_class_t cls = H5Tget_class(type.get());
  const std::size_t size = H5Tget_size(type.get());
  if (cls == H5T_FLOAT && size > 8) fail(object, "attribute " + name + " is wider than 64 bits, expected a double");
  if (cls == H5T_FLOAT) {
    double value = 0.0;
    if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail(object, "cannot read attribute " + name);
    return value;
  }
  if (cls == H5T_INTEGER) {
    const auto value = int_attribute(object, name);
    if (std::fabs(static_cast<double>(*value)) > 9007199254740992.0)
      fail(object, "attribute " + name + " is an integer too large to be read exactly");
    return static_cast<double>(*value);
  }
  fail(object, "attribute " + name + " is " + class_name(cls) + ", expected a number");
}

std::optional<std::int64_t> H5File::int_attribute(const std::string& object, const std::string& name) const {
  const H5Handle a = open_attribute(object, name);
  if (!a.valid()) return std::nullopt;
  const H5Handle type(H5Aget_type(a.get()), H5Tclose);
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_INTEGER) fail(object, "attribute " + name + " is " + class_name(cls) + ", expected an integer");
  if (H5Tget_sign(type.get()) == H5T_SGN_NONE && H5Tget_size(type.get()) >= 8) {
    std::uint64_t value = 0;
    if (H5Aread(a.get(), H5T_NATIVE_UINT64, &value) < 0) fail(object, "cannot read attribute " + name);
    if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
      fail(object, "attribute " + name + " is too large");
    return static_cast<std::int64_t>(value);
  }
  std::int64_t value = 0;
  if (H5Aread(a.get(), H5T_NATIVE_INT64, &value) < 0) fail(object, "cannot read attribute " + name);
  return value;
}

std::optional<std::string> H5File::string_attribute(const std::string& object, const std::string& name) const {
  const H5Handle a = open_attribute(object, name);
  if (!a.valid()) return std::nullopt;
  const H5Handle type(H5Aget_type(a.get()), H5Tclose);
  const H5T_class_t cls = H5Tget_class(type.get());
  if (cls != H5T_STRING) fail(object, "attribute " + name + " is " + class_name(cls) + ", expected a string");
  if (H5Tis_variable_str(type.get()) > 0) {
    // Variable-length strings (h5py's default): HDF5 allocates, we copy and free.
    const H5Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(memory.get(), H5T_VARIABLE);
    H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
    char* text = nullptr;
    if (H5Aread(a.get(), memory.get(), &text) < 0) fail(object, "cannot read attribute " + name);
    const std::size_t length = text ? std::strlen(text) : 0;
    std::string value = length <= kMaxStringAttribute ? std::string(text ? text : "", length) : std::string();
    if (text) H5free_memory(text);
    if (length > kMaxStringAttribute) fail(object, "attribute " + name + " is longer than " + std::to_string(kMaxStringAttribute) + " bytes");
    return value;
  }
  const std::size_t size = H5Tget_size(type.get());
  if (size == 0 || size > kMaxStringAttribute)
    fail(object, "attribute " + name + " declares a string of " + std::to_string(size) + " bytes");
  std::string value(size, '\0');
  if (H5Aread(a.get(), type.get(), value.data()) < 0) fail(object, "cannot read attribute " + name);
  value.resize(std::strlen(value.c_str()));  // null-padded or null-terminated
  return value;
}

}  // namespace gesmi::io
