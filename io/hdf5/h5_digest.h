#pragma once
// Datasets that carry their own digest: the writer stores, as the dataset's attribute
// named after the digest's kind (`xxh128` today, `sha256` in results of formats 2 to
// 5), the digest of its name, shape and values; the reader recomputes it from the
// values read and refuses a dataset whose digest differs or is missing. It proves that
// a result file holds what gesmi wrote (no edit, no damage); it does not stop someone
// who recomputes the digests on purpose (docs/guarantees.md).

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/digest/digest.h"
#include "io/hdf5/h5_file.h"

namespace gesmi::io {

/// The digest of a dataset's name, shape and values, the values added in blocks (of a
/// writer or of a reader, H5File::RowBlocks): the same as of all of them at once.
class DatasetDigest {
 public:
  DatasetDigest(std::string dataset, std::size_t rows, std::size_t columns, DigestKind kind);
  template <class T>
  void add(std::span<const T> values) {
    digest_.add_bytes(values.data(), values.size_bytes());
  }
  /// Finishes the digest; hex digits.
  std::string hex() { return digest_.hex(); }
  /// Finishes the digest and stores it as the dataset's digest attribute in `file`.
  /// Returns it.
  std::string record(H5File& file);
  /// Finishes the digest and compares it with the dataset's digest attribute in `file`:
  /// FormatError naming the file and dataset when it is missing or differs. Returns it.
  std::string verify(const H5File& file);

 private:
  std::string dataset_;
  DigestKind kind_;
  Digest digest_;
};

/// Writes a dataset (as H5File::write) and its digest attribute; returns the digest.
std::string write_digested(H5File& file, const std::string& dataset, std::span<const double> values, std::size_t rows,
                           DigestKind kind, std::size_t columns = 1, int rank = 1);
std::string write_digested(H5File& file, const std::string& dataset, std::span<const std::int32_t> values,
                           std::size_t rows, DigestKind kind, std::size_t columns = 1, int rank = 1);

/// Writes a dataset of doubles in blocks (as H5File::write_in_blocks) and its digest
/// attribute, the same as write_digested of all its values; returns the digest.
std::string write_digested_in_blocks(H5File& file, const std::string& dataset, std::size_t rows, std::size_t columns,
                                     int rank, DigestKind kind, const H5File::RowFiller& fill);

/// Checks values read from `dataset` (rows x columns) against its digest attribute of
/// that kind; FormatError naming the file and dataset when it is missing or differs.
/// Returns the digest.
std::string verify_digest(const H5File& file, const std::string& dataset, std::span<const double> values,
                          std::size_t rows, std::size_t columns, DigestKind kind);
std::string verify_digest(const H5File& file, const std::string& dataset, std::span<const std::int32_t> values,
                          std::size_t rows, std::size_t columns, DigestKind kind);

/// "differ from the <kind> digest gesmi recorded ...; solve again ...": the end of the
/// message for values that do not match their digest.
std::string differ_from_recorded(DigestKind kind);

/// The digest of named values (attributes), in the given order.
std::string digest_of_fields(const std::vector<std::pair<std::string, std::string>>& fields, DigestKind kind);

}  // namespace gesmi::io
