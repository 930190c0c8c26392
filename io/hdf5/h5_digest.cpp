#include "io/hdf5/h5_digest.h"

#include "io/digest/digest.h"
#include "io/format_error.h"

namespace gesmi::io {
DatasetDigest::DatasetDigest(std::string dataset, std::size_t rows, std::size_t columns, DigestKind kind)
    : dataset_(std::move(dataset)), kind_(kind), digest_(kind) {
  digest_.add(std::string_view(dataset_));
  digest_.add_count(rows);
  digest_.add_count(columns);
  digest_.add_count(rows * columns);  // (Digest::add of the values: their count first)
}

std::string DatasetDigest::record(H5File& f) {
  const std::string hex = digest_.hex();
  f.set_attribute(dataset_, digest_name(kind_), hex);
  return hex;
}

std::string DatasetDigest::verify(const H5File& f) {
  const std::optional<std::string> stored = f.string_attribute(dataset_, digest_name(kind_));
  if (!stored)
    throw FormatError(f.path() + ": " + dataset_ + ": has no " + digest_name(kind_) + " attribute (not written by this gesmi)");
  const std::string hex = digest_.hex();
  if (*stored != hex) throw FormatError(f.path() + ": " + dataset_ + ": contents " + differ_from_recorded(kind_));
  return hex;
}

namespace {

template <class T>
std::string write_with_digest(H5File& f, const std::string& dataset, std::span<const T> values, std::size_t rows,
                              std::size_t columns, int rank, DigestKind kind) {
  f.write(dataset, values, rows, columns, rank);
  DatasetDigest h(dataset, rows, columns, kind);
  h.add(values);
  return h.record(f);
}

template <class T>
std::string verify(const H5File& f, const std::string& dataset, std::span<const T> values, std::size_t rows,
                   std::size_t columns, DigestKind kind) {
  DatasetDigest h(dataset, rows, columns, kind);
  h.add(values);
  return h.verify(f);
}

}  // namespace

std::string write_digested(H5File& f, const std::string& dataset, std::span<const double> values, std::size_t rows,
                           DigestKind kind, std::size_t columns, int rank) {
  return write_with_digest(f, dataset, values, rows, columns, rank, kind);
}
std::string write_digested(H5File& f, const std::string& dataset, std::span<const std::int32_t> values,
                           std::size_t rows, DigestKind kind, std::size_t columns, int rank) {
  return write_with_digest(f, dataset, values, rows, columns, rank, kind);
}
std::string write_digested_in_blocks(H5File& f, const std::string& dataset, std::size_t rows, std::size_t columns,
                                     int rank, DigestKind kind, const H5File::RowFiller& fill) {
  DatasetDigest h(dataset, rows, columns, kind);
  f.write_in_blocks(dataset, rows, columns, rank, [&](std::size_t first, std::size_t count, std::span<double> out) {
    fill(first, count, out);
    h.add(std::span<const double>(out));
  });
  return h.record(f);
}

std::string verify_digest(const H5File& f, const std::string& dataset, std::span<const double> values,
                          std::size_t rows, std::size_t columns, DigestKind kind) {
  return verify(f, dataset, values, rows, columns, kind);
}
std::string verify_digest(const H5File& f, const std::string& dataset, std::span<const std::int32_t> values,
                          std::size_t rows, std::size_t columns, DigestKind kind) {
  return verify(f, dataset, values, rows, columns, kind);
}

std::string differ_from_recorded(DigestKind kind) {
  return std::string("differ from the ") + digest_title(kind) +
         " digest gesmi recorded when it wrote the file (edited or damaged); solve again to get a result you can trust";
}

std::string digest_of_fields(const std::vector<std::pair<std::string, std::string>>& fields, DigestKind kind) {
  Digest h(kind);
  for (const auto& [name, value] : fields) {
    h.add(std::string_view(name));
    h.add(std::string_view(value));
  }
  return h.hex();
}

}  // namespace gesmi::io
