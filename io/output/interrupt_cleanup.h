#pragma once
// Temporary files and folders to remove when the process is interrupted (SIGINT,
// SIGTERM, SIGHUP: a user's Ctrl-C, a batch scheduler's time limit, a closed
// terminal): the handler removes them and exits with 128 + the signal number (130,
// 143, 129). The table is fixed-size and the handler only calls unlink, rmdir and
// _exit, which are async-signal-safe.

#include <string>

namespace gesmi::io {

/// Tracks a temporary file (or an empty folder gesmi created) until untrack();
/// returns a slot, or -1 when the table is full (the path is then only removed on a
/// normal exit). Installs the handlers on first use.
int track_temporary(const std::string& path, bool folder = false);
void untrack_temporary(int slot);

}  // namespace gesmi::io
