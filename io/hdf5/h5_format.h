#pragma once
// The identity of a gesmi HDF5 file: the root attributes `format` (what the file
// is) and `format_version` (which layout). A reader accepts the versions it knows
// and refuses, in one line, files of another kind or of a newer gesmi.

#include <cstdint>
#include <string_view>

#include "io/hdf5/h5_file.h"

namespace gesmi::io {

struct H5FormatVersions {
  std::int64_t current = 1;     // what this gesmi writes
  std::int64_t oldest = 1;      // the oldest it still reads
  std::int64_t when_absent = 0; // the version of files written before the attribute existed (0: refuse)
};

/// Checks `format` and `format_version`; returns the file's version. `description`
/// names the kind in messages ("gesmi mission").
std::int64_t check_format(const H5File& file, std::string_view format, std::string_view description,
                          const H5FormatVersions& versions);

/// Writes `format` and `format_version` (the current one).
void write_format(H5File& file, std::string_view format, const H5FormatVersions& versions);

}  // namespace gesmi::io
