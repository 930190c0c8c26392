#include "io/hdf5/h5_format.h"

#include <string>

#include "io/format_error.h"

namespace gesmi::io {

std::int64_t check_format(const H5File& f, std::string_view format, std::string_view description,
                          const H5FormatVersions& versions) {
  const std::string expected(format);
  const std::optional<std::string> found = f.string_attribute("/", "format");
  if (found != std::optional<std::string>(expected))
    throw FormatError(f.path() + ": not a " + std::string(description) + " file (attribute 'format' is not '" + expected + "')");
  const std::optional<std::int64_t> stored = f.int_attribute("/", "format_version");
  if (!stored && versions.when_absent == 0) throw FormatError(f.path() + ": /: missing attribute format_version");
  const std::int64_t version = stored.value_or(versions.when_absent);
  if (version > versions.current)
    throw FormatError(f.path() + ": /: format_version " + std::to_string(version) + " was written by a newer gesmi (this one reads " +
                      std::to_string(versions.oldest) + " to " + std::to_string(versions.current) + "); upgrade gesmi");
  if (version < versions.oldest)
    throw FormatError(f.path() + ": /: format_version " + std::to_string(version) + " is not one this gesmi reads (" +
                      std::to_string(versions.oldest) + " to " + std::to_string(versions.current) + ")");
  return version;
}

void write_format(H5File& f, std::string_view format, const H5FormatVersions& versions) {
  f.set_attribute("/", "format", std::string(format));
  f.set_attribute("/", "format_version", versions.current);
}

}  // namespace gesmi::io
