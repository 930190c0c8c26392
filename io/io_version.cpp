// The version string written into every result file.
#include "io/io_version.h"

namespace gesmi::io {

std::string_view version() { return GESMI_VERSION; }

}  // namespace gesmi::io
