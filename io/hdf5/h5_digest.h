#pragma once
// Datasets that carry their own SHA-256: the writer stores, as the dataset's
// attribute `sha256`, the digest of its name, shape and values; the reader
// recomputes it from the values read and refuses a dataset whose digest differs or
// is missing. It proves that a result file holds what gesmi wrote (no edit, no
// damage); it does not stop someone who recomputes the digests on purpose
// (docs/guarantees.md).

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/hdf5/h5_file.h"

namespace gesmi::io {

/// Writes a dataset (as H5File::write) and its `sha256` attribute; returns the digest.
std::string write_digested(H5File& file, const std::string& dataset, std::span<const double> values, std::size_t rows,
                           std::size_t columns = 1, int rank = 1);
std::string write_digested(H5File& file, const std::string& dataset, std::span<const std::int32_t> values,
                           std::size_t rows, std::size_t columns = 1, int rank = 1);

/// Checks values read from `dataset` (rows x columns) against its `sha256` attribute;
/// FormatError naming the file and dataset when it is missing or differs. Returns the digest.
std::string verify_digest(const H5File& file, const std::string& dataset, std::span<const double> values,
                          std::size_t rows, std::size_t columns);
std::string verify_digest(const H5File& file, const std::string& dataset, std::span<const std::int32_t> values,
                          std::size_t rows, std::size_t columns);

/// The digest of named values (attributes), in the given order.
std::string digest_of_fields(const std::vector<std::pair<std::string, std::string>>& fields);

}  // namespace gesmi::io
