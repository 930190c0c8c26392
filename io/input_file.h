#pragma once
// Every file gesmi reads is checked to be a regular file before it is opened: a pipe
// would block the reader until some writer came, and a device such as /dev/zero or
// /dev/urandom would never end.

#include <string>

namespace gesmi::io {

/// FormatError "PATH: cannot open the file (does it exist?)" when it cannot be found,
/// "PATH: is a pipe, not a file: ..." (or a folder, a device, a socket) when it is not a
/// regular file.
void require_regular_file(const std::string& path);

}  // namespace gesmi::io
